#include "pirouette/view/http_session.h"

#include <boost/beast/websocket.hpp>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "pirouette/view/foxglove_protocol.h"
#include "pirouette/view/web_assets.h"
#include "pirouette/view/ws_session.h"

namespace pirouette::view {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;

namespace {

// An HTTP request must arrive whole within this, or the connection closes.
constexpr auto kHttpTimeout = std::chrono::seconds(10);
// Requests are GETs: no body is needed; headers as browsers send them.
constexpr std::uint64_t kHttpBodyLimit = 1024;
constexpr std::uint32_t kHttpHeaderLimit = 16 * 1024;

}  // namespace

void LiveServer::Impl::HttpSession::Read() {
  parser_.emplace();
  parser_->body_limit(kHttpBodyLimit);
  parser_->header_limit(kHttpHeaderLimit);
  stream_.expires_after(kHttpTimeout);
  http::async_read(
      stream_, buffer_, *parser_,
      [self = shared_from_this()](const ErrorCode& error, std::size_t) { self->OnRead(error); });
}

void LiveServer::Impl::HttpSession::OnRead(const ErrorCode& error) {
  if (error) {
    if (error != http::error::end_of_stream) Reply(http::status::bad_request, "bad request\n");
    return;
  }
  server_.CountHttp();
  Request request = parser_->release();
  if (websocket::is_upgrade(request)) {
    Upgrade(request);
    return;
  }
  if (request.find(http::field::upgrade) != request.end()) {
    Refuse(request, http::status::bad_request,
           "only a WebSocket upgrade (subprotocol foxglove.websocket.v1) is served here\n");
    return;
  }
  if (request.method() != http::verb::get && request.method() != http::verb::head) {
    Refuse(request, http::status::method_not_allowed, "only GET and HEAD are served\n");
    return;
  }
  const std::optional<WebAsset> asset = FindWebAsset(request.target());
  if (!asset) {
    Refuse(request, http::status::not_found, "not found\n");
    return;
  }
  Respond(request, http::status::ok, asset->content_type,
          std::string(reinterpret_cast<const char*>(asset->bytes.data()), asset->bytes.size()));
}

void LiveServer::Impl::HttpSession::Upgrade(const Request& request) {
  const std::string_view target = request.target();
  if (target != "/" && target.substr(0, 2) != "/?") {
    Refuse(request, http::status::not_found, "the WebSocket is at /\n");
    return;
  }
  const auto offered = request.find(http::field::sec_websocket_protocol);
  if (offered == request.end() || offered->value().find(kSubprotocol) == std::string_view::npos) {
    Refuse(request, http::status::bad_request,
           "offer the subprotocol foxglove.websocket.v1 (Sec-WebSocket-Protocol)\n");
    return;
  }
  stream_.expires_never();  // the WebSocket keeps its own timeouts
  std::make_shared<WsSession>(server_, stream_.release_socket())->Accept(request);
}

void LiveServer::Impl::HttpSession::Refuse(const Request& request, http::status status,
                                           std::string text) {
  server_.CountRefused();
  Respond(request, status, "text/plain; charset=utf-8", std::move(text), false);
}

void LiveServer::Impl::HttpSession::Respond(const Request& request, http::status status,
                                            std::string_view content_type, std::string body,
                                            bool keep_alive) {
  auto response = std::make_shared<http::response<http::string_body>>(status, request.version());
  response->set(http::field::server, "pirouette");
  response->set(http::field::content_type, content_type);
  response->set(http::field::cache_control, "no-store");
  response->set("X-Content-Type-Options", "nosniff");
  response->keep_alive(keep_alive && request.keep_alive());
  const bool head = request.method() == http::verb::head;
  response->body() = std::move(body);
  response->prepare_payload();
  if (head) response->body().clear();
  Write(response);
}

void LiveServer::Impl::HttpSession::Reply(http::status status, std::string text) {
  server_.CountRefused();
  auto response = std::make_shared<http::response<http::string_body>>(status, 11);
  response->set(http::field::content_type, "text/plain; charset=utf-8");
  response->keep_alive(false);
  response->body() = std::move(text);
  response->prepare_payload();
  Write(response);
}

void LiveServer::Impl::HttpSession::Write(
    const std::shared_ptr<http::response<http::string_body>>& response) {
  http::async_write(stream_, *response,
                    [self = shared_from_this(), response](const ErrorCode& error, std::size_t) {
                      if (!error && response->keep_alive()) {
                        self->Read();
                      } else {
                        ErrorCode ignored;
                        self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
                      }
                    });
}

}  // namespace pirouette::view
