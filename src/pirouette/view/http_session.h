#pragma once

// Internal to view/: the live server's HTTP connections (live_server_impl.h).

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange unincluded

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "pirouette/view/live_server_impl.h"

namespace pirouette::view {

// One HTTP connection: serves the page's files, or hands a WebSocket upgrade
// of `/` to a WsSession.
class LiveServer::Impl::HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(Impl& server, tcp::socket socket) : server_(server), stream_(std::move(socket)) {
    ++server_.connections;
  }
  ~HttpSession() { --server_.connections; }
  HttpSession(const HttpSession&) = delete;
  HttpSession& operator=(const HttpSession&) = delete;

  void Read();

 private:
  using Request = boost::beast::http::request<boost::beast::http::string_body>;

  void OnRead(const ErrorCode& error);
  void Upgrade(const Request& request);
  void Refuse(const Request& request, boost::beast::http::status status, std::string text);
  void Respond(const Request& request, boost::beast::http::status status,
               std::string_view content_type, std::string body, bool keep_alive = true);
  void Reply(boost::beast::http::status status, std::string text);
  void Write(const std::shared_ptr<boost::beast::http::response<boost::beast::http::string_body>>&
                 response);

  Impl& server_;
  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
};

}  // namespace pirouette::view
