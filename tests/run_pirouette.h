#pragma once

// Runs the pirouette binary as a user would, for the command-line tests.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace pirouette::testing {

struct RunResult {
  int exit_code = -1;
  std::string stdout_only;
  std::string stderr_only;

  // Standard output, then standard error.
  std::string output() const { return stdout_only + stderr_only; }
};

// Runs `PIROUETTE_BINARY args` through the shell (`args` quoted as needed)
// and collects its exit code and both streams.
inline RunResult RunPirouette(const std::string& args) {
  namespace fs = std::filesystem;
  static int calls = 0;
  const fs::path err =
      fs::temp_directory_path() /
      ("pirouette_test_stderr_" + std::to_string(::getpid()) + "_" + std::to_string(calls++));
  const std::string command = std::string(PIROUETTE_BINARY) + " " + args + " 2>" + err.string();
  RunResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) {
    result.stdout_only.append(buffer.data(), n);
  }
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err);
  result.stderr_only.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  fs::remove(err);
  return result;
}

}  // namespace pirouette::testing
