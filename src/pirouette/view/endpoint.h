#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace pirouette::view {

// Where the live view listens: `--view [HOST:]PORT`. The host defaults to
// the loopback interface: opening the view to a network is the user's
// explicit choice (a HOST of 0.0.0.0 or an address of a network interface).
struct Endpoint {
  std::string host = "127.0.0.1";
  std::uint16_t port = 0;  // 0: any free port
};

// Parses "PORT", "HOST:PORT" or "[IPv6]:PORT". Throws core::InputError naming
// `option` and what is wrong.
Endpoint ParseEndpoint(std::string_view text, const std::string& option = "--view");

// "http://HOST:PORT/" ("[v6]" bracketed).
std::string HttpUrl(const Endpoint& endpoint);

}  // namespace pirouette::view
