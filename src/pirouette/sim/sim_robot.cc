#include "pirouette/sim/sim_robot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "pirouette/core/geometry2.h"

namespace pirouette::sim {
namespace {

using core::DistanceToSegment;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The simulated robot's speeds (for the frames' time stamps only).
constexpr double kDriveSpeed = 0.1;                    // metres a second
constexpr double kTurnSpeed = std::numbers::pi / 2.0;  // radians a second (90°/s)
constexpr double kCaptureTime = 0.05;                  // seconds a frame

// How far the disc may overlap something before a move counts as blocked.
// The robot then stops where it first touched (overlap 0), so a robot in
// contact lies this far outside the blocking set: it can drive away from the
// contact or along it, without rounding errors deciding.
constexpr double kOverlapTolerance = 1e-9;

// A closed interval of the path parameter s (metres along the move);
// empty when lo > hi.
struct Interval {
  double lo = -kInfinity;
  double hi = kInfinity;
  bool empty() const { return lo > hi; }
};

constexpr Interval kEmpty{kInfinity, -kInfinity};

Interval Intersect(const Interval& a, const Interval& b) {
  return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

// {s : lo <= value0 + s·rate <= hi}.
Interval Slab(double value0, double rate, double lo, double hi) {
  if (rate == 0.0) return value0 >= lo && value0 <= hi ? Interval{} : kEmpty;
  const double s0 = (lo - value0) / rate;
  const double s1 = (hi - value0) / rate;
  return {std::min(s0, s1), std::max(s0, s1)};
}

// The line origin + s·u (u unit) inside the closed disc (centre, rho).
Interval LineInDisc(const Eigen::Vector2d& origin, const Eigen::Vector2d& u,
                    const Eigen::Vector2d& centre, double rho) {
  if (rho < 0.0) return kEmpty;
  const Eigen::Vector2d f = origin - centre;
  const double b = f.dot(u);
  const double discriminant = b * b - (f.squaredNorm() - rho * rho);
  if (discriminant < 0.0) return kEmpty;
  const double root = std::sqrt(discriminant);
  return {-b - root, -b + root};
}

// The line inside the capsule of radius rho around the segment ab: the union
// of the discs at its ends and the rectangle along it, which is convex, so
// the line meets it in one interval.
Interval LineInCapsule(const Eigen::Vector2d& origin, const Eigen::Vector2d& u,
                       const Eigen::Vector2d& a, const Eigen::Vector2d& b, double rho) {
  if (rho < 0.0) return kEmpty;
  Interval result = kEmpty;
  const auto unite = [&result](const Interval& part) {
    if (part.empty()) return;
    result = {std::min(result.lo, part.lo), std::max(result.hi, part.hi)};
  };
  unite(LineInDisc(origin, u, a, rho));
  unite(LineInDisc(origin, u, b, rho));
  const Eigen::Vector2d edge = b - a;
  const double length = edge.norm();
  if (length > 0.0) {
    const Eigen::Vector2d along = edge / length;
    const Eigen::Vector2d normal(-along.y(), along.x());
    const Eigen::Vector2d offset = origin - a;
    unite(Intersect(Slab(offset.dot(along), u.dot(along), 0.0, length),
                    Slab(offset.dot(normal), u.dot(normal), -rho, rho)));
  }
  return result;
}

// What the robot's disc must not overlap, cut into convex pieces: for each
// polygon edge, the capsule of radius (radius - depth) around it holds the
// centres where the disc overlaps the edge by at least `depth`; for each
// circle, the disc of radius (R + radius - depth); for each side of the
// floor, the half plane beyond the line (radius - depth) inside it. A
// polygon's interior cannot be reached without crossing the capsules around
// its edges, so these pieces catch every first contact. Along the line
// origin + s·u each piece is one interval of s.
//
// The result of a cast: where the move is blocked, and where it stops.
struct ContactResult {
  double touch = kInfinity;    // where the disc first touches (overlap 0) the blocking piece
  double blocked = kInfinity;  // where the overlap first exceeds kOverlapTolerance
};

// Takes one piece into account: `deep` is where the disc overlaps it by more
// than kOverlapTolerance, `touching` where it touches it at all, `deepening`
// whether the overlap grows as the robot starts to move.
void Consider(const Interval& deep, const Interval& touching, bool deepening,
              ContactResult& result) {
  if (deep.empty() || deep.hi < 0.0) return;
  double blocked = deep.lo;
  if (deep.lo < 0.0) {
    // Already overlapping more than the tolerance (a bad start): blocked only
    // when the move makes it worse.
    if (!deepening) return;
    blocked = 0.0;
  }
  if (blocked < result.blocked) {
    result.blocked = blocked;
    result.touch = std::clamp(touching.empty() ? blocked : touching.lo, 0.0, blocked);
  }
}

// Where a disc of `radius` at `origin` driving along u (unit) first overlaps
// an obstacle, a wall or the floor's outside by more than kOverlapTolerance,
// and where it touched it first. Exact for polygons, circles and the floor.
ContactResult CastDisc(const World& world, const Eigen::Vector2d& origin, const Eigen::Vector2d& u,
                       double radius) {
  ContactResult result;
  const double deep_radius = radius - kOverlapTolerance;
  for (const Solid& solid : world.solids()) {
    if (solid.circle) {
      const Eigen::Vector2d& c = solid.circle->centre;
      const double r = solid.circle->radius;
      Consider(LineInDisc(origin, u, c, r + deep_radius), LineInDisc(origin, u, c, r + radius),
               u.dot(origin - c) < 0.0, result);
      continue;
    }
    const std::vector<Eigen::Vector2d>& polygon = solid.footprint;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Eigen::Vector2d& a = polygon[i];
      const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
      const Interval deep = LineInCapsule(origin, u, a, b, deep_radius);
      if (deep.empty() || deep.hi < 0.0) continue;
      // Deepening: moving toward the nearest point of the edge.
      const Eigen::Vector2d ab = b - a;
      const double t = ab.squaredNorm() > 0.0
                           ? std::clamp((origin - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0)
                           : 0.0;
      const bool deepening =
          u.dot(origin - (a + t * ab)) < 0.0 || DistanceToSegment(origin, a, b) == 0.0;
      Consider(deep, LineInCapsule(origin, u, a, b, radius), deepening, result);
    }
  }
  // The floor's sides: the disc must keep within [0, size] on each axis.
  const Eigen::Vector2d& size = world.floor().size;
  for (int axis = 0; axis < 2; ++axis) {
    const double p = origin[axis];
    const double v = u[axis];
    // Overlap with the low side: radius - p; with the high side: radius - (size - p).
    Consider(Slab(p, v, -kInfinity, deep_radius), Slab(p, v, -kInfinity, radius), v < 0.0, result);
    Consider(Slab(p, v, size[axis] - deep_radius, kInfinity),
             Slab(p, v, size[axis] - radius, kInfinity), v > 0.0, result);
  }
  return result;
}

double StandardNormal(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  return normal(rng);
}

}  // namespace

SimRobot::SimRobot(const World& world, std::uint64_t seed, View view)
    : SimRobot(world, seed, std::move(view), world.robot().odometry_noise) {}

SimRobot::SimRobot(const World& world, std::uint64_t seed, View view,
                   const core::OdometryNoise& noise)
    : world_(world),
      noise_(noise),
      view_(std::move(view)),
      rng_(seed),
      world_T_robot_(world.robot().start),
      // The odometry frame is the world frame at the start: odometry and
      // truth agree until the robot first moves.
      odom_T_robot_(world.robot().start) {}

// One standard normal is drawn per move whatever the noise, so that the
// stream of draws, and so the trajectory for a seed, does not depend on it.
core::MoveOutcome SimRobot::Execute(const core::Move& move) {
  core::MoveOutcome outcome;
  outcome.requested = move;
  if (move.kind == core::Move::Kind::kTurn) {
    const double epsilon = noise_.rotation_bias + noise_.rotation * StandardNormal(rng_);
    const double true_angle = move.amount * (1.0 + epsilon);
    world_T_robot_ =
        core::Pose2(world_T_robot_.x(), world_T_robot_.y(), world_T_robot_.heading() + true_angle);
    odom_T_robot_ =
        core::Pose2(odom_T_robot_.x(), odom_T_robot_.y(), odom_T_robot_.heading() + move.amount);
    outcome.achieved = move.amount;
    time_s_ += std::abs(true_angle) / kTurnSpeed;
  } else {
    const double epsilon = noise_.translation_bias + noise_.translation * StandardNormal(rng_);
    const double scale = 1.0 + epsilon;  // true distance per encoder distance
    const double true_signed = move.amount * scale;
    const Eigen::Vector2d u = (true_signed < 0.0 ? -1.0 : 1.0) * world_T_robot_.Direction();
    const double wanted = std::abs(true_signed);
    double travelled = wanted;
    if (wanted > 0.0) {
      const ContactResult contact =
          CastDisc(world_, world_T_robot_.translation(), u, world_.robot().radius);
      if (contact.blocked <= wanted) {
        travelled = std::min(contact.touch, wanted);
        outcome.stopped_at_contact = true;
      }
    }
    const Eigen::Vector2d p = world_T_robot_.translation() + travelled * u;
    world_T_robot_ = core::Pose2(p.x(), p.y(), world_T_robot_.heading());
    // What the encoders measure: the true distance over the scale, in the
    // sign of the command.
    const double measured = (move.amount < 0.0 ? -1.0 : 1.0) * travelled / std::abs(scale);
    outcome.achieved = outcome.stopped_at_contact ? measured : move.amount;
    odom_T_robot_ = odom_T_robot_ * core::Pose2(outcome.achieved, 0.0, 0.0);
    time_s_ += travelled / kDriveSpeed;
  }
  outcome.odometry = odom_T_robot_;
  return outcome;
}

// The frame is stamped at the moment it is taken; taking it lasts kCaptureTime.
// A null view gives empty images.
robot::Frame SimRobot::Capture() {
  robot::Frame frame;
  if (view_) frame.image = view_(world_T_robot_);
  frame.odometry = odom_T_robot_;
  frame.time_s = time_s_;
  time_s_ += kCaptureTime;
  return frame;
}

}  // namespace pirouette::sim
