#include "pirouette/testing/fuzz_input.h"

#include <unistd.h>

#include <fstream>
#include <stdexcept>

namespace pirouette::testing {

std::vector<std::string_view> SplitFuzzInput(std::string_view input, std::size_t max_parts) {
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < max_parts) {
    const std::size_t at = input.find(kFuzzPartSeparator);
    if (at == std::string_view::npos) break;
    parts.push_back(input.substr(0, at));
    input.remove_prefix(at + kFuzzPartSeparator.size());
  }
  parts.push_back(input);
  return parts;
}

FuzzFolder::FuzzFolder()
    : path_(std::filesystem::temp_directory_path() /
            ("pirouette-fuzz-" + std::to_string(::getpid()))) {
  Reset();
}

FuzzFolder::~FuzzFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

void FuzzFolder::Reset() const {
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

std::string FuzzFolder::Write(const std::string& relative, std::string_view bytes) const {
  const std::filesystem::path file = path_ / relative;
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + file.string());
  return file.string();
}

}  // namespace pirouette::testing
