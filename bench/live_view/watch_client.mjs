// A live-view client for measuring the cost of watching (bench/live_view/measure.sh):
// subscribes to every channel and, when the run ends, prints one JSON line
// with the bytes received, the messages by topic, the stops seen and the
// delay from each map's publication (its message time) to its arrival.
// Usage: node watch_client.mjs ws://127.0.0.1:PORT/ [stall]
// With `stall` it subscribes, then never reads again (a client on a dead
// link) and leaves after 20 s: the run must not notice.
import WebSocket from "../../tests/js/node_modules/ws/index.js";

const url = process.argv[2];
const stall = process.argv[3] === "stall";
const stats = { bytes: 0, messages: {}, map_delays_ms: [], stops: 0, status: "" };
let topics = new Map();

function connect() {
  const ws = new WebSocket(url, ["foxglove.websocket.v1"]);
  ws.on("error", () => setTimeout(connect, 50));
  ws.on("message", (data, binary) => {
    stats.bytes += data.length;
    if (!binary) {
      const m = JSON.parse(data.toString());
      if (m.op === "advertise") {
        for (const c of m.channels) topics.set(c.id, c.topic);
        ws.send(JSON.stringify({ op: "subscribe",
          subscriptions: m.channels.map((c) => ({ id: c.id, channelId: c.id })) }));
        if (stall) {
          ws._socket.pause();
          setTimeout(() => process.exit(0), 20000);
        }
      }
      return;
    }
    const topic = topics.get(data.readUInt32LE(1));
    stats.messages[topic] = (stats.messages[topic] ?? 0) + 1;
    if (topic === "/map") {
      const sentNs = data.readBigUInt64LE(5);
      const nowNs = BigInt(Date.now()) * 1000000n;
      stats.map_delays_ms.push(Number(nowNs - sentNs) / 1e6);
    }
    if (topic === "/pirouette/status") {
      // std_msgs/String in CDR: header 4, length 4, then the text and its NUL.
      const length = data.readUInt32LE(13 + 4);
      const status = JSON.parse(data.subarray(13 + 8, 13 + 8 + length - 1).toString());
      stats.stops = status.stops;
      if (status.status !== "running" && status.status !== "paused") {
        stats.status = status.status;
        const d = stats.map_delays_ms.sort((a, b) => a - b);
        stats.map_delay_median_ms = d[Math.floor(d.length / 2)];
        stats.map_delay_max_ms = d[d.length - 1];
        delete stats.map_delays_ms;
        stats.bytes_per_stop = Math.round(stats.bytes / Math.max(1, stats.stops));
        console.log(JSON.stringify(stats));
        ws.close();
        process.exit(0);
      }
    }
  });
}
connect();
