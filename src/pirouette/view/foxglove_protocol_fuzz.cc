// Fuzzes what a live-view client sends over the WebSocket (the Foxglove
// protocol): the input's first byte picks a text frame (even) or a binary
// one (odd), the rest is the frame. The parsers answer garbage with a
// ParseError, never an exception.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <variant>

#include "pirouette/testing/fuzz_input.h"
#include "pirouette/view/foxglove_protocol.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::span<const std::uint8_t> frame(data + 1, size - 1);
  if (data[0] % 2 == 0) {
    const pirouette::view::ClientRequest request =
        pirouette::view::ParseClientText(pirouette::testing::FuzzText(frame.data(), frame.size()));
    if (request.valueless_by_exception()) std::abort();
  } else {
    const auto message = pirouette::view::ParseClientBinary(frame);
    if (const auto* m = std::get_if<pirouette::view::ClientMessage>(&message)) {
      // The payload is a view into the frame, after its opcode and channel.
      if (m->payload.data() < frame.data() ||
          m->payload.data() + m->payload.size() > frame.data() + frame.size()) {
        std::abort();
      }
    }
  }
  return 0;
}
