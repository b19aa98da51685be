// pirouette's live view: the page reads the run's Foxglove WebSocket stream
// (foxglove.websocket.v1, the same channels and CDR bytes that Foxglove and
// ROS 2 get) and draws it. No library, no build step: plain ES2020.
"use strict";

const SUBPROTOCOL = "foxglove.websocket.v1";
const FREE = 254, OCCUPIED = 0, UNKNOWN = 205; // map_server's greys

// ---- A little-endian CDR reader (what ROS 2 writes: 4-byte encapsulation
// header 00 01 00 00, then each primitive aligned to its size, counted from
// the end of the header).
class CdrReader {
  constructor(bytes) {
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    this.bytes = bytes;
    if (bytes.byteLength < 4) throw new Error("CDR: shorter than its header");
    const kind = this.view.getUint16(0, false);
    if (kind !== 0x0001) throw new Error(`CDR: encapsulation ${kind} is not little-endian CDR`);
    this.pos = 4;
  }
  align(n) {
    const rel = this.pos - 4;
    if (rel % n) this.pos += n - (rel % n);
  }
  need(n) {
    if (this.pos + n > this.bytes.byteLength) throw new Error("CDR: message ends early");
  }
  u32() { this.align(4); this.need(4); const v = this.view.getUint32(this.pos, true); this.pos += 4; return v; }
  i32() { this.align(4); this.need(4); const v = this.view.getInt32(this.pos, true); this.pos += 4; return v; }
  f32() { this.align(4); this.need(4); const v = this.view.getFloat32(this.pos, true); this.pos += 4; return v; }
  f64() { this.align(8); this.need(8); const v = this.view.getFloat64(this.pos, true); this.pos += 8; return v; }
  string() {
    const n = this.u32(); // length including the NUL
    this.need(n);
    const s = new TextDecoder().decode(this.bytes.subarray(this.pos, this.pos + Math.max(0, n - 1)));
    this.pos += n;
    return s;
  }
  bytesOf(n) { this.need(n); const b = this.bytes.subarray(this.pos, this.pos + n); this.pos += n; return b; }
  int8s() { const n = this.u32(); const b = this.bytesOf(n); return new Int8Array(b.buffer, b.byteOffset, n); }
  uint8s() { return this.bytesOf(this.u32()); }
  time() { return { sec: this.i32(), nanosec: this.u32() }; }
  header() { return { stamp: this.time(), frame_id: this.string() }; }
  vector3() { return { x: this.f64(), y: this.f64(), z: this.f64() }; }
  quaternion() { return { x: this.f64(), y: this.f64(), z: this.f64(), w: this.f64() }; }
  pose() { return { position: this.vector3(), orientation: this.quaternion() }; }
}

// The messages the page reads, by schema name.
const DECODERS = {
  "nav_msgs/msg/OccupancyGrid": (r) => {
    const header = r.header();
    const info = {
      map_load_time: r.time(), resolution: r.f32(), width: r.u32(), height: r.u32(), origin: r.pose(),
    };
    return { header, info, data: r.int8s() };
  },
  "nav_msgs/msg/Path": (r) => {
    const header = r.header();
    const poses = [];
    for (let n = r.u32(); n > 0; --n) poses.push({ header: r.header(), pose: r.pose() });
    return { header, poses };
  },
  "sensor_msgs/msg/CompressedImage": (r) => ({ header: r.header(), format: r.string(), data: r.uint8s() }),
  "std_msgs/msg/String": (r) => ({ data: r.string() }),
  "tf2_msgs/msg/TFMessage": (r) => {
    const transforms = [];
    for (let n = r.u32(); n > 0; --n) {
      transforms.push({
        header: r.header(), child_frame_id: r.string(),
        transform: { translation: r.vector3(), rotation: r.quaternion() },
      });
    }
    return { transforms };
  },
};

function decode(schemaName, bytes) {
  const decoder = DECODERS[schemaName];
  return decoder ? decoder(new CdrReader(bytes)) : undefined;
}

function yawOf(q) {
  return Math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
}

// ---- What the page knows of the run.
const state = { map: null, path: [], stops: [], plan: [], status: null };
const $ = (id) => document.getElementById(id);
const cells = $("map-cells");
const view = $("map");

// The map into #map-cells, one pixel a cell, the top row first.
function setMap(grid) {
  const { width, height } = grid.info;
  if (grid.data.length !== width * height) throw new Error(`map: ${grid.data.length} cells for ${width}x${height}`);
  state.map = grid;
  cells.width = width;
  cells.height = height;
  if (width === 0 || height === 0) return;
  const ctx = cells.getContext("2d");
  const image = ctx.createImageData(width, height);
  const px = image.data;
  for (let row = 0; row < height; ++row) {
    const from = (height - 1 - row) * width; // data starts at the bottom row
    for (let col = 0; col < width; ++col) {
      const v = grid.data[from + col];
      const grey = v < 0 ? UNKNOWN : v > 65 ? OCCUPIED : v <= 19 ? FREE : UNKNOWN;
      const o = 4 * (row * width + col);
      px[o] = px[o + 1] = px[o + 2] = grey;
      px[o + 3] = 255;
    }
  }
  ctx.putImageData(image, 0, 0);
}

// Draws the map scaled to fit, then the path, the stops, the plan and the robot.
function draw() {
  const box = view.getBoundingClientRect();
  const dpr = window.devicePixelRatio || 1;
  const w = Math.max(1, Math.round(box.width * dpr)), h = Math.max(1, Math.round(box.height * dpr));
  if (view.width !== w || view.height !== h) { view.width = w; view.height = h; }
  const ctx = view.getContext("2d");
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = "#444";
  ctx.fillRect(0, 0, w, h);
  const map = state.map;
  if (!map || map.info.width === 0 || map.info.height === 0) return;
  const { width, height, resolution, origin } = map.info;
  const scale = Math.min(w / width, h / height);
  const left = (w - width * scale) / 2, top = (h - height * scale) / 2;
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(cells, left, top, width * scale, height * scale);
  // World metres (map frame) to canvas pixels.
  const toPx = (p) => [
    left + ((p.x - origin.position.x) / resolution) * scale,
    top + (height - (p.y - origin.position.y) / resolution) * scale,
  ];
  const unit = Math.max(2, Math.min(w, h) / 120);
  const line = (poses, colour, dash) => {
    if (poses.length < 2) return;
    ctx.beginPath();
    poses.forEach((p, i) => { const [x, y] = toPx(p.pose.position); i ? ctx.lineTo(x, y) : ctx.moveTo(x, y); });
    ctx.strokeStyle = colour;
    ctx.lineWidth = unit / 2;
    ctx.setLineDash(dash);
    ctx.stroke();
    ctx.setLineDash([]);
  };
  line(state.path, "#1f6fd1", []);
  ctx.fillStyle = "#1f6fd1";
  for (const p of state.path) {
    const [x, y] = toPx(p.pose.position);
    ctx.beginPath();
    ctx.arc(x, y, unit * 0.6, 0, 2 * Math.PI);
    ctx.fill();
  }
  ctx.strokeStyle = "#1f6fd1"; // the stops: where the robot pirouetted, a ring each
  ctx.lineWidth = unit / 2;
  for (const p of state.stops) {
    const [x, y] = toPx(p.pose.position);
    ctx.beginPath();
    ctx.arc(x, y, unit * 1.6, 0, 2 * Math.PI);
    ctx.stroke();
  }
  line(state.plan, "#e07b00", [unit * 1.5, unit]);
  if (state.plan.length) {
    const [x, y] = toPx(state.plan[state.plan.length - 1].pose.position);
    ctx.strokeStyle = "#e07b00";
    ctx.lineWidth = unit / 2;
    ctx.beginPath();
    ctx.arc(x, y, unit * 1.2, 0, 2 * Math.PI);
    ctx.stroke();
  }
  if (state.path.length) { // the robot: where the path ends, facing its heading
    const last = state.path[state.path.length - 1].pose;
    const [x, y] = toPx(last.position);
    const yaw = yawOf(last.orientation);
    const r = unit * 3.5;
    ctx.save();
    ctx.translate(x, y);
    ctx.rotate(-yaw); // the canvas's y points down
    ctx.beginPath();
    ctx.moveTo(r, 0);
    ctx.lineTo(-r * 0.7, r * 0.6);
    ctx.lineTo(-r * 0.7, -r * 0.6);
    ctx.closePath();
    ctx.fillStyle = "#d12f2f";
    ctx.fill();
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = unit / 3;
    ctx.stroke();
    ctx.restore();
  }
}

let drawQueued = false;
function redraw() {
  if (drawQueued) return;
  drawQueued = true;
  requestAnimationFrame(() => { drawQueued = false; draw(); });
}
window.addEventListener("resize", redraw);

function setStatus(json) {
  let s;
  try { s = JSON.parse(json); } catch { s = { status: "?", reason: `status not JSON: ${json}` }; }
  state.status = s;
  $("status").textContent = s.status ?? "";
  $("status").dataset.status = s.status ?? "";
  $("stops").textContent = s.stops ?? "–";
  $("area").textContent = typeof s.known_area_m2 === "number" ? s.known_area_m2.toFixed(2) : "–";
  $("elapsed").textContent = typeof s.elapsed_s === "number" ? s.elapsed_s.toFixed(1) : "–";
  $("reason").textContent = s.reason || "";
}

let floorUrl = null;
function setFloor(image) {
  const type = image.format.includes("png") ? "image/png" : "image/jpeg";
  const url = URL.createObjectURL(new Blob([image.data], { type }));
  if (floorUrl) URL.revokeObjectURL(floorUrl); // the image shown keeps its pixels
  floorUrl = url;
  $("floor").src = url;
}

function note(text, bad) {
  $("connection").textContent = text;
  $("connection").className = bad ? "bad" : "";
}

// ---- The connection.
let ws = null;
let controlChannel = null; // the client channel id the controls go out on
const channels = new Map(); // channel id -> channel
const subscriptions = new Map(); // subscription id -> channel
let nextSubscription = 1;

function handleJson(msg) {
  switch (msg.op) {
    case "serverInfo": {
      const canControl = (msg.capabilities || []).includes("clientPublish");
      $("controls").hidden = !canControl;
      if (canControl) {
        controlChannel = 1;
        ws.send(JSON.stringify({ op: "advertise", channels: [
          { id: controlChannel, topic: "/pirouette/control", encoding: "json", schemaName: "pirouette/Control" }] }));
      }
      break;
    }
    case "advertise": {
      const subs = [];
      for (const ch of msg.channels) {
        channels.set(ch.id, ch);
        if (ch.encoding !== "cdr" || !DECODERS[ch.schemaName]) continue;
        const id = nextSubscription++;
        subscriptions.set(id, ch);
        subs.push({ id, channelId: ch.id });
      }
      if (subs.length) ws.send(JSON.stringify({ op: "subscribe", subscriptions: subs }));
      break;
    }
    case "unadvertise":
      for (const id of msg.channelIds) channels.delete(id);
      break;
    case "status":
      $("server-message").textContent = msg.message;
      $("server-message").className = msg.level >= 2 ? "bad" : "";
      break;
  }
}

function handleBinary(buffer) {
  const bytes = new Uint8Array(buffer);
  if (bytes.length < 13 || bytes[0] !== 0x01) return; // only message data
  const dv = new DataView(buffer);
  const ch = subscriptions.get(dv.getUint32(1, true));
  if (!ch) return;
  const topic = "/" + ch.topic.replace(/^\//, ""); // a namespace may come before the names
  try {
    const m = decode(ch.schemaName, bytes.subarray(13));
    if (topic.endsWith("/map")) setMap(m);
    else if (topic.endsWith("/pirouette/path")) state.path = m.poses;
    else if (topic.endsWith("/pirouette/plan")) state.plan = m.poses;
    else if (topic.endsWith("/pirouette/stops")) state.stops = m.poses;
    else if (topic.endsWith("/pirouette/status")) setStatus(m.data);
    else if (topic.endsWith("/pirouette/floor")) setFloor(m);
    else return;
  } catch (e) {
    console.warn(`${ch.topic}: ${e.message}`);
    return;
  }
  redraw();
}

function connect() {
  const url = `${location.protocol === "https:" ? "wss" : "ws"}://${location.host}/`;
  note(`connecting to ${url}…`);
  ws = new WebSocket(url, [SUBPROTOCOL]);
  ws.binaryType = "arraybuffer";
  ws.onopen = () => note("connected");
  ws.onmessage = (e) => {
    if (typeof e.data === "string") {
      try { handleJson(JSON.parse(e.data)); } catch (err) { console.warn(`bad message: ${err.message}`); }
    } else {
      handleBinary(e.data);
    }
  };
  ws.onclose = () => {
    channels.clear();
    subscriptions.clear();
    $("controls").hidden = true;
    // paused and (sim-serve's) serving are not an end: connect again
    const ended = state.status && !["running", "paused", "serving"].includes(state.status.status);
    note(ended ? "the run has ended; disconnected" : "disconnected; retrying…", !ended);
    if (!ended) setTimeout(connect, 1000);
  };
}

function sendControl(command) {
  if (!ws || ws.readyState !== WebSocket.OPEN || controlChannel === null) return;
  const json = new TextEncoder().encode(JSON.stringify({ command }));
  const frame = new Uint8Array(5 + json.length);
  frame[0] = 0x01; // client message data
  new DataView(frame.buffer).setUint32(1, controlChannel, true);
  frame.set(json, 5);
  ws.send(frame);
}

for (const button of document.querySelectorAll("#controls button")) {
  button.addEventListener("click", () => sendControl(button.dataset.command));
}

connect();
redraw();
