#include "pirouette/run/checkpoint_writer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <utility>

#include "pirouette/core/angle.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/map_file.h"
#include "pirouette/run/explore_job.h"

namespace pirouette::run {
namespace {

double Round(double v, double unit) { return std::round(v / unit) * unit; }

}  // namespace

nlohmann::json CheckpointRunJson(const nlohmann::json& run_base, const RunSnapshot& snapshot) {
  nlohmann::json run = run_base;
  run["status"] = "running";
  run["reason"] = "a checkpoint: the run had not ended when this was written";
  double path_m = 0.0;
  for (std::size_t i = 1; i < snapshot.path.size(); ++i) {
    path_m += (snapshot.path[i].translation() - snapshot.path[i - 1].translation()).norm();
  }
  run["stops"] = snapshot.stops.size();
  run["moves"] = snapshot.progress.moves;
  run["pirouettes"] = snapshot.progress.pirouettes;
  run["frames"] = snapshot.frames;
  run["path_length_m"] = Round(path_m, 1e-4);
  run["known_area_m2"] = Round(snapshot.progress.known_area_m2, 1e-4);
  run["wall_time_s"] = Round(snapshot.progress.elapsed_s, 1e-3);
  const core::Pose2& p = snapshot.map_T_robot;
  run["pose"] = nlohmann::json::array(
      {Round(p.x(), 1e-4), Round(p.y(), 1e-4), Round(core::RadToDeg(p.heading()), 0.01)});
  return run;
}

CheckpointWriter::CheckpointWriter(std::string out_dir, nlohmann::json run_base)
    : out_dir_(std::move(out_dir)),
      run_base_(std::move(run_base)),
      thread_([this] { WriteLoop(); }) {}

CheckpointWriter::~CheckpointWriter() { Finish(); }

void CheckpointWriter::Publish(const RunSnapshot& snapshot) {
  if (snapshot.frames <= frames_taken_) return;
  const auto start = std::chrono::steady_clock::now();
  Pending next{SeenPart(snapshot.grid).ToMapOfRecord(),
               CheckpointRunJson(run_base_, snapshot).dump(2) + "\n"};
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (finishing_ || !error_.empty()) return;
    pending_ = std::move(next);
  }
  wake_.notify_one();
  frames_taken_ = snapshot.frames;
  ++cost_.taken;
  cost_.prepare_s +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string CheckpointWriter::Finish() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    finishing_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
  return error_;
}

void CheckpointWriter::WriteLoop() {
  const std::filesystem::path out(out_dir_);
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return pending_.has_value() || finishing_; });
    if (!pending_) return;  // finishing, nothing left to write
    Pending job = std::move(*pending_);
    pending_.reset();
    lock.unlock();
    const auto start = std::chrono::steady_clock::now();
    std::string error;
    try {
      // map.pgm is renamed into place before map.yaml (io::WriteRosMap).
      io::WriteRosMap(job.map, (out / "map.yaml").string());
      io::WriteFileAtomically((out / "run.json").string(), job.run_json);
    } catch (const std::exception& e) {
      error = e.what();
    }
    const double took =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lock.lock();
    ++cost_.written;
    cost_.write_s += took;
    cost_.max_write_s = std::max(cost_.max_write_s, took);
    if (!error.empty()) {
      error_ = error;
      pending_.reset();
      return;
    }
  }
}

}  // namespace pirouette::run
