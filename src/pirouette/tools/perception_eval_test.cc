#include "pirouette/tools/perception_eval.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pirouette::tools {
namespace {

eval::WorldPerception OneWorld() {
  eval::WorldPerception w;
  w.world_path = "worlds/a \"quoted\" name.yaml";
  w.world_name = "a";
  w.camera_name = "yujin";
  w.max_range_m = 0.412345;
  w.frames = 12;
  w.seconds_per_frame = 0.0123456;
  w.true_hits = 5;
  w.silhouette_hits = 1;
  w.measured_hits = 4;
  w.measured_hits_off_obstacles = 1;
  w.comparison.confusion[0] = {3, 1, 0};  // truth hit: measured hit, clear, blind
  w.comparison.confusion[1] = {0, 4, 0};
  w.comparison.confusion[2] = {0, 0, 2};
  w.comparison.range_errors_m = {0.001, -0.002, 0.0031234};
  return w;
}

TEST(PerceptionEvalJsonTest, IsOneObjectWithTheFiguresRounded) {
  eval::PerceptionEvalRequest request;
  request.method = vision::MaskSource::kTruth;
  request.poses = 1;
  const std::vector<eval::WorldPerception> worlds = {OneWorld(), OneWorld()};
  const std::string text = PerceptionEvalJson(request, worlds);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
  EXPECT_EQ(json.at("method"), "truth");
  EXPECT_EQ(json.at("poses_per_world"), 1);
  EXPECT_EQ(json.at("seed"), 1);
  ASSERT_EQ(json.at("worlds").size(), 2u);
  const nlohmann::ordered_json& w = json.at("worlds")[0];
  EXPECT_EQ(w.at("world"), "worlds/a \"quoted\" name.yaml");
  EXPECT_EQ(w.at("max_range_m"), 0.4123);
  EXPECT_EQ(w.at("seconds_per_frame"), 0.0123);
  EXPECT_EQ(w.at("true_hits_at_silhouettes"), 1);
  EXPECT_EQ(w.at("measured_hits"), 4);
  EXPECT_EQ(w.at("measured_hits_off_obstacles"), 1);
  EXPECT_EQ(w.at("columns"), 10);
  const nlohmann::ordered_json& error = w.at("range_error_m");
  EXPECT_EQ(error.at("compared"), 3);
  EXPECT_EQ(error.at("median"), 0.002);
  EXPECT_EQ(error.at("max"), 0.00312);
  EXPECT_EQ(error.at("median_signed"), 0.001);
  EXPECT_EQ(w.at("wrong_class_rate"), 0.1);
  EXPECT_EQ(w.at("confusion_truth_to_measured").at("hit").at("clear"), 1);
  EXPECT_EQ(w.at("confusion_truth_to_measured").at("blind").at("blind"), 2);
  // The keys in the report's order.
  std::vector<std::string> keys;
  for (const auto& item : w.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{
                      "world", "name", "camera", "max_range_m", "frames", "seconds_per_frame",
                      "true_hits", "true_hits_at_silhouettes", "measured_hits",
                      "measured_hits_off_obstacles", "columns", "range_error_m", "wrong_class_rate",
                      "confusion_truth_to_measured"}));
  // Over all worlds.
  EXPECT_EQ(json.at("all").at("frames"), 24);
  EXPECT_EQ(json.at("all").at("columns"), 20);
  EXPECT_EQ(json.at("all").at("range_error_m").at("compared"), 6);
}

}  // namespace
}  // namespace pirouette::tools
