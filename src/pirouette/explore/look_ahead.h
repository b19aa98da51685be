#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "pirouette/core/obstacle_profile.h"

namespace pirouette::explore {

struct LookAheadOptions {
  double radius_m = 0.0;     // the robot's disc
  double near_m = 0.0;       // the camera sees no floor nearer than this (under it)
  double max_range_m = 0.0;  // readings are trusted out to this range
  // The map's cell: the planner keeps cell centres a radius from occupied
  // cell centres, so a reading nearer the swept disc's rim than this is the
  // map's business, not the look's (else look and plan disagree forever).
  double cell_m = 0.0;
};

enum class LookVerdict {
  kClear,    // the floor is free for the whole move, as far as the camera sees
  kBlocked,  // an obstacle's base is in the way
  kBlind,    // something fills the view in the way: its base is under the camera
};

// The paper's "look before moving" (Taylor, Geva & Boles 2005, §4): before a
// straight move, the robot faces it and takes a frame; the move is made only
// when that frame shows the floor free for the whole swept corridor (the
// robot's disc along the move: points within radius_m - cell_m of the
// segment). The floor nearer than near_m is not seen
// then: the planner only sends the robot over floor the map knows is free.
class LookAhead {
 public:
  explicit LookAhead(const LookAheadOptions& options) : options_(options) {}

  const LookAheadOptions& options() const { return options_; }

  // The longest forward move one frame can vouch for: its swept disc must end
  // within the max range.
  double LongestCheckedMove() const;
  // The half width of the swept corridor the look checks: points within
  // radius_m - cell_m of the move's segment (the planner keeps cell centres
  // a radius from occupied ones; the rim's cell is the map's business).
  double SweptHalfWidth() const { return options_.radius_m - options_.cell_m; }

  struct Finding {
    LookVerdict verdict = LookVerdict::kClear;
    // For kBlocked: the hits inside the swept corridor (the profile's feet
    // among them), robot frame.
    std::vector<Eigen::Vector2d> hits_robot;
    // How far forward the frame vouches for the move: where a kClear reading
    // short of the max range (the floor seen free to there, unresolved past
    // it) crosses the swept corridor, the disc may go until its front
    // reaches the nearest such point; infinity where none does.
    double seen_m = std::numeric_limits<double>::infinity();
  };
  // Judges a forward move of `distance_m` (> 0) from the frame's profile,
  // taken facing the move (readings in the robot frame), and says where the
  // way is blocked, and how far it is seen (Finding::seen_m: a move is
  // vouched for only that far).
  Finding Blocking(const core::ObstacleProfile& profile, double distance_m) const;

 private:
  LookAheadOptions options_;
};

}  // namespace pirouette::explore
