#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <string>

#include "pirouette/robot/line_protocol.h"
#include "pirouette/robot/robot.h"
#include "pirouette/robot/tcp_connection.h"

namespace pirouette::robot {

struct RobotServerOptions {
  std::string host = "127.0.0.1";  // the address to listen on ("0.0.0.0": every interface)
  int port = 5555;                 // 0: any free port (see RobotServer::port())
  // Serve() returns soon after this becomes true (e.g. set by a signal
  // handler); may be null.
  const std::atomic<bool>* stop_requested = nullptr;
  // The longest wait for a client to take a reply's bytes before it is
  // dropped.
  std::chrono::milliseconds write_timeout{30000};
  // Told what happens (a client came, went, was refused), one line without
  // '\n'; may be empty. Called on the thread running Serve().
  std::function<void(const std::string&)> log;
  // For testing (sim-serve --fault half-frame@N): from the Nth request of a
  // connection on (counting TURN, MOVE and CAPTURE; 0: never), a CAPTURE is
  // answered with its header and half the frame's bytes, and then nothing
  // more: the connection hangs until the client goes.
  int half_frame_from = 0;
};

// Serves a Robot over TCP with the line protocol (line_protocol.h), one
// client at a time: each request is carried out on the robot and answered.
// A request that is not the protocol, or that the robot throws on, is
// answered with ERR and the connection goes on. A second client while one is
// connected is answered "ERR busy" and closed. Angles reach the robot in
// radians.
class RobotServer {
 public:
  // Binds and listens. Throws RobotError if it cannot (the address is in use,
  // the host is not an address of this machine).
  RobotServer(Robot& robot, RobotServerOptions options);
  ~RobotServer();
  RobotServer(const RobotServer&) = delete;
  RobotServer& operator=(const RobotServer&) = delete;

  // The port it listens on (the one picked when asked for port 0).
  int port() const { return port_; }
  // "HOST:PORT".
  std::string address() const;

  // Serves clients until Stop() or *options.stop_requested; returns within
  // about kStopPollInterval of either (a reply being sent is finished
  // first). Call on one thread.
  void Serve();
  // Asks Serve() to return; callable from any thread.
  void Stop() { stop_.store(true); }

  static constexpr std::chrono::milliseconds kStopPollInterval{50};

 private:
  void ServeClient(TcpConnection client, const std::string& peer);
  // Carries out one request line and sends its reply; false when the client
  // could not be written to.
  bool Answer(TcpConnection& client, const std::string& line);
  // half_frame_from: reads and drops what the client sends until it goes.
  void Hang(TcpConnection& client, const std::string& peer);
  bool Stopping() const;
  // Answers "ERR busy" to clients that connect while one is served.
  void RefuseWaitingClients();
  void Log(const std::string& message) const;

  Robot& robot_;
  RobotServerOptions options_;
  int listen_fd_ = -1;
  int port_ = 0;
  std::atomic<bool> stop_{false};
  int requests_ = 0;      // TURN, MOVE and CAPTURE of the connection served
  bool hanging_ = false;  // half_frame_from: half a frame was sent
};

}  // namespace pirouette::robot
