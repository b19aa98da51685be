#pragma once

#include <functional>
#include <string>

namespace pirouette::run {

// A live progress line on standard error: rewritten in place on a terminal
// (at most ten times a second), a line every few seconds otherwise (a log
// file); nothing when quiet. The text is made only when it is shown.
class ProgressLine {
 public:
  explicit ProgressLine(bool quiet);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void Show(double elapsed_s, const std::function<std::string()>& text);

 private:
  bool quiet_;
  bool tty_;
  bool shown_ = false;
  double last_s_ = 0.0;
};

}  // namespace pirouette::run
