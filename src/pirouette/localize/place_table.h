#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pirouette/core/obstacle_profile.h"
#include "pirouette/localize/place_signature.h"

namespace pirouette::localize {

// One place of a table: where a pirouette was made, the heading the robot
// had at its start, and what it saw (the view in the robot's frame then).
struct PlaceEntry {
  double x_m = 0.0;
  double y_m = 0.0;
  double heading_rad = 0.0;  // world frame, counter-clockwise from +x
  PlaceView view;
  std::vector<core::ReadingKind> kinds;  // per bin, or empty
};

// A candidate place for a query.
struct PlaceMatch {
  int entry = 0;          // index into PlaceTable::entries(): the entry matched
  double distance = 0.0;  // the signature's distance (see each signature)
  // The query robot's heading in the world frame (the entry's heading plus
  // the alignment's), for signatures that give one.
  std::optional<double> heading_rad;
  // The query robot's position in the world frame, where the search refined
  // it (AlignPose).
  std::optional<Eigen::Vector2d> position_m;
};

// How far Nearest looks around a matched place for the query's position.
struct PoseSearch {
  double radius_m = 0.0;     // 0: no refinement
  double min_step_m = 0.01;  // the finest step of the search
};

// The shortlist the colour signature aligns: this many nearest by its
// heading-invariant part.
inline constexpr int kColourShortlist = 40;
// With a PoseSearch, this many of the best aligned candidates are refined.
inline constexpr int kRefinedCandidates = 6;

// A table of places and their signatures (Taylor, Geva & Boles 2005, §5.3:
// "a table of signatures and positions" looked up by nearest neighbour),
// with the colour ROP of §5.1. Brute force: tables hold hundreds of places.
class PlaceTable {
 public:
  PlaceTable() = default;
  // Every entry's view must have kRadialProfileBins ranges and 0 or that
  // many colours (std::invalid_argument otherwise).
  PlaceTable(std::string world, double max_range_m, std::vector<PlaceEntry> entries);

  const std::string& world() const { return world_; }
  double max_range_m() const { return max_range_m_; }
  const std::vector<PlaceEntry>& entries() const { return entries_; }

  // The k best entries for `query` by `kind`, best first (fewer when the
  // table is smaller). For kDct, kHu and kFourier: the signatures' nearest
  // neighbours; kFourier then aligns each candidate (AlignProfiles, ranges
  // only) for the heading. For kColour: the kColourShortlist nearest by
  // ColourSignatureDistance, re-ranked by AlignProfiles with colour (the
  // distance is the alignment's cost), which also gives the heading.
  // With search.radius_m > 0, kFourier and kColour shortlist kColourShortlist
  // by their heading-invariant distance, align them all (AlignProfiles, with
  // colour for kColour), and refine the best kRefinedCandidates by AlignPose
  // (search.radius_m, search.min_step_m), ranked by its cost: each match then
  // also has the query's position. Throws std::invalid_argument unless the
  // query has mapping::kRadialProfileBins ranges.
  std::vector<PlaceMatch> Nearest(const PlaceView& query, SignatureKind kind, int k = 1,
                                  const PoseSearch& search = {}) const;

 private:
  // Every place's signature distance from the query, in the table's order.
  std::vector<PlaceMatch> SignatureDistances(const PlaceView& query, SignatureKind kind) const;
  // Each match's distance and heading from aligning its view with the query's
  // (with colours or not), and with `search` its position refined too.
  void Align(const PlaceView& query, bool colour, std::vector<PlaceMatch>& matches) const;
  void AlignPoses(const PlaceView& query, bool colour, const PoseSearch& search,
                  std::vector<PlaceMatch>& matches) const;

  std::string world_;
  double max_range_m_ = 0.0;
  std::vector<PlaceEntry> entries_;
  std::vector<std::vector<double>> dct_;
  std::vector<HuSignature> hu_;
  std::vector<std::vector<double>> fourier_;
  std::vector<ColourSignature> colour_;
};

}  // namespace pirouette::localize
