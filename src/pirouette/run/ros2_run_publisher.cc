#include "pirouette/run/ros2_run_publisher.h"

#include <chrono>

#include "pirouette/robot/ros2/dds_writer.h"
#include "pirouette/robot/ros2/ros2_sample.h"
#include "pirouette/run/explore_job.h"
#include "pirouette/run/run_messages.h"

namespace pirouette::run {

namespace ros2 = robot::ros2;

struct Ros2RunPublisher::Writers {
  explicit Writers(const ros2::DdsParticipant& p)
      : map(p, "map", ros2::kMapQos),
        tf(p, "tf", ros2::kTfQos),
        path(p, "pirouette/path", ros2::kLatchedQos),
        plan(p, "pirouette/plan", ros2::kReliableQos),
        floor(p, "pirouette/floor", ros2::kImageWriterQos),
        status(p, "pirouette/status", ros2::kLatchedQos) {}

  ros2::DdsWriter<nav_msgs_msg_dds__OccupancyGrid_> map;
  ros2::DdsWriter<tf2_msgs_msg_dds__TFMessage_> tf;
  ros2::DdsWriter<nav_msgs_msg_dds__Path_> path;
  ros2::DdsWriter<nav_msgs_msg_dds__Path_> plan;
  ros2::DdsWriter<sensor_msgs_msg_dds__Image_> floor;
  ros2::DdsWriter<std_msgs_msg_dds__String_> status;
};

Ros2RunPublisher::Ros2RunPublisher(const Ros2PublishOptions& options)
    : participant_(std::make_unique<ros2::DdsParticipant>(options.domain_id, options.network,
                                                          options.ros_namespace)),
      writers_(std::make_unique<Writers>(*participant_)) {}

Ros2RunPublisher::~Ros2RunPublisher() = default;

void Ros2RunPublisher::Watch(ExplorationObserver& observer) {
  auto before = observer.on_snapshot;
  observer.on_snapshot = [this, before](const RunSnapshot& snapshot) {
    if (before) before(snapshot);
    Publish(snapshot);
  };
}

void Ros2RunPublisher::Publish(const RunSnapshot& snapshot) {
  const auto stamp = ros2::RosTime(std::chrono::system_clock::now());
  if (snapshot.frames != published_frames_) {
    published_frames_ = snapshot.frames;
    writers_->map.Write(*MapMessage(SeenPart(snapshot.grid).ToMapOfRecord(), stamp));
    if (!snapshot.bgr.empty()) {
      writers_->floor.Write(
          *FloorImageMessage(FloorPicture(snapshot.bgr, snapshot.floor_mask), stamp));
    }
  }
  writers_->tf.Write(*MapToOdomMessage(snapshot.map_T_odom, stamp));
  writers_->path.Write(*PathMessage(PathPoses(snapshot.path, snapshot.map_T_robot), stamp));
  writers_->plan.Write(*PathMessage(PlanPoses(snapshot.map_T_robot, snapshot.plan), stamp));
  writers_->status.Write(
      *StatusMessage(StatusJson("running", snapshot.progress.pirouettes,
                                snapshot.progress.known_area_m2, "", snapshot.progress.elapsed_s)));
}

void Ros2RunPublisher::PublishFinal(const mapping::TrinaryMap& map, const ExplorationResult& result,
                                    double linger_s) {
  const auto stamp = ros2::RosTime(std::chrono::system_clock::now());
  writers_->map.Write(*MapMessage(map, stamp));
  writers_->path.Write(*PathMessage(result.path, stamp));
  writers_->plan.Write(*PathMessage({}, stamp));
  writers_->status.Write(*StatusMessage(StatusJson(
      result.status, result.pirouettes, KnownAreaM2(map), result.reason, result.wall_time_s)));
  const auto linger = static_cast<dds_duration_t>(linger_s * 1e9);
  for (const dds_entity_t writer :
       {writers_->map.entity(), writers_->path.entity(), writers_->status.entity()}) {
    dds_wait_for_acks(writer, linger);  // a reader that does not answer is not waited for longer
  }
}

}  // namespace pirouette::run
