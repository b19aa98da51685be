#include "pirouette/localize/place_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pirouette/core/angle.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::localize {
namespace {

constexpr int kBins = mapping::kRadialProfileBins;

}  // namespace

PlaceTable::PlaceTable(std::string world, double max_range_m, std::vector<PlaceEntry> entries)
    : world_(std::move(world)), max_range_m_(max_range_m), entries_(std::move(entries)) {
  for (const PlaceEntry& e : entries_) {
    if (static_cast<int>(e.view.ranges_m.size()) != kBins ||
        (!e.view.colours.empty() && static_cast<int>(e.view.colours.size()) != kBins) ||
        (!e.kinds.empty() && static_cast<int>(e.kinds.size()) != kBins)) {
      throw std::invalid_argument("PlaceTable: every place needs 360 bins");
    }
    dct_.push_back(DctSignature(e.view.ranges_m));
    hu_.push_back(HuMoments(e.view.ranges_m));
    fourier_.push_back(FourierSignature(e.view.ranges_m));
    colour_.push_back(MakeColourSignature(e.view));
  }
}

namespace {

// The best `count` matches, nearest first (ties by entry), the rest dropped.
void SortTake(std::vector<PlaceMatch>& all, int count) {
  const auto keep = static_cast<std::size_t>(std::clamp(count, 0, static_cast<int>(all.size())));
  std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(keep), all.end(),
                    [](const PlaceMatch& a, const PlaceMatch& b) {
                      return a.distance < b.distance ||
                             (a.distance == b.distance && a.entry < b.entry);
                    });
  all.resize(keep);
}

}  // namespace

std::vector<PlaceMatch> PlaceTable::SignatureDistances(const PlaceView& query,
                                                       SignatureKind kind) const {
  const int n = static_cast<int>(entries_.size());
  std::vector<PlaceMatch> all(static_cast<std::size_t>(n));
  const auto each = [&](const auto& distance) {
    for (int i = 0; i < n; ++i) all[i] = {i, distance(i), std::nullopt, std::nullopt};
  };
  switch (kind) {
    case SignatureKind::kDct: {
      const std::vector<double> q = DctSignature(query.ranges_m);
      each([&](int i) { return SignatureDistance(q, dct_[i]); });
      break;
    }
    case SignatureKind::kHu: {
      const HuSignature q = HuMoments(query.ranges_m);
      each([&](int i) { return HuDistance(q, hu_[i]); });
      break;
    }
    case SignatureKind::kFourier: {
      const std::vector<double> q = FourierSignature(query.ranges_m);
      each([&](int i) { return SignatureDistance(q, fourier_[i]); });
      break;
    }
    case SignatureKind::kColour: {
      const ColourSignature q = MakeColourSignature(query);
      each([&](int i) { return ColourSignatureDistance(q, colour_[i]); });
      break;
    }
  }
  return all;
}

void PlaceTable::Align(const PlaceView& query, bool colour,
                       std::vector<PlaceMatch>& matches) const {
  for (PlaceMatch& m : matches) {
    const PlaceEntry& e = entries_[static_cast<std::size_t>(m.entry)];
    const Alignment a = AlignProfiles(query, e.view, colour);
    m.distance = a.cost;
    m.heading_rad = core::NormalizeAngle(e.heading_rad + a.heading_rad);
  }
}

void PlaceTable::AlignPoses(const PlaceView& query, bool colour, const PoseSearch& search,
                            std::vector<PlaceMatch>& matches) const {
  for (PlaceMatch& m : matches) {
    const PlaceEntry& e = entries_[static_cast<std::size_t>(m.entry)];
    const PoseAlignment a =
        AlignPose(query, e.view, max_range_m_, search.radius_m, search.min_step_m, colour);
    const double c = std::cos(e.heading_rad), s = std::sin(e.heading_rad);
    m.distance = a.cost;
    m.heading_rad = core::NormalizeAngle(e.heading_rad + a.heading_rad);
    m.position_m = Eigen::Vector2d(e.x_m + c * a.position_m.x() - s * a.position_m.y(),
                                   e.y_m + s * a.position_m.x() + c * a.position_m.y());
  }
}

std::vector<PlaceMatch> PlaceTable::Nearest(const PlaceView& query, SignatureKind kind, int k,
                                            const PoseSearch& search) const {
  if (query.ranges_m.size() != static_cast<std::size_t>(mapping::kRadialProfileBins)) {
    throw std::invalid_argument("PlaceTable::Nearest: a query has one range a degree");
  }
  std::vector<PlaceMatch> all = SignatureDistances(query, kind);
  if (kind == SignatureKind::kDct || kind == SignatureKind::kHu) {
    SortTake(all, k);
    return all;
  }
  const bool colour = kind == SignatureKind::kColour;
  const bool refine = search.radius_m > 0.0;
  if (!colour && !refine) {
    // The Fourier signature's nearest, each with its heading by cross-correlation.
    SortTake(all, k);
    for (PlaceMatch& m : all) {
      const PlaceEntry& e = entries_[static_cast<std::size_t>(m.entry)];
      m.heading_rad =
          core::NormalizeAngle(e.heading_rad + AlignProfiles(query, e.view, false).heading_rad);
    }
    return all;
  }
  SortTake(all, std::max(k, kColourShortlist));
  Align(query, colour, all);
  if (!refine) {
    SortTake(all, k);
    return all;
  }
  SortTake(all, std::max(k, kRefinedCandidates));
  AlignPoses(query, colour, search, all);
  SortTake(all, k);
  return all;
}

}  // namespace pirouette::localize
