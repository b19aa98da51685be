#pragma once

#include <chrono>

namespace pirouette::run {

// A steady-clock duration in seconds.
inline double Seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

// Adds the wall time from construction to destruction, in seconds, to a
// counter: where the time of a run goes, stage by stage.
class StageTimer {
 public:
  explicit StageTimer(double& total_s) : total_s_(total_s), start_(Clock::now()) {}
  ~StageTimer() { total_s_ += Seconds(Clock::now() - start_); }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  using Clock = std::chrono::steady_clock;
  double& total_s_;
  Clock::time_point start_;
};

}  // namespace pirouette::run
