#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace pirouette::core {

// Bad input from outside (a file, a command-line value): the edge turns it
// into a message and exit code 2 (SPEC.md). `line` is 1-based; 0 when the
// error is not tied to a line (the file is missing, say).
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string field, const std::string& problem)
      : std::runtime_error(Format(file, line, field, problem)),
        file_(std::move(file)),
        line_(line),
        field_(std::move(field)) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }

 private:
  static std::string Format(const std::string& file, int line, const std::string& field,
                            const std::string& problem) {
    std::string out = file;
    if (line > 0) out += ":" + std::to_string(line);
    if (!out.empty()) out += ": ";
    if (!field.empty()) out += "field '" + field + "': ";
    out += problem;
    return out;
  }

  std::string file_;
  int line_;
  std::string field_;
};

}  // namespace pirouette::core
