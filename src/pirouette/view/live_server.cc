#include "pirouette/view/live_server.h"

#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange unincluded

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <deque>
#include <future>
#include <map>
#include <optional>
#include <set>
#include <thread>

#include "pirouette/view/web_assets.h"

namespace pirouette::view {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using ErrorCode = boost::system::error_code;

namespace {

// An HTTP request must arrive whole within this, or the connection closes.
constexpr auto kHttpTimeout = std::chrono::seconds(10);
// Requests are GETs: no body is needed; headers as browsers send them.
constexpr std::uint64_t kHttpBodyLimit = 1024;
constexpr std::uint32_t kHttpHeaderLimit = 16 * 1024;
// Status replies a client has not taken yet; past this it is not reading
// what it asks for and is dropped.
constexpr std::size_t kMaxQueuedTexts = 64;
// How long closing the server waits for clients to take their close frame.
constexpr auto kCloseGrace = std::chrono::milliseconds(500);
constexpr std::string_view kControlTopic = "/pirouette/control";
// Connections (HTTP and WebSocket) served at once; more are closed at once,
// so that a flood of sockets cannot take the run's file descriptors.
constexpr int kMaxConnections = 64;
// Subscriptions a client may hold: each channel a few times over is plenty.
constexpr std::size_t kMaxSubscriptions = 64;
// After an accept fails (out of file descriptors), the wait before the next.
constexpr auto kAcceptRetry = std::chrono::milliseconds(100);

struct Published {
  std::shared_ptr<const std::vector<std::uint8_t>> payload;
  std::uint64_t time_ns = 0;
};

std::optional<ControlCommand> CommandNamed(const std::string& name) {
  if (name == "pause") return ControlCommand::kPause;
  if (name == "resume") return ControlCommand::kResume;
  if (name == "stop") return ControlCommand::kStop;
  if (name == "home") return ControlCommand::kHome;
  return std::nullopt;
}

}  // namespace

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

  void Stop() {
    asio::post(io_, [this] { CloseAll(); });
    const auto deadline = std::chrono::steady_clock::now() + kCloseGrace;
    while (clients_.load() > 0 && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    io_.stop();
    if (thread_.joinable()) thread_.join();
  }

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

  void Accept(const http::request<http::string_body>& request) {
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.set_option(websocket::stream_base::decorator([](websocket::response_type& response) {
      response.set(http::field::sec_websocket_protocol, kSubprotocol);
      response.set(http::field::server, "pirouette");
    }));
    ws_.read_message_max(server_.options().max_client_message_bytes);
    ws_.async_accept(
        request, [self = shared_from_this()](const ErrorCode& error) { self->OnAccept(error); });
  }

  // A message on `channel_id` for this client, if it subscribes to it.
  void Deliver(std::uint32_t channel_id, const Published& message) {
    for (const auto& [subscription, channel] : subscriptions_) {
      if (channel == channel_id) Queue(subscription, message);
    }
  }

  void Close() {
    if (!open_) return;
    open_ = false;
    ws_.async_close(websocket::close_code::going_away,
                    [self = shared_from_this()](const ErrorCode&) { self->Drop(); });
  }

  bool Flushed() const { return !writing_ && texts_.empty() && order_.empty(); }

 private:
  void OnAccept(const ErrorCode& error) {
    if (error) return;  // not added: nothing to undo
    open_ = true;
    server_.Add(shared_from_this());
    SendText(
        ServerInfoJson(server_.options().name, server_.options().control, server_.session_id()));
    SendText(AdvertiseJson(server_.channels()));
    Read();
  }

  void Read() {
    ws_.async_read(buffer_, [self = shared_from_this()](const ErrorCode& error, std::size_t) {
      self->OnRead(error);
    });
  }

  void OnRead(const ErrorCode& error) {
    if (error) {  // closed, too big (Beast has sent close 1009), or broken
      Drop();
      return;
    }
    const auto* data = static_cast<const std::uint8_t*>(buffer_.cdata().data());
    const std::span<const std::uint8_t> bytes(data, buffer_.size());
    if (ws_.got_text()) {
      HandleText(std::string_view(reinterpret_cast<const char*>(data), bytes.size()));
    } else {
      HandleBinary(bytes);
    }
    buffer_.consume(buffer_.size());
    if (open_) Read();
  }

  void Refuse(const std::string& why) {
    server_.CountRefused();
    SendText(StatusJson(StatusLevel::kError, why));
  }

  static constexpr const char* kNoControl =
      "refused: this live view was started without --view-control, so it changes nothing";

  void HandleText(std::string_view text) {
    std::visit([this](const auto& request) { Handle(request); }, ParseClientText(text));
  }

  void Handle(const Subscribe& request) {
    for (const Subscription& s : request.subscriptions) {
      const std::optional<Published>* latest = server_.Latest(s.channel);
      if (latest == nullptr) {
        Refuse("subscribe: no channel " + std::to_string(s.channel));
      } else if (subscriptions_.size() >= kMaxSubscriptions) {
        Refuse("subscribe: a client may hold " + std::to_string(kMaxSubscriptions) +
               " subscriptions");
      } else if (!subscriptions_.emplace(s.id, s.channel).second) {
        Refuse("subscribe: subscription id " + std::to_string(s.id) + " is already in use");
      } else if (latest->has_value()) {
        Queue(s.id, **latest);  // a late subscriber gets the latest at once
      }
    }
  }

  void Handle(const Unsubscribe& request) {
    for (const std::uint32_t id : request.ids) {
      subscriptions_.erase(id);
      if (pending_.erase(id) > 0) std::erase(order_, id);
    }
  }

  void Handle(const ClientAdvertise& request) {
    if (!server_.options().control) {
      Refuse(std::string("advertise: ") + kNoControl);
      return;
    }
    for (const ClientChannel& c : request.channels) {
      if (c.topic != kControlTopic || c.encoding != "json") {
        Refuse("advertise: only " + std::string(kControlTopic) +
               " in json encoding is taken, not " + c.topic + " in " + c.encoding);
        continue;
      }
      if (client_channels_.size() >= kMaxSubscriptions && !client_channels_.contains(c.id)) {
        Refuse("advertise: a client may advertise " + std::to_string(kMaxSubscriptions) +
               " channels");
        continue;
      }
      client_channels_[c.id] = c;
    }
  }

  void Handle(const ClientUnadvertise& request) {
    for (const std::uint32_t id : request.ids) client_channels_.erase(id);
  }

  void Handle(const Unsupported& request) {
    Refuse("op \"" + request.op + "\" is not offered by this server");
  }

  void Handle(const ParseError& error) { Refuse("malformed message: " + error.reason); }

  void HandleBinary(std::span<const std::uint8_t> bytes) {
    const auto parsed = ParseClientBinary(bytes);
    if (const auto* error = std::get_if<ParseError>(&parsed)) {
      Refuse("malformed binary message: " + error->reason);
      return;
    }
    if (!server_.options().control) {
      Refuse(std::string("control: ") + kNoControl);
      return;
    }
    const auto& message = std::get<ClientMessage>(parsed);
    if (client_channels_.find(message.channel) == client_channels_.end()) {
      Refuse("control: channel " + std::to_string(message.channel) + " was not advertised");
      return;
    }
    const auto json =
        nlohmann::json::parse(message.payload.begin(), message.payload.end(), nullptr, false);
    const std::string name =
        json.is_object() && json.contains("command") && json["command"].is_string()
            ? json["command"].get<std::string>()
            : std::string();
    const std::optional<ControlCommand> command = CommandNamed(name);
    if (!command) {
      Refuse(R"(control: expected {"command": "pause"|"resume"|"stop"|"home"})");
      return;
    }
    const std::string answer =
        server_.options().on_control ? server_.options().on_control(*command) : name;
    SendText(StatusJson(StatusLevel::kInfo, answer));
  }

  void SendText(std::string text) {
    if (!open_) return;
    if (texts_.size() >= kMaxQueuedTexts) {  // it asks and does not read the answers
      Close();
      return;
    }
    texts_.push_back(std::move(text));
    WriteNext();
  }

  void Queue(std::uint32_t subscription, const Published& message) {
    if (!open_) return;
    auto [at, added] = pending_.try_emplace(subscription, message);
    if (added) {
      order_.push_back(subscription);
    } else {
      at->second = message;  // a slow client skips the older one
      server_.CountSkipped();
    }
    WriteNext();
  }

  void WriteNext() {
    if (writing_ || !open_) return;
    if (!texts_.empty()) {
      text_in_flight_ = std::move(texts_.front());
      texts_.pop_front();
      writing_ = true;
      ws_.text(true);
      ws_.async_write(asio::buffer(text_in_flight_),
                      [self = shared_from_this()](const ErrorCode& error, std::size_t bytes) {
                        self->OnWrite(error, bytes);
                      });
      return;
    }
    if (order_.empty()) return;
    const std::uint32_t subscription = order_.front();
    order_.pop_front();
    const auto at = pending_.find(subscription);
    data_in_flight_ = std::move(at->second);
    pending_.erase(at);
    header_ = MessageDataHeader(subscription, data_in_flight_.time_ns);
    writing_ = true;
    ws_.binary(true);
    const std::array<asio::const_buffer, 2> buffers = {asio::buffer(header_),
                                                       asio::buffer(*data_in_flight_.payload)};
    ws_.async_write(buffers,
                    [self = shared_from_this()](const ErrorCode& error, std::size_t bytes) {
                      self->OnWrite(error, bytes);
                    });
  }

  void OnWrite(const ErrorCode& error, std::size_t bytes) {
    writing_ = false;
    data_in_flight_ = {};
    if (error) {
      Drop();
      return;
    }
    server_.CountSent(bytes);
    WriteNext();
  }

  void Drop() {
    open_ = false;
    pending_.clear();
    order_.clear();
    texts_.clear();
    server_.Remove(shared_from_this());
  }

  Impl& server_;
  websocket::stream<beast::tcp_stream> ws_;
  beast::flat_buffer buffer_;
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

  void Read() {
    parser_.emplace();
    parser_->body_limit(kHttpBodyLimit);
    parser_->header_limit(kHttpHeaderLimit);
    stream_.expires_after(kHttpTimeout);
    http::async_read(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](const ErrorCode& error, std::size_t) { self->OnRead(error); });
  }

 private:
  using Request = http::request<http::string_body>;

  void OnRead(const ErrorCode& error) {
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

  void Upgrade(const Request& request) {
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

  void Refuse(const Request& request, http::status status, std::string text) {
    server_.CountRefused();
    Respond(request, status, "text/plain; charset=utf-8", std::move(text), false);
  }

  void Respond(const Request& request, http::status status, std::string_view content_type,
               std::string body, bool keep_alive = true) {
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

  void Reply(http::status status, std::string text) {
    server_.CountRefused();
    auto response = std::make_shared<http::response<http::string_body>>(status, 11);
    response->set(http::field::content_type, "text/plain; charset=utf-8");
    response->keep_alive(false);
    response->body() = std::move(text);
    response->prepare_payload();
    Write(response);
  }

  void Write(const std::shared_ptr<http::response<http::string_body>>& response) {
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

  Impl& server_;
  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
};

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
