#include "pirouette/tools/perception_eval.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>

#include "pirouette/tools/json_output.h"

namespace pirouette::tools {
namespace {

constexpr core::ReadingKind kKinds[] = {core::ReadingKind::kHit, core::ReadingKind::kClear,
                                        core::ReadingKind::kBlind};

// The q-quantile (0..1) by the nearest rank; 0 for none.
double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const auto rank =
      static_cast<std::size_t>(std::clamp(std::ceil(q * static_cast<double>(values.size())) - 1.0,
                                          0.0, static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

// The comparison's fields, added to `out`.
void AddComparison(const eval::ProfileComparison& c, nlohmann::ordered_json& out) {
  out["columns"] = c.columns();
  std::vector<double> absolute;
  absolute.reserve(c.range_errors_m.size());
  for (const double e : c.range_errors_m) absolute.push_back(std::abs(e));
  out["range_error_m"] = {{"compared", absolute.size()},
                          {"median", RoundTo(Quantile(absolute, 0.5), 5)},
                          {"p95", RoundTo(Quantile(absolute, 0.95), 5)},
                          {"max", RoundTo(Quantile(absolute, 1.0), 5)},
                          {"median_signed", RoundTo(Quantile(c.range_errors_m, 0.5), 5)}};
  out["wrong_class_rate"] = RoundTo(c.WrongClassRate(), 5);
  nlohmann::ordered_json confusion;
  for (const core::ReadingKind truth : kKinds) {
    const auto& row = c.confusion[static_cast<std::size_t>(truth)];
    nlohmann::ordered_json measured;
    for (const core::ReadingKind kind : kKinds) {
      measured[ReadingKindName(kind)] = row[static_cast<std::size_t>(kind)];
    }
    confusion[ReadingKindName(truth)] = std::move(measured);
  }
  out["confusion_truth_to_measured"] = std::move(confusion);
}

}  // namespace

std::string PerceptionEvalJson(const eval::PerceptionEvalRequest& request,
                               const std::vector<eval::WorldPerception>& worlds) {
  nlohmann::ordered_json json;
  json["method"] = std::string(vision::MaskSourceName(request.method));
  json["poses_per_world"] = request.poses;
  json["seed"] = request.seed;
  nlohmann::ordered_json per_world = nlohmann::ordered_json::array();
  eval::ProfileComparison all;
  int frames = 0;
  for (const eval::WorldPerception& w : worlds) {
    nlohmann::ordered_json world;
    world["world"] = w.world_path;
    world["name"] = w.world_name;
    world["camera"] = w.camera_name;
    world["max_range_m"] = RoundTo(w.max_range_m, 4);
    world["frames"] = w.frames;
    world["seconds_per_frame"] = RoundTo(w.seconds_per_frame, 4);
    world["true_hits"] = w.true_hits;
    world["true_hits_at_silhouettes"] = w.silhouette_hits;
    world["measured_hits"] = w.measured_hits;
    world["measured_hits_off_obstacles"] = w.measured_hits_off_obstacles;
    AddComparison(w.comparison, world);
    per_world.push_back(std::move(world));
    all.Add(w.comparison);
    frames += w.frames;
  }
  json["worlds"] = std::move(per_world);
  nlohmann::ordered_json overall;
  overall["frames"] = frames;
  AddComparison(all, overall);
  json["all"] = std::move(overall);
  return JsonText(json, 2);
}

}  // namespace pirouette::tools
