// A stand-in for `pirouette explore --view`, for working on the web page
// (src/pirouette/view/web/) without building or running pirouette, and for
// checking the tests themselves: it serves the page over HTTP and speaks the
// Foxglove WebSocket protocol on one port, as pirouette does, with a small
// fake run: a map that grows, a path, a plan, a camera frame and the status,
// then "complete"; with --out it writes OUT/map.pgm at the end as a run does.
//
//   node tests/js/mock_server.mjs [--port 8765] [--out DIR] [--duration S] [--linger S] [--control]
//     [--end STATUS] [--wrong-cells N]
//   then open http://127.0.0.1:8765/
import wsProtocol from "@foxglove/ws-protocol";
import { MessageWriter } from "@foxglove/rosmsg2-serialization";
import { parse } from "@foxglove/rosmsg";
import { WebSocketServer } from "ws";
import http from "node:http";
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { parseArgs } from "node:util";
import { schema } from "./ros2_schemas.mjs";

const { FoxgloveServer } = wsProtocol;

const { values: opt } = parseArgs({
  options: {
    port: { type: "string", default: "8765" },
    host: { type: "string", default: "127.0.0.1" },
    out: { type: "string" },
    duration: { type: "string", default: "8" },
    linger: { type: "string", default: "20" },
    control: { type: "boolean", default: false },
    // To check that the tests fail when they should: the run's end, and a map.pgm that differs.
    end: { type: "string", default: "complete" },
    "wrong-cells": { type: "string", default: "0" },
  },
});
const webDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "../../src/pirouette/view/web");

// A camera frame (a test pattern, 96x72): what the floor channel sends.
const JPEG = Buffer.from("/9j/4AAQSkZJRgABAgAAAQABAAD//gAQTGF2YzU5LjM3LjEwMAD/2wBDAAgQEBMQExYWFhYWFhoYGhsbGxoaGhobGxsdHR0iIiIdHR0bGx0dICAiIiUmJSMjIiMmJigoKDAwLi44ODpFRVP/xACmAAADAQEBAQEBAAAAAAAAAAAABgcIBQQDAgEBAAIDAQEAAAAAAAAAAAAAAAAHBgUIBAMQAAECBAUCAwYFBQEBAAAAAAECAAURBANDgsEhEjFBIhNRkQah0tEyorM1FWFCYoN0sSVyEQABAgMECAIHBwEJAQAAAAABAgAEEQMSBUJDgcHCg0ExUSHSE6EyFaIG0SKCYRSjUlORNHNEI2KzsrFj03T/wAARCABIAGADARIAAhIAAxIA/9oADAMBAAIRAxEAPwDP7GMYxs0OxMur6sCpjU3Lg6JHEqPt2HaZ/l1UVh06nY/hzELSOSRMqP8AHYcJlsC4s/d7bhftdNzwtepILq1ChFJBIlOSyVqEwooTxs8SBMTm3CkoVVPiUeKPXur1l9fV0YAAAASA2AHZ8UNBqr/UTZR14q6y+fVzsAASHYDg5PfnxJSuk+TTSK0QRMpnJNKY+k1JdySZGwJEp7kjtPKC1qqKUpSipSiVKUoklRPckk9ySeZc6UoqMyZv8OQUaFKHQEUkJQnoBz7SmeJPbuT3L6ntqHhqMLTFOjTTTSOCRKZkBMnmpUgJqMyeL7WsxHDzaMiOHm0dtC4tGtkLi0a2v79yN5sMv3I3mw1ljtWNfsexWPADHKmNZiOHm0ZEcPNo7aFxaNbIXFo1tf37kbzYZfuRvNhrBAOx3f8AXdoqLpKCkKUhQ5KSSCOHYju/JwanVqUVBdNaqahyUglKhMS7ESPLs/B+SjiAukW7myugV2UdD8CWgNuwscKhCKnZXBXBR1H/AJcLbPv74WVBJXEwhNSiCVKpSJXRT1BmStAM5n1kplOfcvTb0bDsTLq1z3frBfTctqI8xKU991pExykTMymOR6TI9WwYrDp1OlREGshIPrI7E9eh6z7d3kC4s/d7bZkVdCbsiq1SmR5USbaUSANMgkqQAAE2BaFiXIdiO0zSWP0Y+NjwA+pQ2E1NXT2VEhN29atqKZTAWsJMpgicjtsWMYx6BhMPTQw6mVsblSDeWoS6KCShM+IMkplsZyUVSMi6JEcPNo7aFxaNbIXFo1tf37kbzYZfuRvNhrLHasa/Y5qxylj3WxrMRw82jIjh5tHbQuLRrZC4tGtr+/cjebDL9yN5sNZY7VjX7HsVjwAxypjWYjh5tGRHDzaO2hcWjWyFxaNbX9+5G82GX7kbzYayx2zGv2Oav7rShBuI862q9aCyuwBc8xPlAquDkbYskoCVEyuEGXhJ2cpdh+GX1T6fk91OH+2ob9Fb+EeN+a1EFQytpagT4gqTcSJ+K2riFCXJIJl4kgmXIAlrcRw82j9oXFo1shcWjW+C/cjebDL9yN5sPbLS/d2+qohNIpQAItm3tOUrSjbT1J3ISJ/y7VjX7HlSE/qNF/tWPzUvzw+6ixW0t24eKLd+0tRkTJKVgkyEyZD03YxjHsGI4ebRkRw82jtoXFo1shcWjW1/fuRvNhl+5G82Gssdqxr9jmrHKWPdbGsxHDzaMiOHm0dtC4tGtkLi0a2v79yN5sMv3I3mw1ljtWNfsexWPADHKmNZiOHm0ZEcPNo7aFxaNbIXFo1tf37kbzYZfuRvNhrLHbMa/Y5CsXP3avHJHP8A9LkrgeJlZv8AOSec0zE+M1K4zE+Un3V3StKklNuagQq4LVtN5U9lcryUi6SsTCyVzWCeU5ltRx/z6n6vQPk3W2/7Lg/2vfqeJqERw82jIjh5tH1wuLRrZC4tGt0F+5G82GX7kbzYemfdb9Gpf8359x+j3btLswikSsSJSpfUHw3LilpO0+qVA+o7u1Y1+x5TRDqpf2255kfM6lSdnwGKop5q9Cvk4hWd0q7opPOn7yPE2dXdIp7t2ooqQXQReRb4XApfMkpknmV9CVgcjuZTkS/3SdnNKN6QdK1bqy5YKh69EtQ1nnS+Lti6/lWKVqzbn9aBKdmXNQ6Nq13+zaWnqPiH1rrdYvq7znfl1fA0Mh5rVdkYjnSl9tHibbieLlBpbyeqPin6txuvTov27jn/AJdXwPPCGxlX5dyOdeW7q+B55ieLltZQ1N7hwtzlyn4kjrL1UHQ0vUMNfV3/AFf43OWXV+//ACNDQ3Bsu9r5gInyvLrWrNuf0VBKdmXNA6NGFyP9orjg/jt/O7Wl6ZTecIvlVn9hfhamhuDYPtCF/c91fhazLY11tOj7lyyq+jQ6vu1MLhvJXKH/ADKXjej6LeCb0g1cqs/sVPC1DDv218TpFcJXenKfgX3l/a5PV92jIb4dvQWpw/OWbR+//senaLnd6ERnk+T9dm3PDzsy9aXR+VBuoiNKrpc/Cv5XMbTzsfh+9B/d/wA2j/6PS63Rpu2LXypT+2jxNqw3BsABV0f2tNAm6Y0ZPv0/G3QtupMTSXyVPQr5OKw3B8ioo11FywkngjlJa9lcEkpmrjMFUhMyG5k2ZTTtKDr0bVtEuWJJ69CXOoni/S9YerFeV5SbVm3PuBKdmXrEdHJA7amMQy2lKE3QlKQAlKbVwBIGwAARIADoHA1OCqIRz7PxieLV3syM/a99HibcDlbH0MaFY2aHYmXVkOxMurqorDp1MisOnU2BcWfu9tlxZ+723UKOIeUPLuzKf6VdSn+D6ge0dGqvthY3yxYqTKeB5kfcfu9IcccWv/4X/GrMTB2EVTM1aZNlNUynaSZSTUJ7GckqnMkGc3Q+90f1ufer/wCj/wBb8SoKAUkggiYIMwQeRB6Otgf6SG/saX+wOoSpK0hSSFJUAQQZgg8iCOxBdPdv9BCf/PR/00tTiOHm0ZEcPNo5XC4tGtkLi0a3Gr9yN5sMv3I3mw1ljtWNfsexWPADHKmNZiOHm0ZEcPNo7aFxaNbIXFo1tf37kbzYZfuRvNhrLHbMa/Y+PRw4zFy8NuoR8309vo3VtOFgTMLqjtzCPF8v5csbuv74rTZXDQCjamUriBKQHHySDMkmYt9pSmicwRnxs0OxMurIdiZdXVRWHTqZFYdOpsC4s/d7bLiz93ttmY6ljYDH/9k=", "base64");

// ---- The fake run: a 4 m x 3 m room of 5 cm cells, walls around, a box in
// the middle; the robot goes round it and sees 0.8 m about itself.
const RES = 0.05, W = 80, H = 60, ORIGIN = { x: -1, y: -0.5 };
const truth = new Int8Array(W * H); // row-major from the bottom row
for (let j = 0; j < H; ++j) {
  for (let i = 0; i < W; ++i) {
    const wall = i < 2 || j < 2 || i >= W - 2 || j >= H - 2;
    const box = i >= 34 && i < 46 && j >= 24 && j < 36;
    truth[j * W + i] = wall || box ? 100 : 0;
  }
}
const known = new Int8Array(W * H).fill(-1);
const route = [];
for (let k = 0; k <= 24; ++k) {
  const a = (k / 24) * 2 * Math.PI;
  route.push({ x: ORIGIN.x + 2 + 1.3 * Math.cos(a), y: ORIGIN.y + 1.5 + 0.9 * Math.sin(a) });
}
function see(p) {
  for (let j = 0; j < H; ++j) {
    for (let i = 0; i < W; ++i) {
      const x = ORIGIN.x + (i + 0.5) * RES, y = ORIGIN.y + (j + 0.5) * RES;
      if (Math.hypot(x - p.x, y - p.y) < 0.8) known[j * W + i] = truth[j * W + i];
    }
  }
}

// ---- The channels, as pirouette advertises them.
const server = new FoxgloveServer({
  name: "pirouette (mock)",
  capabilities: opt.control ? ["clientPublish"] : [],
  supportedEncodings: ["json"],
});
const channels = {};
for (const [topic, schemaName] of [
  ["/map", "nav_msgs/msg/OccupancyGrid"],
  ["/tf", "tf2_msgs/msg/TFMessage"],
  ["/pirouette/path", "nav_msgs/msg/Path"],
  ["/pirouette/plan", "nav_msgs/msg/Path"],
  ["/pirouette/floor", "sensor_msgs/msg/CompressedImage"],
  ["/pirouette/status", "std_msgs/msg/String"],
]) {
  const text = schema(schemaName);
  channels[topic] = {
    id: server.addChannel({ topic, encoding: "cdr", schemaName, schema: text, schemaEncoding: "ros2msg" }),
    writer: new MessageWriter(parse(text, { ros2: true })),
  };
}

const t0 = Date.now();
const stamp = () => { const ms = Date.now(); return { sec: Math.floor(ms / 1000), nanosec: (ms % 1000) * 1e6 }; };
const header = () => ({ stamp: stamp(), frame_id: "map" });
const quat = (yaw) => ({ x: 0, y: 0, z: Math.sin(yaw / 2), w: Math.cos(yaw / 2) });
const poseStamped = (p, yaw) => ({ header: header(), pose: { position: { x: p.x, y: p.y, z: 0 }, orientation: quat(yaw) } });
function publish(topic, message) {
  const ch = channels[topic];
  server.sendMessage(ch.id, BigInt(Date.now()) * 1000000n, ch.writer.writeMessage(message));
}

let step = 0, paused = false, ended = null;
const steps = route.length - 1;
function publishAll(status, reason) {
  const path = route.slice(0, step + 1).map((p, k) => {
    const next = route[Math.min(k + 1, steps)], prev = route[Math.max(k - 1, 0)];
    return poseStamped(p, Math.atan2(next.y - prev.y, next.x - prev.x));
  });
  publish("/map", {
    header: header(),
    info: { map_load_time: stamp(), resolution: RES, width: W, height: H,
      origin: { position: { x: ORIGIN.x, y: ORIGIN.y, z: 0 }, orientation: quat(0) } },
    data: known,
  });
  publish("/tf", { transforms: [{ header: header(), child_frame_id: "odom",
    transform: { translation: { x: 0, y: 0, z: 0 }, rotation: quat(0) } }] });
  publish("/pirouette/path", { header: header(), poses: path });
  const plan = status === "running" ? route.slice(step, step + 3).map((p) => poseStamped(p, 0)) : [];
  publish("/pirouette/plan", { header: header(), poses: plan });
  publish("/pirouette/floor", { header: { stamp: stamp(), frame_id: "camera" }, format: "jpeg", data: JPEG });
  const knownCells = known.reduce((n, v) => n + (v >= 0 ? 1 : 0), 0);
  publish("/pirouette/status", { data: JSON.stringify({ status, stops: step + 1,
    known_area_m2: Math.round(knownCells * RES * RES * 1e4) / 1e4, reason, elapsed_s: (Date.now() - t0) / 1000 }) });
}

// map.pgm as pirouette writes it: P5, the top row first, 254 free, 0 occupied, 205 unknown.
function writePgm(dir) {
  fs.mkdirSync(dir, { recursive: true });
  const pixels = Buffer.alloc(W * H);
  for (let r = 0; r < H; ++r) {
    for (let i = 0; i < W; ++i) {
      const v = known[(H - 1 - r) * W + i];
      pixels[r * W + i] = v < 0 ? 205 : v === 100 ? 0 : 254;
    }
  }
  for (let n = Number(opt["wrong-cells"]), i = 0; n > 0 && i < pixels.length; ++i) {
    if (pixels[i] !== 205) { pixels[i] = 254 - pixels[i]; --n; }
  }
  const file = path.join(dir, "map.pgm");
  fs.writeFileSync(file + ".tmp", Buffer.concat([Buffer.from(`P5\n# pirouette mock\n${W} ${H}\n255\n`), pixels]));
  fs.renameSync(file + ".tmp", file);
}

const tickMs = (Number(opt.duration) * 1000) / steps;
see(route[0]);
const timer = setInterval(() => {
  if (ended) { publishAll(ended, ended === "complete" ? "" : "the mock was told to end so"); return; } // latched: late subscribers get the last of each
  if (!paused && step < steps) { ++step; see(route[step]); }
  if (step >= steps) {
    ended = opt.end;
    publishAll(ended, ended === "complete" ? "" : "the mock was told to end so");
    if (opt.out) writePgm(opt.out);
    console.error(`mock: complete; serving ${opt.linger} s more`);
    setTimeout(() => process.exit(0), Number(opt.linger) * 1000);
    return;
  }
  publishAll("running", "");
}, tickMs);

server.on("message", ({ channelId, data, client }) => {
  let command;
  try { command = JSON.parse(new TextDecoder().decode(data)).command; } catch { command = undefined; }
  const known = { pause: () => { paused = true; }, resume: () => { paused = false; }, stop: () => { step = steps; }, home: () => {} };
  if (!known[command]) {
    server.sendStatus({ level: 2, message: `unknown control request on channel ${channelId}` }, client.connection);
    return;
  }
  known[command]();
  server.sendStatus({ level: 0, message: `${command}: done` }, client.connection);
});
server.on("error", (e) => console.error(`mock: ${e.message}`));

// ---- One port: the page's files over HTTP, the protocol over WebSocket.
const TYPES = { ".html": "text/html; charset=utf-8", ".js": "text/javascript; charset=utf-8", ".css": "text/css; charset=utf-8" };
const httpServer = http.createServer((req, res) => {
  const name = req.url === "/" ? "index.html" : decodeURIComponent(req.url.split("?")[0].slice(1));
  if (!/^[\w.-]+$/.test(name) || !fs.existsSync(path.join(webDir, name))) {
    res.writeHead(404, { "content-type": "text/plain" }).end("not found\n");
    return;
  }
  res.writeHead(200, { "content-type": TYPES[path.extname(name)] ?? "application/octet-stream" });
  res.end(fs.readFileSync(path.join(webDir, name)));
});
const wss = new WebSocketServer({ server: httpServer, handleProtocols: (protocols) => server.handleProtocols(protocols) });
wss.on("connection", (conn, req) => {
  server.handleConnection(conn, `${req.socket.remoteAddress}:${req.socket.remotePort}`);
  conn.on("close", () => {
    if (ended && wss.clients.size === 0) { console.error("mock: every client has gone"); clearInterval(timer); process.exit(0); }
  });
});
httpServer.listen(Number(opt.port), opt.host, () => console.error(`mock: http://${opt.host}:${opt.port}/`));
