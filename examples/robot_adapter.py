#!/usr/bin/env python3
"""Lets pirouette drive your robot: a TCP server speaking pirouette's robot
line protocol (docs/robot-protocol.md), for you to adapt.

Run it on the robot (or on a computer that talks to it), then, from the
computer that runs pirouette:

    pirouette explore --robot tcp://ROBOT_HOST:5555 --camera my_camera.yaml --radius 0.15

Try it without hardware first: `--fake` simulates odometry and answers every
CAPTURE with a plain grey frame, so the protocol can be watched end to end:

    python3 examples/robot_adapter.py --fake --port 5555

To adapt it, fill in the four functions in the class `MyRobot` below (they
are marked "FILL IN"): turn on the spot, drive straight, grab a frame, and
read the odometry. Everything else (sockets, the protocol) is done here, with
Python's standard library only; numpy and OpenCV (cv2) are needed only by
MyRobot.grab_frame.

Units: metres, degrees counter-clockwise, seconds. The odometry is the pose
the robot believes it has (wheel encoders): x, y in metres and heading in
degrees in a fixed frame; where that frame starts does not matter.
"""

import argparse
import math
import socket
import sys
import time

PROTOCOL = "pirouette-robot/1"


class FakeRobot:
    """A robot without hardware: odometry follows the commands exactly and
    the camera sees a grey picture."""

    def __init__(self, width=320, height=240):
        self.width, self.height = width, height
        self.x, self.y, self.heading_deg = 0.0, 0.0, 0.0

    def turn(self, degrees):
        self.heading_deg = (self.heading_deg + degrees + 180.0) % 360.0 - 180.0
        return degrees, False

    def move(self, metres):
        h = math.radians(self.heading_deg)
        self.x += metres * math.cos(h)
        self.y += metres * math.sin(h)
        return metres, False

    def grab_frame(self):
        return self.width, self.height, bytes([128]) * (self.width * self.height * 3)

    def odometry(self):
        return self.x, self.y, self.heading_deg


class MyRobot:
    """Your robot. Each method blocks until the robot has done it."""

    def __init__(self, camera_index=0):
        import cv2  # only the real robot needs OpenCV

        self.cv2 = cv2
        self.camera = cv2.VideoCapture(camera_index)
        if not self.camera.isOpened():
            raise RuntimeError(f"cannot open camera {camera_index}")
        # FILL IN: connect to the robot's motors and encoders.

    def turn(self, degrees):
        """FILL IN: turn on the spot by `degrees`, counter-clockwise positive,
        and wait until the turn is over. Return (achieved_degrees, False):
        the angle turned by odometry."""
        raise NotImplementedError("turn")

    def move(self, metres):
        """FILL IN: drive straight `metres` (negative: backwards), stopping at
        once if the bumper touches something. Return (achieved_metres,
        stopped_at_contact), achieved by odometry, in the sign of the
        command."""
        raise NotImplementedError("move")

    def grab_frame(self):
        """Return (width, height, bytes): the newest camera frame as RGB8,
        width*height*3 bytes, row by row from the top. The camera must be the
        one described by the camera file given to `pirouette explore`, at
        the same resolution."""
        for _ in range(4):  # drop frames buffered while the robot moved
            self.camera.grab()
        ok, bgr = self.camera.read()
        if not ok:
            raise RuntimeError("the camera gave no frame")
        rgb = self.cv2.cvtColor(bgr, self.cv2.COLOR_BGR2RGB)
        height, width = rgb.shape[:2]
        return width, height, rgb.tobytes()

    def odometry(self):
        """FILL IN: return (x_metres, y_metres, heading_degrees), the pose by
        the wheel encoders, in a frame that stays fixed during the run."""
        raise NotImplementedError("odometry")


def number(value):
    """A number as the protocol writes it: repr() reads back exactly."""
    return repr(float(value))


class Session:
    """One client's conversation: reads request lines, answers each."""

    def __init__(self, robot, connection):
        self.robot = robot
        self.connection = connection
        self.reader = connection.makefile("rb")
        self.start = time.monotonic()

    def pose_words(self):
        x, y, heading_deg = self.robot.odometry()
        return f"{number(x)} {number(y)} {number(heading_deg)}"

    def send(self, data):
        self.connection.sendall(data if isinstance(data, bytes) else data.encode("ascii"))

    def answer(self, words):
        command, args = words[0], words[1:]
        if command == "HELLO" and len(args) == 1:
            if args[0] != PROTOCOL:
                return f"ERR this robot speaks {PROTOCOL}, not {args[0]}\n"
            return f"OK {PROTOCOL}\n"
        if command in ("TURN", "MOVE") and len(args) == 1:
            amount = float(args[0])
            if not math.isfinite(amount):
                return f"ERR {command} needs a finite number\n"
            act = self.robot.turn if command == "TURN" else self.robot.move
            achieved, contact = act(amount)
            return f"OK {number(achieved)} {self.pose_words()} {1 if contact else 0}\n"
        if command == "CAPTURE" and not args:
            time_s = time.monotonic() - self.start
            pose = self.pose_words()  # the pose when the picture is taken
            width, height, pixels = self.robot.grab_frame()
            if len(pixels) != width * height * 3:
                return f"ERR frame has {len(pixels)} bytes, not {width}x{height}x3\n"
            self.send(f"FRAME {width} {height} {pose} {number(time_s)}\n")
            self.send(pixels)
            return None
        if command == "ODOM" and not args:
            return f"OK {self.pose_words()}\n"
        return "ERR expected HELLO, TURN <degrees>, MOVE <metres>, CAPTURE or ODOM\n"

    def run(self):
        for raw in self.reader:
            words = raw.decode("ascii", "replace").split()
            if not words:
                self.send("ERR empty request\n")
                continue
            try:
                reply = self.answer(words)
            except (ValueError, RuntimeError, NotImplementedError) as error:
                message = str(error).replace("\r", " ").replace("\n", " ")
                reply = f"ERR {words[0]} failed: {message}\n"
            if reply is not None:
                self.send(reply)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--host", default="0.0.0.0", help="address to listen on")
    parser.add_argument("--port", type=int, default=5555)
    parser.add_argument("--camera", type=int, default=0, help="cv2.VideoCapture index")
    parser.add_argument("--fake", action="store_true", help="no hardware: fake odometry, grey frames")
    args = parser.parse_args()

    robot = FakeRobot() if args.fake else MyRobot(args.camera)
    with socket.create_server((args.host, args.port)) as server:
        port = server.getsockname()[1]
        print(f"robot_adapter: listening on {args.host}:{port}", file=sys.stderr)
        while True:  # one client at a time
            connection, peer = server.accept()
            connection.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            print(f"robot_adapter: client {peer[0]}:{peer[1]} connected", file=sys.stderr)
            with connection:
                try:
                    Session(robot, connection).run()
                except OSError as error:
                    print(f"robot_adapter: {error}", file=sys.stderr)
            print("robot_adapter: client left", file=sys.stderr)


if __name__ == "__main__":
    try:
        main()
    except KeyboardInterrupt:
        pass
