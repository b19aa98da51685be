#pragma once

// Internal to view/: the live server's WebSocket clients (live_server_impl.h).

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange unincluded

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "pirouette/view/foxglove_protocol.h"
#include "pirouette/view/live_server_impl.h"

namespace pirouette::view {

// One WebSocket client: its subscriptions, its advertised channels (with
// --view-control), and what waits to be sent to it.
class LiveServer::Impl::WsSession : public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(Impl& server, tcp::socket socket) : server_(server), ws_(std::move(socket)) {
    ++server_.connections;
  }
  ~WsSession() { --server_.connections; }
  WsSession(const WsSession&) = delete;
  WsSession& operator=(const WsSession&) = delete;

  void Accept(const boost::beast::http::request<boost::beast::http::string_body>& request);

  // A message on `channel_id` for this client, if it subscribes to it.
  void Deliver(std::uint32_t channel_id, const Published& message);

  void Close();

  bool Flushed() const { return !writing_ && texts_.empty() && order_.empty(); }

 private:
  void OnAccept(const ErrorCode& error);
  void Read();
  void OnRead(const ErrorCode& error);
  void Refuse(const std::string& why);

  void HandleText(std::string_view text);
  void Handle(const Subscribe& request);
  void Handle(const Unsubscribe& request);
  void Handle(const ClientAdvertise& request);
  void Handle(const ClientUnadvertise& request);
  void Handle(const Unsupported& request);
  void Handle(const ParseError& error);
  void HandleBinary(std::span<const std::uint8_t> bytes);

  void SendText(std::string text);
  void Queue(std::uint32_t subscription, const Published& message);
  void WriteNext();
  void OnWrite(const ErrorCode& error, std::size_t bytes);
  void Drop();

  Impl& server_;
  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  boost::beast::flat_buffer buffer_;
  bool open_ = false;
  std::map<std::uint32_t, std::uint32_t> subscriptions_;  // subscription id → channel id
  std::map<std::uint32_t, ClientChannel> client_channels_;
  std::deque<std::string> texts_;
  std::map<std::uint32_t, Published> pending_;  // one a subscription
  std::deque<std::uint32_t> order_;             // pending_'s subscriptions, oldest first
  bool writing_ = false;
  std::string text_in_flight_;
  std::array<std::uint8_t, kMessageHeaderBytes> header_{};
  Published data_in_flight_;
};

}  // namespace pirouette::view
