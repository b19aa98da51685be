#include "pirouette/view/foxglove_protocol.h"

#include <nlohmann/json.hpp>

#include <limits>

namespace pirouette::view {

namespace {

using nlohmann::json;

constexpr std::uint8_t kMessageData = 0x01;

void PutLittleEndian(std::uint8_t* at, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) at[i] = static_cast<std::uint8_t>(value >> (8 * i));
}

// A field that must be an unsigned 32-bit id; throws json::type_error otherwise.
std::uint32_t IdOf(const json& object, const char* field) {
  const json& value = object.at(field);
  if (!value.is_number_unsigned() ||
      value.get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument(std::string("\"") + field + "\" must be an unsigned 32-bit id");
  }
  return value.get<std::uint32_t>();
}

std::vector<std::uint32_t> IdsOf(const json& object, const char* field) {
  const json& list = object.at(field);
  if (!list.is_array()) {
    throw std::invalid_argument(std::string("\"") + field + "\" must be a list");
  }
  std::vector<std::uint32_t> ids;
  for (const json& value : list) {
    if (!value.is_number_unsigned() ||
        value.get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max()) {
      throw std::invalid_argument(std::string("\"") + field + "\" must hold unsigned 32-bit ids");
    }
    ids.push_back(value.get<std::uint32_t>());
  }
  return ids;
}

const json& ListOf(const json& object, const char* field) {
  const json& list = object.at(field);
  if (!list.is_array()) {
    throw std::invalid_argument(std::string("\"") + field + "\" must be a list");
  }
  return list;
}

ClientRequest ParseOp(const json& message) {
  if (!message.is_object()) return ParseError{"a message must be a JSON object"};
  const auto op_field = message.find("op");
  if (op_field == message.end() || !op_field->is_string()) {
    return ParseError{"a message must have a string \"op\""};
  }
  const std::string op = op_field->get<std::string>();
  if (op == "subscribe") {
    Subscribe subscribe;
    for (const json& s : ListOf(message, "subscriptions")) {
      subscribe.subscriptions.push_back({IdOf(s, "id"), IdOf(s, "channelId")});
    }
    return subscribe;
  }
  if (op == "unsubscribe") return Unsubscribe{IdsOf(message, "subscriptionIds")};
  if (op == "advertise") {
    ClientAdvertise advertise;
    for (const json& c : ListOf(message, "channels")) {
      advertise.channels.push_back({IdOf(c, "id"), c.at("topic").get<std::string>(),
                                    c.at("encoding").get<std::string>(),
                                    c.value("schemaName", std::string())});
    }
    return advertise;
  }
  if (op == "unadvertise") return ClientUnadvertise{IdsOf(message, "channelIds")};
  return Unsupported{op};
}

}  // namespace

std::string ServerInfoJson(std::string_view name, bool client_publish,
                           std::string_view session_id) {
  json capabilities = json::array();
  if (client_publish) capabilities.push_back("clientPublish");
  return json{{"op", "serverInfo"},
              {"name", name},
              {"capabilities", capabilities},
              {"supportedEncodings", client_publish ? json::array({"json"}) : json::array()},
              {"metadata", json::object()},
              {"sessionId", session_id}}
      .dump();
}

std::string AdvertiseJson(const std::vector<Channel>& channels) {
  json list = json::array();
  for (const Channel& c : channels) {
    list.push_back({{"id", c.id},
                    {"topic", c.topic},
                    {"encoding", c.encoding},
                    {"schemaName", c.schema_name},
                    {"schema", c.schema},
                    {"schemaEncoding", c.schema_encoding}});
  }
  return json{{"op", "advertise"}, {"channels", list}}.dump();
}

std::string StatusJson(StatusLevel level, std::string_view message) {
  return json{{"op", "status"}, {"level", static_cast<int>(level)}, {"message", message}}.dump(
      -1, ' ', false, json::error_handler_t::replace);
}

std::array<std::uint8_t, kMessageHeaderBytes> MessageDataHeader(std::uint32_t subscription,
                                                                std::uint64_t time_ns) {
  std::array<std::uint8_t, kMessageHeaderBytes> header{};
  header[0] = kMessageData;
  PutLittleEndian(&header[1], subscription, 4);
  PutLittleEndian(&header[5], time_ns, 8);
  return header;
}

ClientRequest ParseClientText(std::string_view text) {
  try {
    return ParseOp(json::parse(text));
  } catch (const std::exception& e) {  // json's parse, type and out_of_range errors; ours
    return ParseError{e.what()};
  }
}

std::variant<ClientMessage, ParseError> ParseClientBinary(std::span<const std::uint8_t> bytes) {
  constexpr std::size_t kHeader = 5;
  if (bytes.empty()) return ParseError{"an empty binary message"};
  if (bytes[0] != kMessageData) {
    return ParseError{"binary opcode " + std::to_string(bytes[0]) +
                      " is not offered (only 1, message data)"};
  }
  if (bytes.size() < kHeader) return ParseError{"a binary message shorter than its header"};
  std::uint32_t channel = 0;
  for (int i = 0; i < 4; ++i) channel |= static_cast<std::uint32_t>(bytes[1 + i]) << (8 * i);
  return ClientMessage{channel, bytes.subspan(kHeader)};
}

}  // namespace pirouette::view
