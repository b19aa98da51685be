// The live view's protocol against a client nobody here wrote: FoxgloveClient
// (@foxglove/ws-protocol) connects to a run, subscribes to /map and
// /pirouette/status, decodes their CDR with @foxglove/rosmsg2-serialization
// from the ros2msg schemas the server advertised, waits for the run's end and
// checks the status says complete and the last map equals OUT_DIR/map.pgm.
//
//   node foxglove_client_test.mjs URL OUT_DIR     (URL: ws://HOST:PORT/ or http://HOST:PORT/)
// Exit: 0 pass, 1 fail, 77 skip (packages not installed).
import { fail, need, sleep, timeoutS, waitForPgm, greyOf, compareWithPgm } from "./common.mjs";

const [url, outDir] = process.argv.slice(2);
if (!url || !outDir) fail("usage: node foxglove_client_test.mjs URL OUT_DIR");
const wsUrl = url.replace(/^http/, "ws");

const { FoxgloveClient } = (await need("@foxglove/ws-protocol")).default;
const { MessageReader } = await need("@foxglove/rosmsg2-serialization");
const { parse } = await need("@foxglove/rosmsg");
const WebSocket = (await need("ws")).default;

const deadline = Date.now() + timeoutS * 1000;
const timer = setTimeout(() => fail(`no final status within ${timeoutS} s (LIVE_TEST_TIMEOUT_S)`), timeoutS * 1000);

const subscribed = new Map(); // subscription id -> {topic, reader}
let serverInfo = null, lastMap = null, maps = 0, finalStatus = null;
let resolveEnd;
const ended = new Promise((resolve) => { resolveEnd = resolve; });

// Connects, retrying while the server is not up yet (within 60 s). The
// handlers go on at once: the server's first messages may come with the
// handshake's answer, in the same event as "open".
async function connect() {
  const until = Date.now() + 60_000;
  let lastError = "";
  while (Date.now() < until) {
    const client = new FoxgloveClient({ ws: new WebSocket(wsUrl, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
    let open = false;
    listen(client, () => open);
    const opened = await new Promise((resolve) => {
      client.on("open", () => { open = true; resolve(true); });
      client.on("error", (e) => { lastError = e?.message ?? String(e); resolve(false); });
      client.on("close", () => resolve(false));
    });
    if (opened) return client;
    client.close();
    await sleep(250);
  }
  fail(`could not connect to ${wsUrl} within 60 s: ${lastError}`);
}

function listen(client, isOpen) {
  client.on("serverInfo", (info) => { serverInfo = info; });
  client.on("status", (s) => console.error(`server status (level ${s.level}): ${s.message}`));
  client.on("close", (e) => {
    if (isOpen() && !finalStatus) fail(`the server closed the connection before the run's end (code ${e?.code} ${e?.reason ?? ""})`);
  });
  client.on("advertise", (channels) => {
    for (const ch of channels) {
      if (ch.topic !== "/map" && ch.topic !== "/pirouette/status") continue;
      if (ch.encoding !== "cdr") fail(`${ch.topic}: encoding ${ch.encoding}, not cdr`);
      if (ch.schemaEncoding !== "ros2msg") fail(`${ch.topic}: schemaEncoding ${ch.schemaEncoding}, not ros2msg`);
      const want = ch.topic === "/map" ? "nav_msgs/msg/OccupancyGrid" : "std_msgs/msg/String";
      if (ch.schemaName !== want) fail(`${ch.topic}: schemaName ${ch.schemaName}, not ${want}`);
      let reader;
      try {
        reader = new MessageReader(parse(ch.schema, { ros2: true }));
      } catch (e) {
        fail(`${ch.topic}: its schema does not parse as ros2msg: ${e.message}\n${ch.schema}`);
      }
      subscribed.set(client.subscribe(ch.id), { topic: ch.topic, reader });
    }
  });
  client.on("message", ({ subscriptionId, data }) => {
    const sub = subscribed.get(subscriptionId);
    if (!sub) return;
    const bytes = new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
    let m;
    try {
      m = sub.reader.readMessage(bytes);
    } catch (e) {
      fail(`${sub.topic}: a message (${bytes.length} bytes) does not decode: ${e.message}`);
    }
    if (sub.topic === "/map") {
      const { width, height } = m.info;
      if (m.data.length !== width * height) fail(`/map: ${m.data.length} cells for ${width}x${height}`);
      lastMap = m;
      ++maps;
    } else {
      let s;
      try { s = JSON.parse(m.data); } catch { fail(`/pirouette/status: not JSON: ${m.data}`); }
      if (typeof s.status !== "string") fail(`/pirouette/status: no status in ${m.data}`);
      if (s.status !== "running" && !finalStatus) { finalStatus = s; resolveEnd(); }
    }
  });
}

const client = await connect();
console.error(`connected to ${wsUrl}`);
await ended;
clearTimeout(timer);
console.error(`final status: ${JSON.stringify(finalStatus)}`);
if (!serverInfo) fail("no serverInfo");
if (finalStatus.status !== "complete") fail(`the run ended "${finalStatus.status}", not complete: ${finalStatus.reason}`);
await sleep(1000); // a map sent right after the status
if (!lastMap) fail("no /map message");
const pgm = await waitForPgm(outDir, Math.max(5, (deadline - Date.now()) / 1000));
const { width, height } = lastMap.info;
const greys = new Uint8Array(width * height);
for (let row = 0; row < height; ++row) {
  for (let col = 0; col < width; ++col) greys[row * width + col] = greyOf(lastMap.data[(height - 1 - row) * width + col]);
}
const result = compareWithPgm(width, height, greys, pgm, `the last of ${maps} /map messages`);
client.close();
if (!result.ok) fail(result.message);
console.error(`PASS: ${result.message}; status complete (${finalStatus.stops} stops, ${finalStatus.known_area_m2} m²)`);
process.exit(0);
