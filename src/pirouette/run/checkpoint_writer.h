#pragma once

#include <condition_variable>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>

#include "pirouette/mapping/trinary_map.h"
#include "pirouette/run/exploration_result.h"

namespace pirouette::run {

// What the checkpoints of a run cost, for run.json.
struct CheckpointCost {
  int taken = 0;           // stops checkpointed (snapshots handed to the writer)
  int written = 0;         // checkpoints written (a newer one replaces one not yet written)
  double prepare_s = 0.0;  // the run's own time: cropping the map, the run.json, in all
  double write_s = 0.0;    // the writer thread's time: encoding, writing, fsync, renaming
  double max_write_s = 0.0;
};

// Makes a run crash-safe: after every stop (a snapshot with frames the last
// checkpoint did not hold: a pirouette, a look before a move, a look after
// contact) it rewrites OUT/map.pgm, OUT/map.yaml and OUT/run.json, each
// atomically (io::WriteFileAtomically: written aside, fsync'ed, renamed), so
// that a run killed at any moment (SIGKILL, a power cut) leaves the map up to
// its last stop, whole, and a run.json that says `status: running`. The
// image is renamed into place before the yaml that describes it, so the two
// disagree only if the process dies between the two renames (microseconds).
//
// The files are written by a thread of the writer's own, so the robot does
// not wait for the disk (an fsync takes milliseconds); the run's thread only
// crops the map and makes run.json. A checkpoint taken while the one before
// is still being written replaces it (the newest stop wins, the queue is one
// deep). Finish() before the run writes its final outputs, so that no
// checkpoint can overwrite them.
//
// `run_base` holds the run.json fields known before the run (format, world,
// seed, planner, ...); each checkpoint adds its progress to it.
class CheckpointWriter {
 public:
  CheckpointWriter(std::string out_dir, nlohmann::json run_base);
  ~CheckpointWriter();
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  // Takes a checkpoint when the snapshot holds frames the last one did not.
  void Publish(const RunSnapshot& snapshot);
  // Writes what is pending and stops the thread; later Publish calls do
  // nothing. Returns the first write error (empty: none): a checkpoint that
  // cannot be written stops checkpointing, not the run.
  std::string Finish();

  // Valid after Finish().
  const CheckpointCost& cost() const { return cost_; }

 private:
  struct Pending {
    mapping::TrinaryMap map;
    std::string run_json;
  };
  void WriteLoop();

  std::string out_dir_;
  nlohmann::json run_base_;
  int frames_taken_ = 0;
  CheckpointCost cost_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Pending> pending_;  // guarded by mutex_
  bool finishing_ = false;          // guarded by mutex_
  std::string error_;               // guarded by mutex_
  std::thread thread_;              // last: started once the rest is built
};

// The checkpoint's run.json: `run_base` with status "running" and the
// snapshot's progress (stops, moves, pirouettes, frames, path length, known
// area, elapsed time, the robot's pose in the map).
nlohmann::json CheckpointRunJson(const nlohmann::json& run_base, const RunSnapshot& snapshot);

}  // namespace pirouette::run
