#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace pirouette::view {

// A file of the live view's web page (src/pirouette/view/web/), compiled
// into the program so that it needs nothing from outside, not even its own
// install folder.
struct WebAsset {
  std::string_view name;          // "index.html"
  std::string_view content_type;  // "text/html; charset=utf-8"
  std::span<const unsigned char> bytes;
};

// The asset a request's path names: "/" is index.html, "/app.js" app.js.
// Anything else (a folder, "..", a query's own path) is none: only the
// embedded files are ever served, never a file of the disk.
std::optional<WebAsset> FindWebAsset(std::string_view path);

}  // namespace pirouette::view
