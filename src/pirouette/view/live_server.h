#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "pirouette/view/endpoint.h"
#include "pirouette/view/foxglove_protocol.h"

namespace pirouette::view {

// The live view cannot listen (the port is taken, the host is not one of the
// machine's addresses).
class ViewError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a client with --view-control may ask of a run.
enum class ControlCommand { kPause, kResume, kStop, kHome };

struct LiveServerOptions {
  Endpoint endpoint;
  std::string name = "pirouette";
  // Clients may publish on `/pirouette/control` (the protocol's clientPublish
  // capability); off: every state-changing request is refused.
  bool control = false;
  // Answers a control command with the message the client is shown. Called
  // on the server's thread: it must not block (set a flag).
  std::function<std::string(ControlCommand)> on_control;
  // A client's message larger than this closes its connection (code 1009);
  // the run goes on. Subscribing to every channel takes well under 1 kB.
  std::size_t max_client_message_bytes = std::size_t{64} * 1024;
};

// The latest message of each channel is kept and sent to each new subscriber
// at once (so a late client gets the map without waiting for a stop).
struct LiveServerStats {
  int clients = 0;       // connected now (WebSocket)
  int clients_ever = 0;  // WebSocket clients accepted since the start
  std::uint64_t messages_sent = 0;
  std::uint64_t bytes_sent = 0;
  std::uint64_t messages_skipped = 0;  // replaced by a newer one before a slow client took it
  std::uint64_t http_requests = 0;
  std::uint64_t refused = 0;  // requests and messages refused (with their reason)
};

// One port, HTTP and WebSocket (SPEC.md, "Live view"): GET of the embedded
// web page's files, and the Foxglove WebSocket protocol at `/` (subprotocol
// foxglove.websocket.v1). Boost.Beast (Debian's libboost-dev) over one
// Asio thread: it is header-only, already the HTTP/WebSocket library of the
// Boost the project builds with, and keeps the upgrade on the same socket.
//
// Publish never waits for a client: each client holds at most one message a
// subscription waiting to be sent; a newer one replaces it (the client skips
// frames), so a slow or stalled client costs the run nothing but the memory
// of one message per channel.
class LiveServer {
 public:
  // Listens at once; throws ViewError naming the endpoint when it cannot.
  LiveServer(LiveServerOptions options, std::vector<Channel> channels);
  ~LiveServer();  // closes every connection
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  // The endpoint listened on (its port resolved when 0 was asked).
  const Endpoint& endpoint() const;

  // Sends `payload` on channel `channel_id` (an id of the channels given) to
  // every subscriber, stamped `time_ns` (ns since the epoch). Thread-safe.
  void Publish(std::uint32_t channel_id, std::shared_ptr<const std::vector<std::uint8_t>> payload,
               std::uint64_t time_ns);

  LiveServerStats Stats() const;

  // Waits up to `timeout_s` until every client has been sent everything
  // published so far; false on the timeout.
  bool WaitFlushed(double timeout_s) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pirouette::view
