#include "pirouette/view/endpoint.h"

#include <charconv>

#include "pirouette/core/input_error.h"

namespace pirouette::view {

Endpoint ParseEndpoint(std::string_view text, const std::string& option) {
  const auto fail = [&](const std::string& problem) {
    throw core::InputError("", 0, option, "'" + std::string(text) + "': " + problem);
  };
  Endpoint endpoint;
  std::string_view port = text;
  const std::size_t colon = text.rfind(':');
  if (colon != std::string_view::npos) {
    std::string_view host = text.substr(0, colon);
    port = text.substr(colon + 1);
    if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
      host = host.substr(1, host.size() - 2);
    } else if (host.find(':') != std::string_view::npos) {
      fail("an IPv6 host goes in brackets: [::1]:PORT");
    }
    if (host.empty()) fail("the host before ':' is empty (give PORT alone for 127.0.0.1)");
    endpoint.host = std::string(host);
  }
  unsigned value = 0;
  const auto [end, error] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (port.empty() || error != std::errc() || end != port.data() + port.size() || value > 65535) {
    fail("the port must be a number from 0 to 65535");
  }
  endpoint.port = static_cast<std::uint16_t>(value);
  return endpoint;
}

std::string HttpUrl(const Endpoint& endpoint) {
  const bool v6 = endpoint.host.find(':') != std::string::npos;
  return "http://" + (v6 ? "[" + endpoint.host + "]" : endpoint.host) + ":" +
         std::to_string(endpoint.port) + "/";
}

}  // namespace pirouette::view
