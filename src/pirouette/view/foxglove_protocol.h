#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace pirouette::view {

// The Foxglove WebSocket protocol, version 1 (subprotocol
// `foxglove.websocket.v1`, github.com/foxglove/ws-protocol docs/spec.md): the
// messages a server sends and parses, with no socket in sight.
inline constexpr std::string_view kSubprotocol = "foxglove.websocket.v1";

// A channel the server advertises.
struct Channel {
  std::uint32_t id = 0;
  std::string topic;            // "/map"
  std::string encoding;         // "cdr"
  std::string schema_name;      // "nav_msgs/msg/OccupancyGrid"
  std::string schema;           // its ros2msg text
  std::string schema_encoding;  // "ros2msg"
};

enum class StatusLevel { kInfo = 0, kWarning = 1, kError = 2 };

// Server → client, text frames (JSON).
std::string ServerInfoJson(std::string_view name, bool client_publish, std::string_view session_id);
std::string AdvertiseJson(const std::vector<Channel>& channels);
std::string StatusJson(StatusLevel level, std::string_view message);

// Server → client binary frame header of a message on a subscription:
// opcode 0x01, subscription id (uint32 LE), receive time in ns (uint64 LE);
// the payload follows.
inline constexpr std::size_t kMessageHeaderBytes = 13;
std::array<std::uint8_t, kMessageHeaderBytes> MessageDataHeader(std::uint32_t subscription,
                                                                std::uint64_t time_ns);

// Client → server, parsed. Anything else is a ParseError with its reason.
struct Subscription {
  std::uint32_t id = 0;
  std::uint32_t channel = 0;
};
struct Subscribe {
  std::vector<Subscription> subscriptions;
};
struct Unsubscribe {
  std::vector<std::uint32_t> ids;
};
struct ClientChannel {
  std::uint32_t id = 0;
  std::string topic;
  std::string encoding;
  std::string schema_name;
};
struct ClientAdvertise {
  std::vector<ClientChannel> channels;
};
struct ClientUnadvertise {
  std::vector<std::uint32_t> ids;
};
// A known op this server does not offer (parameters, services, ...).
struct Unsupported {
  std::string op;
};
struct ParseError {
  std::string reason;
};
using ClientRequest = std::variant<Subscribe, Unsubscribe, ClientAdvertise, ClientUnadvertise,
                                   Unsupported, ParseError>;

ClientRequest ParseClientText(std::string_view text);

// A client's binary frame: opcode 0x01 (message data on one of its
// advertised channels) with the channel id (uint32 LE) and the payload.
struct ClientMessage {
  std::uint32_t channel = 0;
  std::span<const std::uint8_t> payload;
};
std::variant<ClientMessage, ParseError> ParseClientBinary(std::span<const std::uint8_t> bytes);

}  // namespace pirouette::view
