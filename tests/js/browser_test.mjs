// The live view's page in a real browser: Debian's headless Chromium
// (playwright-core drives it, CHROMIUM overrides /usr/bin/chromium) loads the
// page during a run, waits for its #status to tell the run's end, reads the
// map the page drew (#map-cells: one pixel a cell, map_server's greys) and
// checks it equals OUT_DIR/map.pgm, then writes a screenshot of the page.
//
//   node browser_test.mjs URL OUT_DIR SCREENSHOT.png
// Exit: 0 pass, 1 fail, 77 skip (playwright-core or Chromium absent).
import fs from "node:fs";
import { fail, skip, need, sleep, timeoutS, waitForPgm, compareWithPgm } from "./common.mjs";
import { schema } from "./ros2_schemas.mjs";

const [url, outDir, screenshot] = process.argv.slice(2);
if (!url || !outDir || !screenshot) fail("usage: node browser_test.mjs URL OUT_DIR SCREENSHOT.png");
const executablePath = process.env.CHROMIUM || "/usr/bin/chromium";
if (!fs.existsSync(executablePath)) skip(`no Chromium at ${executablePath}: run scripts/setup (Debian's chromium)`);
const { chromium } = await need("playwright-core");
const { MessageWriter } = await need("@foxglove/rosmsg2-serialization");
const { parse } = await need("@foxglove/rosmsg");

// Messages of every type the page reads, written by rosmsg2-serialization:
// the page's own CDR reader must read them back (odd string lengths, so that
// the alignment matters).
const stamp = { sec: 1700000000, nanosec: 123456789 };
const pose = (x, y, z, w) => ({ position: { x, y, z: 0.5 }, orientation: { x: 0, y: 0, z, w } });
const SAMPLES = {
  "nav_msgs/msg/OccupancyGrid": { header: { stamp, frame_id: "m" }, info: { map_load_time: stamp, resolution: 0.25,
    width: 3, height: 2, origin: pose(-1.5, 2.25, 0, 1) }, data: new Int8Array([0, 100, -1, -1, 0, 100]) },
  "nav_msgs/msg/Path": { header: { stamp, frame_id: "map" }, poses: [
    { header: { stamp, frame_id: "ab" }, pose: pose(1, 2, 0.6, 0.8) },
    { header: { stamp, frame_id: "abcde" }, pose: pose(3, 4, -0.6, 0.8) }] },
  "sensor_msgs/msg/CompressedImage": { header: { stamp, frame_id: "camera" }, format: "jpeg", data: new Uint8Array([255, 216, 1, 2, 3]) },
  "std_msgs/msg/String": { data: "{\"status\":\"running\"}" },
  "tf2_msgs/msg/TFMessage": { transforms: [{ header: { stamp, frame_id: "map" }, child_frame_id: "odom",
    transform: { translation: { x: 0.1, y: -0.2, z: 0 }, rotation: { x: 0, y: 0, z: 0.6, w: 0.8 } } }] },
};
const plain = (v) => JSON.parse(JSON.stringify(v, (k, x) => (ArrayBuffer.isView(x) ? Array.from(x) : x)));

const browser = await chromium.launch({ executablePath, args: ["--no-sandbox"], handleSIGINT: false, handleSIGTERM: false });
for (const signal of ["SIGINT", "SIGTERM"]) {
  process.on(signal, async () => {
    console.error(`stopped (${signal})`);
    await browser.close().catch(() => {});
    process.exit(1);
  });
}
const errors = [];
let code = 1;
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  page.on("pageerror", (e) => errors.push(`uncaught: ${e.message}`));
  page.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") errors.push(`console ${m.type()}: ${m.text()}`); });

  // The page, once the server is up (within 60 s).
  const until = Date.now() + 60_000;
  for (;;) {
    try {
      const response = await page.goto(url, { timeout: 10_000 });
      if (!response.ok()) fail(`${url}: HTTP ${response.status()}`);
      break;
    } catch (e) {
      if (Date.now() > until) fail(`could not load ${url} within 60 s: ${e.message.split("\n")[0]}`);
      await sleep(250);
    }
  }
  console.error(`loaded ${url}`);

  for (const [type, message] of Object.entries(SAMPLES)) {
    const bytes = new MessageWriter(parse(schema(type), { ros2: true })).writeMessage(message);
    const got = await page.evaluate(([t, b]) => {
      try {
        const m = decode(t, new Uint8Array(b)); // app.js's reader
        return JSON.parse(JSON.stringify(m, (k, x) => (ArrayBuffer.isView(x) ? Array.from(x) : x)));
      } catch (e) {
        return { error: e.message };
      }
    }, [type, Array.from(bytes)]);
    if (JSON.stringify(got) !== JSON.stringify(plain(message))) {
      fail(`the page reads a ${type} that rosmsg2-serialization wrote as ${JSON.stringify(got)}, ` +
        `not ${JSON.stringify(plain(message))}`);
    }
  }
  console.error(`the page's CDR reader reads back ${Object.keys(SAMPLES).length} types that rosmsg2-serialization wrote`);

  try {
    await page.waitForFunction(() => {
      const s = document.getElementById("status")?.textContent;
      return s && s !== "running";
    }, null, { timeout: timeoutS * 1000, polling: 200 });
  } catch {
    fail(`#status did not leave "running" within ${timeoutS} s (LIVE_TEST_TIMEOUT_S); ` +
      `it reads "${await page.textContent("#status")}", the connection "${await page.textContent("#connection")}"`);
  }
  const status = await page.textContent("#status");
  console.error(`#status: ${status} ${await page.textContent("#reason")}`);
  if (status !== "complete") fail(`the page says the run ended "${status}", not complete: ${await page.textContent("#reason")}`);
  await sleep(1000); // a map sent right after the status, and its drawing

  // The drawn map: the red channel of #map-cells, one byte a cell, the top row first.
  const drawn = await page.evaluate(() => {
    const canvas = document.getElementById("map-cells");
    const { width, height } = canvas;
    if (!width || !height) return { width, height, greys: "" };
    const px = canvas.getContext("2d").getImageData(0, 0, width, height).data;
    const grey = new Uint8Array(width * height);
    for (let i = 0; i < grey.length; ++i) grey[i] = px[4 * i];
    let s = "";
    for (let i = 0; i < grey.length; i += 0x8000) s += String.fromCharCode(...grey.subarray(i, i + 0x8000));
    return { width, height, greys: btoa(s) };
  });
  const greys = Buffer.from(drawn.greys, "base64");
  await page.screenshot({ path: screenshot });
  console.error(`wrote ${screenshot}`);

  const pgm = await waitForPgm(outDir);
  const result = compareWithPgm(drawn.width, drawn.height, greys, pgm, "the page's map (#map-cells)");
  if (!result.ok) fail(result.message);
  if (errors.length) fail(`the page reported errors: ${errors.join("; ")}`);
  console.error(`PASS: ${result.message}; #status complete`);
  code = 0;
} finally {
  await browser.close();
}
process.exit(code);
