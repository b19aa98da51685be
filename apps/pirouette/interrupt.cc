#include "apps/pirouette/interrupt.h"

#include <csignal>

namespace pirouette::cli {
namespace {

std::atomic<bool> g_stop{false};

extern "C" void OnInterrupt(int signal) {
  g_stop.store(true);
  std::signal(signal, SIG_DFL);
}

}  // namespace

const std::atomic<bool>* StopOnInterrupt() {
  std::signal(SIGINT, OnInterrupt);
  std::signal(SIGTERM, OnInterrupt);
  return &g_stop;
}

}  // namespace pirouette::cli
