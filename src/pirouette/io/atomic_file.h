#pragma once

#include <string>
#include <string_view>

namespace pirouette::io {

// Writes `bytes` to `path` atomically (SPEC.md): to a temporary file in the
// same folder, flushed, then renamed over `path`, so that a run that dies
// never leaves a half-written file. Throws std::runtime_error naming the path.
void WriteFileAtomically(const std::string& path, std::string_view bytes);

}  // namespace pirouette::io
