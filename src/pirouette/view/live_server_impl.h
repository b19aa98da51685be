#pragma once

// Internal to view/: the live server's state and its one Asio thread
// (live_server.cc), which the sessions it serves use (http_session.h,
// ws_session.h). Not part of view/'s interface: include view/live_server.h.

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange unincluded

#include <boost/asio.hpp>

#include <atomic>
#include <cstdint>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "pirouette/view/live_server.h"

namespace pirouette::view {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using ErrorCode = boost::system::error_code;

// A message as published: its bytes, shared by every client sent it.
struct Published {
  std::shared_ptr<const std::vector<std::uint8_t>> payload;
  std::uint64_t time_ns = 0;
};

class LiveServer::Impl {
 public:
  class WsSession;
  class HttpSession;

  Impl(LiveServerOptions options, std::vector<Channel> channels)
      : options_(std::move(options)), channels_(std::move(channels)), acceptor_(io_) {
    for (std::size_t i = 0; i < channels_.size(); ++i) index_of_[channels_[i].id] = i;
    latest_.resize(channels_.size());
    Listen();
  }

  void Start() {
    Accept();
    thread_ = std::thread([this] {
      // A handler that throws (memory exhausted) costs its connection, not
      // the run: the loop goes on until Stop.
      while (true) {
        try {
          io_.run();
          return;
        } catch (const std::exception&) {
          ++handler_failures_;
        }
      }
    });
  }

  void Stop();

  void Publish(std::uint32_t channel_id, Published message) {
    asio::post(io_,
               [this, channel_id, message = std::move(message)] { Deliver(channel_id, message); });
  }

  bool AllFlushed(double timeout_s);

  const Endpoint& endpoint() const { return endpoint_; }

  LiveServerStats Stats() const {
    LiveServerStats stats;
    stats.clients = clients_.load();
    stats.clients_ever = clients_ever_.load();
    stats.messages_sent = messages_sent_.load();
    stats.bytes_sent = bytes_sent_.load();
    stats.messages_skipped = messages_skipped_.load();
    stats.http_requests = http_requests_.load();
    stats.refused = refused_.load();
    return stats;
  }

  // The session layer's access (all on the server's thread).
  const LiveServerOptions& options() const { return options_; }
  const std::vector<Channel>& channels() const { return channels_; }
  const std::optional<Published>* Latest(std::uint32_t channel_id) const {
    const auto at = index_of_.find(channel_id);
    return at == index_of_.end() ? nullptr : &latest_[at->second];
  }
  void Add(const std::shared_ptr<WsSession>& session);
  void Remove(const std::shared_ptr<WsSession>& session);
  void CountSent(std::size_t bytes) {
    ++messages_sent_;
    bytes_sent_ += bytes;
  }
  void CountSkipped() { ++messages_skipped_; }
  void CountHttp() { ++http_requests_; }
  void CountRefused() { ++refused_; }
  const std::string& session_id() const { return session_id_; }

  // HTTP and WebSocket sessions alive (declared before io_: the sessions
  // io_'s pending handlers hold count down when io_ goes).
  std::atomic<int> connections{0};

 private:
  void Listen();
  void Accept();
  void Deliver(std::uint32_t channel_id, const Published& message);
  void CloseAll();

  LiveServerOptions options_;
  std::vector<Channel> channels_;
  std::map<std::uint32_t, std::size_t> index_of_;
  std::vector<std::optional<Published>> latest_;
  asio::io_context io_;
  // Keeps run() going while nobody is connected, until Stop.
  asio::executor_work_guard<asio::io_context::executor_type> work_{io_.get_executor()};
  tcp::acceptor acceptor_;
  asio::steady_timer accept_retry_{io_};
  Endpoint endpoint_;
  std::set<std::shared_ptr<WsSession>> sessions_;
  std::string session_id_;
  std::thread thread_;
  std::atomic<int> clients_{0};
  std::atomic<int> clients_ever_{0};
  std::atomic<std::uint64_t> messages_sent_{0};
  std::atomic<std::uint64_t> bytes_sent_{0};
  std::atomic<std::uint64_t> messages_skipped_{0};
  std::atomic<std::uint64_t> http_requests_{0};
  std::atomic<std::uint64_t> refused_{0};
  std::atomic<std::uint64_t> handler_failures_{0};
};

}  // namespace pirouette::view
