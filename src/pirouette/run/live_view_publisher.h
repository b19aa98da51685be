#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>

#include "pirouette/run/exploration_options.h"
#include "pirouette/run/run_watcher.h"
#include "pirouette/view/endpoint.h"
#include "pirouette/view/live_server.h"

namespace pirouette::run {

struct LiveViewOptions {
  view::Endpoint endpoint;  // loopback unless told
  bool control = false;     // --view-control: pause, resume, stop, home
  // After the run: serve on this long for clients to take the end (sooner
  // when every client that came has gone). --view-linger.
  double linger_s = 0.0;
  std::string ros_namespace;  // the channels' topics: /NS/map
};

// Shows a run in the live view (SPEC.md, "Live view"): the channels of the
// ROS 2 table (`/map`, `/tf`, `/pirouette/path`, `/pirouette/plan`,
// `/pirouette/floor` as a JPEG CompressedImage, `/pirouette/status`) and
// `/pirouette/stops` (nav_msgs/Path: where the robot pirouetted), each the
// CDR bytes of run_messages.h's message (the bytes the DDS layer writes),
// with its ros2msg schema. Publish is called from the run's thread and never
// waits for a client (view::LiveServer).
class LiveViewPublisher : public RunWatcher {
 public:
  // Listens at once; throws view::ViewError when it cannot.
  explicit LiveViewPublisher(const LiveViewOptions& options);
  ~LiveViewPublisher() override;  // stops the server before the state its thread reads
  LiveViewPublisher(const LiveViewPublisher&) = delete;
  LiveViewPublisher& operator=(const LiveViewPublisher&) = delete;

  const view::Endpoint& endpoint() const { return server_->endpoint(); }
  // The flags the view's controls set (all false without --view-control).
  const RunControl& control() const { return control_; }

  void Publish(const RunSnapshot& snapshot) override;
  void PublishFinal(const mapping::TrinaryMap& map, const ExplorationResult& result) override;

  // Each channel by itself, for a view of something that is not a run (the
  // simulator sim-serve serves): a map, a picture on /pirouette/floor, a path,
  // a status JSON.
  void PublishMap(const mapping::TrinaryMap& map);
  void PublishPicture(const cv::Mat3b& bgr);
  void PublishPath(const std::vector<core::Pose2>& poses);
  void PublishStatus(const std::string& json) { SendStatus(json); }

  // Serves on after PublishFinal for up to the options' linger_s, ending
  // sooner when every client that connected has left or `stop_requested`
  // (Ctrl-C) is set; then waits briefly for clients to take what was sent.
  void Linger(const std::atomic<bool>* stop_requested) const;

  view::LiveServerStats Stats() const { return server_->Stats(); }

  // The channel ids.
  enum ChannelId : std::uint32_t { kMap = 1, kTf, kPath, kPlan, kFloor, kStatus, kStops };

 private:
  std::string OnControl(view::ControlCommand command);
  void SendStatus(const std::string& json);

  LiveViewOptions options_;
  RunControl control_;
  std::unique_ptr<view::LiveServer> server_;
  int published_frames_ = -1;  // the snapshot's frames when the map was last sent
  std::size_t published_stops_ = 0;
  mutable std::mutex status_mutex_;  // the last status's counts, for a pause's answer
  int stops_ = 0;
  double known_area_m2_ = 0.0;
  double elapsed_s_ = 0.0;
};

}  // namespace pirouette::run
