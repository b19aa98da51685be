#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "pirouette/mapping/trinary_map.h"
#include "pirouette/run/exploration_result.h"

namespace pirouette::run {

// Something that shows a run while it goes (ROS 2 over DDS, the live view):
// a snapshot after every stop, move and plan, then the end.
class RunWatcher {
 public:
  virtual ~RunWatcher() = default;
  virtual void Publish(const RunSnapshot& snapshot) = 0;
  // The map as written (map.pgm's cells) and the run's end.
  virtual void PublishFinal(const mapping::TrinaryMap& map, const ExplorationResult& result) = 0;
};

// Chains every watcher onto the observer's on_snapshot (keeping what was
// there); the watchers must outlive the observer's use.
inline void WatchWith(ExplorationObserver& observer,
                      const std::vector<std::unique_ptr<RunWatcher>>& watchers) {
  if (watchers.empty()) return;
  auto before = observer.on_snapshot;
  observer.on_snapshot = [before, &watchers](const RunSnapshot& snapshot) {
    if (before) before(snapshot);
    for (const auto& watcher : watchers) watcher->Publish(snapshot);
  };
}

}  // namespace pirouette::run
