#pragma once

#include <filesystem>
#include <string>

namespace pirouette::testing {

// A fresh, empty folder for one test, removed (with all it holds) when the
// object goes: under the system's temporary folder, named after `prefix`,
// this process and the running GoogleTest test (so that tests run in
// parallel, by ctest or by several processes, never share one).
class TempDir {
 public:
  explicit TempDir(const std::string& prefix = "pirouette");
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // path() / relative, as a string.
  std::string operator/(const std::string& relative) const { return (path_ / relative).string(); }
  // Writes `text` to path() / relative (making its folders); returns that path.
  std::string Write(const std::string& relative, const std::string& text) const;
  // The bytes of path() / relative (empty when it cannot be read).
  std::string Read(const std::string& relative) const;

 private:
  std::filesystem::path path_;
};

}  // namespace pirouette::testing
