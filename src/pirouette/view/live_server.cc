#include "pirouette/view/live_server.h"

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange unincluded

#include <chrono>
#include <future>
#include <memory>
#include <set>
#include <string>
#include <thread>

#include "pirouette/view/http_session.h"
#include "pirouette/view/live_server_impl.h"
#include "pirouette/view/ws_session.h"

namespace pirouette::view {

namespace {

// How long closing the server waits for clients to take their close frame.
constexpr auto kCloseGrace = std::chrono::milliseconds(500);
// Connections (HTTP and WebSocket) served at once; more are closed at once,
// so that a flood of sockets cannot take the run's file descriptors.
constexpr int kMaxConnections = 64;
// After an accept fails (out of file descriptors), the wait before the next.
constexpr auto kAcceptRetry = std::chrono::milliseconds(100);

}  // namespace

void LiveServer::Impl::Stop() {
  asio::post(io_, [this] { CloseAll(); });
  const auto deadline = std::chrono::steady_clock::now() + kCloseGrace;
  while (clients_.load() > 0 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  io_.stop();
  if (thread_.joinable()) thread_.join();
}

void LiveServer::Impl::Listen() {
  ErrorCode error;
  asio::ip::address address = asio::ip::make_address(options_.endpoint.host, error);
  if (error) {  // a name: resolve it
    tcp::resolver resolver(io_);
    const auto results = resolver.resolve(options_.endpoint.host, "", error);
    if (error || results.empty()) {
      throw ViewError("the live view's host '" + options_.endpoint.host +
                      "' is not an address of this machine: " + error.message());
    }
    address = results.begin()->endpoint().address();
  }
  const tcp::endpoint at(address, options_.endpoint.port);
  const std::string where = HttpUrl(options_.endpoint);
  const auto check = [&](const char* step) {
    if (error) {
      throw ViewError("the live view cannot " + std::string(step) + " " + where + ": " +
                      error.message());
    }
  };
  acceptor_.open(at.protocol(), error);
  check("open a socket for");
  acceptor_.set_option(asio::socket_base::reuse_address(true), error);
  check("set up");
  acceptor_.bind(at, error);
  check("listen on");
  acceptor_.listen(asio::socket_base::max_listen_connections, error);
  check("listen on");
  endpoint_ = options_.endpoint;
  endpoint_.port = acceptor_.local_endpoint().port();
  session_id_ = std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(
                                   std::chrono::system_clock::now().time_since_epoch())
                                   .count());
}

void LiveServer::Impl::Accept() {
  acceptor_.async_accept(io_, [this](const ErrorCode& error, tcp::socket socket) {
    if (error == asio::error::operation_aborted || !acceptor_.is_open()) return;  // Stop
    if (error) {  // out of descriptors, say: try again in a while
      accept_retry_.expires_after(kAcceptRetry);
      accept_retry_.async_wait([this](const ErrorCode& e) {
        if (!e) Accept();
      });
      return;
    }
    if (connections.load() >= kMaxConnections) {
      ++refused_;
      ErrorCode ignored;
      socket.close(ignored);
    } else {
      std::make_shared<HttpSession>(*this, std::move(socket))->Read();
    }
    Accept();
  });
}

void LiveServer::Impl::Deliver(std::uint32_t channel_id, const Published& message) {
  const auto at = index_of_.find(channel_id);
  if (at == index_of_.end()) return;
  latest_[at->second] = message;
  for (const auto& session : sessions_) session->Deliver(channel_id, message);
}

void LiveServer::Impl::Add(const std::shared_ptr<WsSession>& session) {
  sessions_.insert(session);
  ++clients_;
  ++clients_ever_;
}

void LiveServer::Impl::Remove(const std::shared_ptr<WsSession>& session) {
  if (sessions_.erase(session) > 0) --clients_;
}

void LiveServer::Impl::CloseAll() {
  ErrorCode ignored;
  acceptor_.close(ignored);
  accept_retry_.cancel();
  const std::set<std::shared_ptr<WsSession>> sessions = sessions_;
  for (const auto& session : sessions) session->Close();
}

bool LiveServer::Impl::AllFlushed(double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (true) {
    auto done = std::make_shared<std::promise<bool>>();
    std::future<bool> flushed = done->get_future();
    asio::post(io_, [this, done] {
      bool all = true;
      for (const auto& session : sessions_) all = all && session->Flushed();
      done->set_value(all);
    });
    if (flushed.wait_until(deadline) != std::future_status::ready) return false;
    if (flushed.get()) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

LiveServer::LiveServer(LiveServerOptions options, std::vector<Channel> channels)
    : impl_(std::make_unique<Impl>(std::move(options), std::move(channels))) {
  impl_->Start();
}

LiveServer::~LiveServer() { impl_->Stop(); }

const Endpoint& LiveServer::endpoint() const { return impl_->endpoint(); }

void LiveServer::Publish(std::uint32_t channel_id,
                         std::shared_ptr<const std::vector<std::uint8_t>> payload,
                         std::uint64_t time_ns) {
  impl_->Publish(channel_id, Published{std::move(payload), time_ns});
}

LiveServerStats LiveServer::Stats() const { return impl_->Stats(); }

bool LiveServer::WaitFlushed(double timeout_s) const { return impl_->AllFlushed(timeout_s); }

}  // namespace pirouette::view
