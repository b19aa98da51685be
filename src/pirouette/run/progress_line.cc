#include "pirouette/run/progress_line.h"

#include <unistd.h>

#include <cstdio>

namespace pirouette::run {

ProgressLine::ProgressLine(bool quiet) : quiet_(quiet), tty_(isatty(STDERR_FILENO) != 0) {}

ProgressLine::~ProgressLine() {
  if (!quiet_ && tty_ && shown_) std::fputc('\n', stderr);
}

void ProgressLine::Show(double elapsed_s, const std::function<std::string()>& text) {
  if (quiet_) return;
  const double interval = tty_ ? 0.1 : 5.0;
  if (shown_ && elapsed_s - last_s_ < interval) return;
  last_s_ = elapsed_s;
  shown_ = true;
  const std::string line = text();
  if (tty_) {
    std::fprintf(stderr, "\r%s\033[K", line.c_str());
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  std::fflush(stderr);
}

}  // namespace pirouette::run
