#!/usr/bin/env python3
"""Writes the seed corpora fuzz/corpus/<target>/ from the shipped files
(worlds/) and the unit tests' cases. Run from the repository's root; the
seeds are checked in, so this is only needed to remake them."""
import os
import re
import struct
import zlib

SEP = b"\n--8<--\n"  # testing::kFuzzPartSeparator
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def out(target, name, data):
    d = os.path.join(ROOT, "fuzz", "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def read(path):
    with open(os.path.join(ROOT, path), "rb") as f:
        return f.read()


def png(width, height, channels, pixel):
    colour_type = {1: 0, 3: 2, 4: 6}[channels]
    raw = b"".join(b"\0" + bytes(pixel) * width for _ in range(height))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(
            ">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8,
                                                             colour_type, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def small_camera(model="plumb_bob", coefficients="[-0.2, 0.05, 0, 0, 0]"):
    n = coefficients.count(",") + 1
    return ("image_width: 8\nimage_height: 6\ncamera_name: tiny\ncamera_matrix:\n  rows: 3\n"
            "  cols: 3\n  data: [7, 0, 3.5, 0, 7, 2.5, 0, 0, 1]\n"
            f"distortion_model: {model}\ndistortion_coefficients:\n  rows: 1\n  cols: {n}\n"
            f"  data: {coefficients}\nmount:\n  height: 0.11\n  tilt: 30\n  forward: 0.03\n"
            "vignetting:\n  k: [0.35, 0.30, 0.40]\n")


MODELS = [("plumb_bob", "[-0.2, 0.05, 0.001, -0.002, 0.01]"),
          ("rational_polynomial", "[0.2, -0.05, 0.001, -0.0008, 0.001, 0.55, 0.05, 0.002]"),
          ("equidistant", "[0.04, -0.012, 0.003, -0.0005]")]

# camera_file: the shipped cameras and each distortion model.
for name in ("yujin.yaml", "webcam640.yaml"):
    out("camera_file", name, read("worlds/" + name))
for model, coefficients in MODELS:
    out("camera_file", model + ".yaml", small_camera(model, coefficients))
out("camera_file", "mount_only.yaml", "mount:\n  height: 0.3\n  tilt: 28\n  forward: 0.1\n")

# map_file: yaml, image, colour layer.
MAP_YAML = ("image: map.pgm\nresolution: 0.05\norigin: [-0.5, -0.25, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
pgm = b"P5\n4 3\n255\n" + bytes([254, 254, 0, 205, 254, 0, 0, 205, 254, 254, 254, 0])
out("map_file", "trinary_p5", MAP_YAML.encode() + SEP + pgm + SEP + png(4, 3, 4, (0, 0, 200, 255)))
out("map_file", "scale_p2", (MAP_YAML + "mode: scale\n").encode() + SEP +
    b"P2\n3 2\n65535\n0 30000 65535\n65535 100 0\n")
out("map_file", "raw_png", (MAP_YAML.replace("map.pgm", "map.png") + "mode: raw\n").encode() +
    SEP + png(3, 2, 3, (40, 40, 40)))
out("map_file", "negate", MAP_YAML.replace("negate: 0", "negate: 1").encode() + SEP + pgm)

# world_file: the shipped worlds with their cameras; a grid world.
for name in sorted(os.listdir(os.path.join(ROOT, "worlds"))):
    text = read("worlds/" + name)
    m = re.search(rb"camera: (\S+\.yaml)", text)
    if not m:
        continue
    world = text.replace(m.group(0), b"camera: camera.yaml")
    out("world_file", name, world + SEP + read("worlds/" + m.group(1).decode()))
out("world_file", "grid.yaml",
    ("format: pirouette-world/1\nname: grid\nfloor:\n  size: [0.2, 0.15]\n  colour: [140, 95, 55]\n"
     "walls:\n  height: 0.1\n  thickness: 0.02\n  colour: [240, 235, 225]\nobstacles:\n"
     "  - grid: {map: map.yaml, height: 0.25, colour: [200, 200, 200]}\n"
     "robot:\n  start: [0.025, 0.125, 0]\n  radius: 0.01\n  camera: camera.yaml\n").encode() +
    SEP + small_camera().encode() + SEP + MAP_YAML.replace("[-0.5, -0.25, 0.0]", "[0, 0, 0]").encode()
    + SEP + pgm)

# run_log: log.yaml, camera.yaml, frames.csv, the first frame.
LOG_YAML = ("format: pirouette-log/1\nrobot:\n  radius: 0.04\nmap:\n  cell: 0.01\n"
            "  max_range: 0.4067\n  method: default\n  localize: scan\n"
            "  odometry_model: [0.05, 0.02]\nsource:\n  world: worlds/soccer_field.yaml\n"
            "  seed: 7\n")
CSV = ("index,time_s,x,y,heading_deg,motion,blocked_leg_m\n0,0,0.2,0.2,45,,\n"
       "1,0.3833,0.2,0.2,75,turn 30,\n2,0.9,0.25,0.23,75,straight 0.05;turn 0,0.1\n"
       "3,1.2,0.26,0.23,75,straight 0.01 contact,\n")
for model, coefficients in MODELS:
    out("run_log", model, LOG_YAML.encode() + SEP + small_camera(model, coefficients).encode() +
        SEP + CSV.encode() + SEP + png(8, 6, 3, (120, 90, 60)))
out("run_log", "no_log_yaml", SEP + small_camera().encode() + SEP +
    b"index,time_s,x,y,heading_deg,motion,blocked_leg_m\n0,0,0,0,0,,\n" + SEP + png(8, 6, 1, (9,)))

# place_table_file.
out("place_table_file", "two_places.yaml",
    "format: pirouette-places/1\nworld: worlds/two_rooms.yaml\nmax_range_m: 0.5\nplaces:\n"
    "  - {x: 0.3, y: 0.3, heading_deg: 0, ranges: [0.1, 0.2, 0.3, 0.4], colours: 'rgby', "
    "kinds: 'hcbh'}\n"
    "  - {x: 1.2, y: 0.4, heading_deg: 90, ranges: [0.5, 0.5, 0.1, 0.2], colours: '....', "
    "kinds: 'cchb'}\n")
out("place_table_file", "empty.yaml",
    "format: pirouette-places/1\nworld: x\nmax_range_m: 1\nplaces: []\n")

# graph_file.
out("graph_file", "three_nodes.g2o",
    "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 0.5 0.01 0.1\nVERTEX_SE2 2 0.9 0.4 1.2\n"
    "EDGE_SE2 0 1 0.5 0 0.1 400 10 1 300 2 50\nEDGE_SE2 1 2 0.4 0.4 1.1 400 0 0 400 0 100\n"
    "EDGE_SE2 0 1 0.49 0.02 0.1 100 0 0 100 0 10\n# loop closures\n"
    "EDGE_SE2 2 0 -0.1 1 -1.2 50 0 0 50 0 5\n")
out("graph_file", "one_node.g2o", "# a comment\n\nVERTEX_SE2 0 1.5 -2 3.14159\n")

# line_protocol: both directions.
out("line_protocol", "requests",
    "HELLO pirouette-robot/1\nTURN 30\nTURN -29.999999999999997\nMOVE 0.05\nMOVE -0.1\r\n"
    "CAPTURE\nODOM\n")
out("line_protocol", "replies",
    "OK pirouette-robot/1\nOK 30 0.2 0.2 75 0\nOK 0.049 0.25 0.23 75 1\n"
    "FRAME 320 240 0.2 0.2 45 0.3833\nOK 0.2 0.2 45\nERR unknown command 'FLY'\n")

# tcp_connection: the same lines as a stream, and a frame with its bytes.
out("tcp_connection", "requests", open(os.path.join(ROOT, "fuzz/corpus/line_protocol/requests"), "rb").read())
out("tcp_connection", "replies", open(os.path.join(ROOT, "fuzz/corpus/line_protocol/replies"), "rb").read())
out("tcp_connection", "frame", "OK pirouette-robot/1\nFRAME 2 2 0.2 0.2 45 0.5\n0123456789abOK 0.2 0.2 45\n")

# ros2_cdr: a type byte (0 Odometry, 1 Image, 2 CameraInfo, 3 Twist), then the CDR.


class Cdr:
    def __init__(self):
        self.b = bytearray()

    def align(self, n):
        while len(self.b) % n:
            self.b.append(0)

    def u8(self, v):
        self.b += struct.pack("<B", v)

    def u32(self, v):
        self.align(4)
        self.b += struct.pack("<I", v)

    def i32(self, v):
        self.align(4)
        self.b += struct.pack("<i", v)

    def f64(self, *vs):
        for v in vs:
            self.align(8)
            self.b += struct.pack("<d", v)

    def string(self, s):
        self.u32(len(s) + 1)
        self.b += s.encode() + b"\0"

    def header(self, sec, frame):
        self.i32(sec)
        self.u32(250000000)
        self.string(frame)

    def bytes(self, kind):
        return bytes([kind]) + b"\x00\x01\x00\x00" + bytes(self.b)


odom = Cdr()
odom.header(1700000000, "odom")
odom.string("base_link")
odom.f64(0.2, 0.3, 0, 0, 0, 0.3826834, 0.9238795)
odom.f64(*([0.0] * 36))
odom.f64(0.05, 0, 0, 0, 0, 0.1)
odom.f64(*([0.0] * 36))
out("ros2_cdr", "odometry", odom.bytes(0))

for encoding, w, h in (("rgb8", 4, 3), ("bgr8", 2, 2), ("mono8", 2, 1)):
    image = Cdr()
    image.header(1700000001, "camera")
    image.u32(h)
    image.u32(w)
    image.string(encoding)
    image.u8(0)
    channels = 1 if encoding == "mono8" else 3
    image.u32(w * channels)
    image.u32(w * h * channels)
    image.b += bytes(range(w * h * channels))
    out("ros2_cdr", "image_" + encoding, image.bytes(1))

for model, coefficients in MODELS:
    d = [float(x) for x in coefficients.strip("[]").split(",")]
    info = Cdr()
    info.header(1700000002, "camera")
    info.u32(240)
    info.u32(320)
    info.string(model)
    info.u32(len(d))
    info.f64(*d)
    info.f64(277.1, 0, 159.5, 0, 277.1, 119.5, 0, 0, 1)
    info.f64(1, 0, 0, 0, 1, 0, 0, 0, 1)
    info.f64(277.1, 0, 159.5, 0, 0, 277.1, 119.5, 0, 0, 0, 1, 0)
    info.u32(0)
    info.u32(0)
    for _ in range(4):
        info.u32(0)
    info.u8(0)
    out("ros2_cdr", "camera_info_" + model, info.bytes(2))

twist = Cdr()
twist.f64(0.1, 0, 0, 0, 0, -0.5)
out("ros2_cdr", "twist", twist.bytes(3))

# foxglove_protocol: a byte (even: text, odd: binary), then the frame.
for i, text in enumerate([
        '{"op":"subscribe","subscriptions":[{"id":0,"channelId":2},{"id":7,"channelId":1}]}',
        '{"op":"unsubscribe","subscriptionIds":[0,7]}',
        '{"op":"advertise","channels":[{"id":1,"topic":"/pirouette/control","encoding":"json",'
        '"schemaName":"pirouette/Control"}]}',
        '{"op":"unadvertise","channelIds":[1]}',
        '{"op":"getParameters","parameterNames":[]}']):
    out("foxglove_protocol", f"text_{i}", b"\0" + text.encode())
out("foxglove_protocol", "binary_message",
    b"\x01\x01" + struct.pack("<I", 1) + b'{"command":"pause"}')
