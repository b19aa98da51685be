#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace pirouette::testing {

// The line that separates the files of a fuzz input that stands for several
// files (a world and its camera, a map's YAML and its image): the input is
// cut at each "\n--8<--\n", the parts in the order the target names them.
inline constexpr std::string_view kFuzzPartSeparator = "\n--8<--\n";

// The fuzzer's bytes as text.
inline std::string_view FuzzText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// `input` cut at kFuzzPartSeparator into at most `max_parts` parts (the last
// part keeps any further separators); always at least one part.
std::vector<std::string_view> SplitFuzzInput(std::string_view input, std::size_t max_parts);

// One folder for the fuzz process, under the system's temporary folder and
// named after the process: emptied by Reset before each input, removed at
// exit. Readers that take paths read the files written into it.
class FuzzFolder {
 public:
  FuzzFolder();
  ~FuzzFolder();
  FuzzFolder(const FuzzFolder&) = delete;
  FuzzFolder& operator=(const FuzzFolder&) = delete;

  // Removes everything the folder holds.
  void Reset() const;
  // Writes `bytes` to path() / relative (making its folders); returns that path.
  std::string Write(const std::string& relative, std::string_view bytes) const;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace pirouette::testing
