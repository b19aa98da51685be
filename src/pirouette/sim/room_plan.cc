#include "pirouette/sim/room_plan.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <optional>
#include <utility>

namespace pirouette::sim {
namespace {

// Tries at a split position before a room is split the other way or kept whole.
constexpr int kSplitTries = 20;

// An interval [lo, hi] along one side of a room.
struct Interval {
  Mm lo = 0;
  Mm hi = 0;
};

enum Side { kBottom = 0, kTop = 1, kLeft = 2, kRight = 3 };

// A room still to be split: its floor, the lines its walls' ends run to (the
// centre lines of the walls around it, or the floor's edges), and the doors
// on each of its sides.
struct Region {
  MmRect floor;
  MmRect anchors;
  std::array<std::vector<Interval>, 4> doors;
};

MmRect Transposed(const MmRect& r) { return {r.y0, r.x0, r.y1, r.x1}; }
MmSegment Transposed(const MmSegment& s) { return {s.y0, s.x0, s.y1, s.x1}; }

Region Transposed(const Region& r) {
  Region t{Transposed(r.floor), Transposed(r.anchors), {}};
  t.doors[kBottom] = r.doors[kLeft];
  t.doors[kTop] = r.doors[kRight];
  t.doors[kLeft] = r.doors[kBottom];
  t.doors[kRight] = r.doors[kTop];
  return t;
}

// What a split adds: the two halves, the wall's pieces, its door.
struct Split {
  Region low;
  Region high;
  std::vector<MmSegment> walls;
  MmRect doorway;
  Mm door_width = 0;
};

bool MeetsADoor(Mm lo, Mm hi, const std::vector<Interval>& doors) {
  return std::any_of(doors.begin(), doors.end(),
                     [&](const Interval& d) { return lo <= d.hi && d.lo <= hi; });
}

Mm DrawDoorWidth(SeededRandom& random, const RoomPlanOptions& o) {
  if (random.Chance(o.wide_door_chance)) return random.Between(o.door_max, o.wide_door_max);
  return random.Between(o.door_min, o.door_max);
}

// Splits `r` by a wall x = s across it, s drawn so that both halves keep
// min_room and the wall's ends miss the doors on the room's bottom and top.
std::optional<Split> SplitAcrossX(SeededRandom& random, const Region& r, const RoomPlanOptions& o) {
  const Mm half = o.thickness / 2;
  const Mm lo = r.floor.x0 + o.min_room + half;
  const Mm hi = r.floor.x1 - o.min_room - half;
  if (lo > hi) return std::nullopt;
  std::optional<Mm> s;
  for (int i = 0; i < kSplitTries && !s; ++i) {
    const Mm x = random.Between(lo, hi);
    const Mm a = x - half - o.jamb;
    const Mm b = x + half + o.jamb;
    if (!MeetsADoor(a, b, r.doors[kBottom]) && !MeetsADoor(a, b, r.doors[kTop])) s = x;
  }
  if (!s) return std::nullopt;
  const Mm width = DrawDoorWidth(random, o);
  const Mm d_lo = r.floor.y0 + o.door_margin;
  const Mm d_hi = r.floor.y1 - o.door_margin - width;
  if (d_lo > d_hi) return std::nullopt;
  const Mm d0 = random.Between(d_lo, d_hi);
  const Interval door{d0, d0 + width};

  Split split;
  split.walls.push_back({*s, r.anchors.y0, *s, door.lo});
  split.walls.push_back({*s, door.hi, *s, r.anchors.y1});
  split.doorway = {*s - half - o.approach, door.lo, *s + half + o.approach, door.hi};
  split.door_width = width;
  split.low = r;
  split.low.floor.x1 = *s - half;
  split.low.anchors.x1 = *s;
  split.low.doors[kRight] = {door};
  split.high = r;
  split.high.floor.x0 = *s + half;
  split.high.anchors.x0 = *s;
  split.high.doors[kLeft] = {door};
  return split;
}

// Splits `r` across its longer side (either when square), else across the other.
std::optional<Split> SplitRegion(SeededRandom& random, const Region& r, const RoomPlanOptions& o) {
  const Mm w = r.floor.x1 - r.floor.x0;
  const Mm h = r.floor.y1 - r.floor.y0;
  bool across_x = w > h || (w == h && random.Chance(0.5));
  for (int attempt = 0; attempt < 2; ++attempt, across_x = !across_x) {
    if (across_x) {
      if (auto split = SplitAcrossX(random, r, o)) return split;
      continue;
    }
    if (auto split = SplitAcrossX(random, Transposed(r), o)) {
      Split back{Transposed(split->low),
                 Transposed(split->high),
                 {},
                 Transposed(split->doorway),
                 split->door_width};
      for (const MmSegment& wall : split->walls) back.walls.push_back(Transposed(wall));
      return back;
    }
  }
  return std::nullopt;
}

Mm Area(const MmRect& r) { return (r.x1 - r.x0) * (r.y1 - r.y0); }

}  // namespace

RoomPlan DrawRoomPlan(SeededRandom& random, const RoomPlanOptions& options) {
  assert(options.thickness % 2 == 0);
  const MmRect floor{0, 0, options.width, options.height};
  std::vector<Region> open = {{floor, floor, {}}};
  RoomPlan plan;
  std::vector<Region> done;
  while (!open.empty() && static_cast<int>(open.size() + done.size()) < options.rooms) {
    // The largest room first, so that rooms come out of like sizes.
    const auto largest = std::max_element(
        open.begin(), open.end(),
        [](const auto& a, const auto& b) { return Area(a.floor) < Area(b.floor); });
    const Region region = *largest;
    open.erase(largest);
    std::optional<Split> split = SplitRegion(random, region, options);
    if (!split) {
      done.push_back(region);
      continue;
    }
    plan.walls.insert(plan.walls.end(), split->walls.begin(), split->walls.end());
    plan.doorways.push_back(split->doorway);
    plan.door_widths.push_back(split->door_width);
    open.push_back(std::move(split->low));
    open.push_back(std::move(split->high));
  }
  for (const Region& r : done) plan.rooms.push_back(r.floor);
  for (const Region& r : open) plan.rooms.push_back(r.floor);
  // A wall piece of no length (a door at the very end of a wall) is dropped.
  std::erase_if(plan.walls, [](const MmSegment& s) { return s.x0 == s.x1 && s.y0 == s.y1; });
  return plan;
}

}  // namespace pirouette::sim
