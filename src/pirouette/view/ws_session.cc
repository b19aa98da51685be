#include "pirouette/view/ws_session.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <utility>
#include <variant>

namespace pirouette::view {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;

namespace {

// Status replies a client has not taken yet; past this it is not reading
// what it asks for and is dropped.
constexpr std::size_t kMaxQueuedTexts = 64;
constexpr std::string_view kControlTopic = "/pirouette/control";
// Subscriptions a client may hold: each channel a few times over is plenty.
constexpr std::size_t kMaxSubscriptions = 64;

constexpr const char* kNoControl =
    "refused: this live view was started without --view-control, so it changes nothing";

std::optional<ControlCommand> CommandNamed(const std::string& name) {
  if (name == "pause") return ControlCommand::kPause;
  if (name == "resume") return ControlCommand::kResume;
  if (name == "stop") return ControlCommand::kStop;
  if (name == "home") return ControlCommand::kHome;
  return std::nullopt;
}

}  // namespace

void LiveServer::Impl::WsSession::Accept(const http::request<http::string_body>& request) {
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.set_option(websocket::stream_base::decorator([](websocket::response_type& response) {
    response.set(http::field::sec_websocket_protocol, kSubprotocol);
    response.set(http::field::server, "pirouette");
  }));
  ws_.read_message_max(server_.options().max_client_message_bytes);
  ws_.async_accept(request,
                   [self = shared_from_this()](const ErrorCode& error) { self->OnAccept(error); });
}

void LiveServer::Impl::WsSession::Deliver(std::uint32_t channel_id, const Published& message) {
  for (const auto& [subscription, channel] : subscriptions_) {
    if (channel == channel_id) Queue(subscription, message);
  }
}

void LiveServer::Impl::WsSession::Close() {
  if (!open_) return;
  open_ = false;
  ws_.async_close(websocket::close_code::going_away,
                  [self = shared_from_this()](const ErrorCode&) { self->Drop(); });
}

void LiveServer::Impl::WsSession::OnAccept(const ErrorCode& error) {
  if (error) return;  // not added: nothing to undo
  open_ = true;
  server_.Add(shared_from_this());
  SendText(ServerInfoJson(server_.options().name, server_.options().control, server_.session_id()));
  SendText(AdvertiseJson(server_.channels()));
  Read();
}

void LiveServer::Impl::WsSession::Read() {
  ws_.async_read(buffer_, [self = shared_from_this()](const ErrorCode& error, std::size_t) {
    self->OnRead(error);
  });
}

void LiveServer::Impl::WsSession::OnRead(const ErrorCode& error) {
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

void LiveServer::Impl::WsSession::Refuse(const std::string& why) {
  server_.CountRefused();
  SendText(StatusJson(StatusLevel::kError, why));
}

void LiveServer::Impl::WsSession::HandleText(std::string_view text) {
  std::visit([this](const auto& request) { Handle(request); }, ParseClientText(text));
}

void LiveServer::Impl::WsSession::Handle(const Subscribe& request) {
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

void LiveServer::Impl::WsSession::Handle(const Unsubscribe& request) {
  for (const std::uint32_t id : request.ids) {
    subscriptions_.erase(id);
    if (pending_.erase(id) > 0) std::erase(order_, id);
  }
}

void LiveServer::Impl::WsSession::Handle(const ClientAdvertise& request) {
  if (!server_.options().control) {
    Refuse(std::string("advertise: ") + kNoControl);
    return;
  }
  for (const ClientChannel& c : request.channels) {
    if (c.topic != kControlTopic || c.encoding != "json") {
      Refuse("advertise: only " + std::string(kControlTopic) + " in json encoding is taken, not " +
             c.topic + " in " + c.encoding);
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

void LiveServer::Impl::WsSession::Handle(const ClientUnadvertise& request) {
  for (const std::uint32_t id : request.ids) client_channels_.erase(id);
}

void LiveServer::Impl::WsSession::Handle(const Unsupported& request) {
  Refuse("op \"" + request.op + "\" is not offered by this server");
}

void LiveServer::Impl::WsSession::Handle(const ParseError& error) {
  Refuse("malformed message: " + error.reason);
}

void LiveServer::Impl::WsSession::HandleBinary(std::span<const std::uint8_t> bytes) {
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

void LiveServer::Impl::WsSession::SendText(std::string text) {
  if (!open_) return;
  if (texts_.size() >= kMaxQueuedTexts) {  // it asks and does not read the answers
    Close();
    return;
  }
  texts_.push_back(std::move(text));
  WriteNext();
}

void LiveServer::Impl::WsSession::Queue(std::uint32_t subscription, const Published& message) {
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

void LiveServer::Impl::WsSession::WriteNext() {
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
  ws_.async_write(buffers, [self = shared_from_this()](const ErrorCode& error, std::size_t bytes) {
    self->OnWrite(error, bytes);
  });
}

void LiveServer::Impl::WsSession::OnWrite(const ErrorCode& error, std::size_t bytes) {
  writing_ = false;
  data_in_flight_ = {};
  if (error) {
    Drop();
    return;
  }
  server_.CountSent(bytes);
  WriteNext();
}

void LiveServer::Impl::WsSession::Drop() {
  open_ = false;
  pending_.clear();
  order_.clear();
  texts_.clear();
  server_.Remove(shared_from_this());
}

}  // namespace pirouette::view
