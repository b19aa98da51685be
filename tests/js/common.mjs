// What the live-view tests share: exit codes, map.pgm, the comparison of a
// map's cells with it.
import fs from "node:fs";
import path from "node:path";

export const PASS = 0, FAIL = 1, SKIP = 77;

export function fail(message) {
  console.error(`FAIL: ${message}`);
  process.exit(FAIL);
}

export function skip(message) {
  console.error(`SKIP: ${message}`);
  process.exit(SKIP);
}

// Imports a package, or skips the test when it is not installed (scripts/setup installs them).
export async function need(name) {
  try {
    return await import(name);
  } catch (e) {
    if (e.code === "ERR_MODULE_NOT_FOUND" || e.code === "MODULE_NOT_FOUND") {
      skip(`${name} is not installed: run scripts/setup (npm ci --prefix tests/js)`);
    }
    throw e;
  }
}

export const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// Seconds the tests wait for a run to end (LIVE_TEST_TIMEOUT_S, default 300).
export const timeoutS = Number(process.env.LIVE_TEST_TIMEOUT_S || 300);

// Waits until DIR/map.pgm exists and parses (the run writes it at its end,
// atomically), for up to `seconds`.
export async function waitForPgm(dir, seconds = 20) {
  const file = path.join(dir, "map.pgm");
  const until = Date.now() + seconds * 1000;
  for (;;) {
    if (fs.existsSync(file)) return readPgm(file);
    if (Date.now() > until) fail(`${file} did not appear within ${seconds} s of the run's end`);
    await sleep(200);
  }
}

// A binary PGM (P5, 8 bits, comments allowed): {width, height, pixels}, the top row first.
export function readPgm(file) {
  const bytes = fs.readFileSync(file);
  let pos = 0;
  const token = () => {
    for (;;) {
      while (pos < bytes.length && /\s/.test(String.fromCharCode(bytes[pos]))) ++pos;
      if (bytes[pos] !== 0x23) break; // '#': a comment to the end of the line
      while (pos < bytes.length && bytes[pos] !== 0x0a) ++pos;
    }
    const start = pos;
    while (pos < bytes.length && !/\s/.test(String.fromCharCode(bytes[pos]))) ++pos;
    return bytes.subarray(start, pos).toString("latin1");
  };
  if (token() !== "P5") fail(`${file}: not a binary PGM (P5)`);
  const width = Number(token()), height = Number(token()), max = Number(token());
  if (!(width >= 0 && height >= 0 && max > 0 && max < 256)) fail(`${file}: bad PGM header`);
  ++pos; // the one whitespace byte after maxval
  const pixels = bytes.subarray(pos, pos + width * height);
  if (pixels.length !== width * height) fail(`${file}: ${pixels.length} pixels for ${width}x${height}`);
  return { width, height, pixels };
}

// OccupancyGrid's value as map_server's grey: 0 free -> 254, 100 occupied -> 0, -1 unknown -> 205.
export function greyOf(v) {
  return v < 0 ? 205 : v > 65 ? 0 : v <= 19 ? 254 : 205;
}

// Compares greys (top row first) with map.pgm: the counts of known cells of
// map.pgm that differ, and of cells known in `greys` but unknown in map.pgm.
export function compareWithPgm(width, height, greys, pgm, what) {
  if (width !== pgm.width || height !== pgm.height) {
    return { ok: false, message: `${what} is ${width}x${height} cells, map.pgm ${pgm.width}x${pgm.height}` };
  }
  let differ = 0, extra = 0, known = 0;
  const first = [];
  for (let i = 0; i < width * height; ++i) {
    const want = pgm.pixels[i], got = greys[i];
    if (want !== 205) {
      ++known;
      if (got !== want) {
        ++differ;
        if (first.length < 5) first.push(`(col ${i % width}, row ${Math.floor(i / width)}): ${got}, map.pgm ${want}`);
      }
    } else if (got !== 205) {
      ++extra;
    }
  }
  const ok = differ === 0 && extra === 0;
  const message = ok
    ? `${what} equals map.pgm: ${width}x${height} cells, ${known} known`
    : `${what} differs from map.pgm (${width}x${height}): ${differ} of its ${known} known cells differ` +
      `${first.length ? ` (first: ${first.join("; ")})` : ""}, ${extra} known that map.pgm leaves unknown`;
  return { ok, message };
}
