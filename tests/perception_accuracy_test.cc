// The segmenters' accuracy over every shipped world, in the simulator (issue
// 3, "Simulated frames"): a pirouette (12 frames) at each of 3 fixed poses a
// world (seed 1), each frame segmented by the paper's method or the default
// one, its obstacle profile against the ray-cast truth. The bounds are
// regression guards, looser than the goals (median ≤ 0.5 cm, p95 ≤
// 2 cm, wrong class ≤ 1%, for both methods) only in the wrong-class rate.
//
// Measured at the time of writing (release build; `pirouette perception-eval
// --method M --poses 3 --seed 1` with the five worlds gives the same figures):
//   default: median 0.5–1.0 mm and p95 2.2–3.7 mm in every world; wrong class
//            1.66% overall, most of it in the maze (6.8%): its first pirouette
//            starts facing a grey wall a few cm away, and the floor model
//            switches from the wall to the floor only when most of that
//            pirouette's reference regions agree (at the 5th frame).
//   paper:   median 0.8–1.2 mm and p95 2.9–3.7 mm in every world; wrong class
//            2.65% overall (apartment 5.8%, mostly hits read clear).
// The goal is 1% wrong class; these guards sit just above what is
// measured. Lower them as the segmenters improve.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pirouette/eval/perception_eval.h"

namespace pirouette::eval {
namespace {

struct Bounds {
  double median_m;
  double p95_m;
  double wrong_class_rate;  // over all worlds
};

// The q-quantile (0..1) by the nearest rank, as `perception-eval` reports it.
double Quantile(std::vector<double> values, double q) {
  const auto rank =
      static_cast<std::size_t>(std::clamp(std::ceil(q * static_cast<double>(values.size())) - 1.0,
                                          0.0, static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

void ExpectAccuracy(vision::MaskSource method, const Bounds& bounds) {
  eval::PerceptionEvalRequest request;
  for (const char* world : {"soccer_field", "cluttered_room", "maze", "two_rooms", "apartment"}) {
    request.world_paths.push_back(std::string(PIROUETTE_WORLDS_DIR) + "/" + world + ".yaml");
  }
  request.method = method;
  request.poses = 3;
  request.seed = 1;
  const std::vector<eval::WorldPerception> worlds = eval::EvaluatePerception(request);
  ASSERT_EQ(worlds.size(), 5u);
  eval::ProfileComparison all;
  std::string per_world;  // the wrong-class rates, for the failure message
  for (const WorldPerception& w : worlds) {
    per_world += " " + w.world_name + " " + std::to_string(w.comparison.WrongClassRate());
    EXPECT_EQ(w.frames, 36) << w.world_name;
    std::vector<double> errors;
    for (const double e : w.comparison.range_errors_m) errors.push_back(std::abs(e));
    ASSERT_GT(errors.size(), 1000u) << w.world_name;
    EXPECT_LE(Quantile(errors, 0.5), bounds.median_m) << w.world_name;
    EXPECT_LE(Quantile(errors, 0.95), bounds.p95_m) << w.world_name;
    all.Add(w.comparison);
  }
  EXPECT_LE(all.WrongClassRate(), bounds.wrong_class_rate) << "by world:" << per_world;
}

TEST(PerceptionAccuracyTest, DefaultMethodInEveryShippedWorld) {
  ExpectAccuracy(vision::MaskSource::kDefault,
                 {.median_m = 0.005, .p95_m = 0.02, .wrong_class_rate = 0.02});
}

TEST(PerceptionAccuracyTest, PaperMethodInEveryShippedWorld) {
  ExpectAccuracy(vision::MaskSource::kPaper,
                 {.median_m = 0.005, .p95_m = 0.02, .wrong_class_rate = 0.05});
}

}  // namespace
}  // namespace pirouette::eval
