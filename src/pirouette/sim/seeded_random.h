#pragma once

#include <cstdint>
#include <random>

namespace pirouette::sim {

// Random numbers that are the same on every platform for a seed: the C++
// standard fixes std::mt19937_64's sequence, but not what its distributions
// (std::uniform_real_distribution and the rest) make of it, so the
// distributions here are written out. Used where a seed must give the same
// bytes everywhere (the world generator).
class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1), on 53 bits.
  double Unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Unit(); }
  // True with probability p.
  bool Chance(double p) { return Unit() < p; }
  // Uniform in [0, n), n >= 1, unbiased (by rejection).
  std::uint64_t Below(std::uint64_t n) {
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    std::uint64_t x = engine_();
    while (x >= limit) x = engine_();
    return x % n;
  }
  // Uniform whole number in [lo, hi], lo <= hi.
  std::int64_t Between(std::int64_t lo, std::int64_t hi) {
    return lo + static_cast<std::int64_t>(Below(static_cast<std::uint64_t>(hi - lo) + 1));
  }

 private:
  std::mt19937_64 engine_;
};

// A standard normal draw by std::normal_distribution: reproducible for a seed
// with one standard library (the simulated robots' noise), not across them as
// SeededRandom is.
inline double StandardNormal(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  return normal(rng);
}

// SplitMix64 (Steele, Lea & Flood 2014): a well-mixed 64-bit value of `x`,
// for seeds derived from a seed.
inline std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace pirouette::sim
