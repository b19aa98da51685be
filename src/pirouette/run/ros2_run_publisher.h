#pragma once

#include <memory>
#include <string>

#include "pirouette/mapping/trinary_map.h"
#include "pirouette/robot/ros2/dds_participant.h"
#include "pirouette/run/exploration_result.h"
#include "pirouette/run/run_watcher.h"

namespace pirouette::run {

// Where a run is published over DDS.
struct Ros2PublishOptions {
  int domain_id = 0;                // ROS_DOMAIN_ID
  robot::ros2::DdsNetwork network;  // loopback unless told
  std::string ros_namespace;        // topics' namespace ("" none)
};

// Publishes a run to ROS 2 (SPEC.md, "ROS 2 over DDS"), as RViz2 and
// `ros2 topic echo` see it: after every snapshot the map (when it changed:
// nav_msgs/OccupancyGrid in frame `map`, 0 free, 100 occupied, -1 unknown by
// the map_server thresholds, the part seen with its margin as map.pgm has it),
// `tf` (map → odom), `pirouette/path` and `pirouette/plan` (nav_msgs/Path),
// `pirouette/floor` (the last frame with its floor drawn, bgr8) and
// `pirouette/status` (std_msgs/String, StatusJson). The messages are
// run_messages.h's. Not thread-safe: call from the run's thread.
class Ros2RunPublisher : public RunWatcher {
 public:
  // Throws robot::ros2::DdsError when the participant or a writer cannot be made.
  explicit Ros2RunPublisher(const Ros2PublishOptions& options);
  ~Ros2RunPublisher() override;
  Ros2RunPublisher(const Ros2RunPublisher&) = delete;
  Ros2RunPublisher& operator=(const Ros2RunPublisher&) = delete;

  // Chains onto the observer's on_snapshot (keeping what was there).
  void Watch(ExplorationObserver& observer);

  void Publish(const RunSnapshot& snapshot) override;

  // The end of the run: the map as written (map.pgm's cells, byte for byte),
  // the path, and the final status with its reason; then waits up to
  // `linger_s` for matched reliable readers to acknowledge them.
  void PublishFinal(const mapping::TrinaryMap& map, const ExplorationResult& result,
                    double linger_s);
  void PublishFinal(const mapping::TrinaryMap& map, const ExplorationResult& result) override {
    PublishFinal(map, result, kLingerS);
  }
  static constexpr double kLingerS = 2.0;

 private:
  struct Writers;
  std::unique_ptr<robot::ros2::DdsParticipant> participant_;
  std::unique_ptr<Writers> writers_;
  int published_frames_ = -1;  // the snapshot's frames when the map was last sent
};

}  // namespace pirouette::run
