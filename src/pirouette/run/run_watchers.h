#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "pirouette/run/live_view_publisher.h"
#include "pirouette/run/ros2_run_publisher.h"
#include "pirouette/run/run_watcher.h"

namespace pirouette::run {

// Every watcher a run was asked for, and the live view among them.
struct RunWatchers {
  std::vector<std::unique_ptr<RunWatcher>> all;
  LiveViewPublisher* view = nullptr;  // owned by `all`; none without --view

  // Throws robot::ros2::DdsError or view::ViewError when one cannot start.
  RunWatchers(const std::optional<Ros2PublishOptions>& ros2,
              const std::optional<LiveViewOptions>& live_view) {
    if (live_view) {
      auto v = std::make_unique<LiveViewPublisher>(*live_view);
      view = v.get();
      all.push_back(std::move(v));
    }
    if (ros2) all.push_back(std::make_unique<Ros2RunPublisher>(*ros2));
  }

  void Watch(ExplorationObserver& observer) const { WatchWith(observer, all); }

  // The end to every watcher, then the live view's linger.
  void Finish(const mapping::TrinaryMap& map, const ExplorationResult& result,
              const std::atomic<bool>* stop_requested) const {
    for (const auto& watcher : all) watcher->PublishFinal(map, result);
    if (view != nullptr) view->Linger(stop_requested);
  }
};

}  // namespace pirouette::run
