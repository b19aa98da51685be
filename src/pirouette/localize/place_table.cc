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

std::vector<PlaceMatch> PlaceTable::Nearest(const PlaceView& query, SignatureKind kind, int k,
                                            const PoseSearch& search) const {
  if (query.ranges_m.size() != static_cast<std::size_t>(mapping::kRadialProfileBins)) {
    throw std::invalid_argument("PlaceTable::Nearest: a query has one range a degree");
  }
  const int n = static_cast<int>(entries_.size());
  std::vector<PlaceMatch> all(static_cast<std::size_t>(n));
  const auto sort_take = [&all](int count) {
    const auto keep = static_cast<std::size_t>(std::clamp(count, 0, static_cast<int>(all.size())));
    std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(keep), all.end(),
                      [](const PlaceMatch& a, const PlaceMatch& b) {
                        return a.distance < b.distance ||
                               (a.distance == b.distance && a.entry < b.entry);
                      });
    all.resize(keep);
  };
  switch (kind) {
    case SignatureKind::kDct: {
      const std::vector<double> q = DctSignature(query.ranges_m);
      for (int i = 0; i < n; ++i) {
        all[i] = {i, SignatureDistance(q, dct_[i]), std::nullopt, std::nullopt};
      }
      sort_take(k);
      return all;
    }
    case SignatureKind::kHu: {
      const HuSignature q = HuMoments(query.ranges_m);
      for (int i = 0; i < n; ++i) all[i] = {i, HuDistance(q, hu_[i]), std::nullopt, std::nullopt};
      sort_take(k);
      return all;
    }
    case SignatureKind::kFourier:
    case SignatureKind::kColour: {
      const bool colour = kind == SignatureKind::kColour;
      const bool refine = search.radius_m > 0.0;
      if (colour) {
        const ColourSignature q = MakeColourSignature(query);
        for (int i = 0; i < n; ++i) {
          all[i] = {i, ColourSignatureDistance(q, colour_[i]), std::nullopt, std::nullopt};
        }
      } else {
        const std::vector<double> q = FourierSignature(query.ranges_m);
        for (int i = 0; i < n; ++i) {
          all[i] = {i, SignatureDistance(q, fourier_[i]), std::nullopt, std::nullopt};
        }
      }
      if (!colour && !refine) {
        sort_take(k);
        for (PlaceMatch& m : all) {
          const PlaceEntry& e = entries_[static_cast<std::size_t>(m.entry)];
          m.heading_rad =
              core::NormalizeAngle(e.heading_rad + AlignProfiles(query, e.view, false).heading_rad);
        }
        return all;
      }
      sort_take(std::max(k, kColourShortlist));
      for (PlaceMatch& m : all) {
        const PlaceEntry& e = entries_[static_cast<std::size_t>(m.entry)];
        const Alignment a = AlignProfiles(query, e.view, colour);
        m.distance = a.cost;
        m.heading_rad = core::NormalizeAngle(e.heading_rad + a.heading_rad);
      }
      if (!refine) {
        sort_take(k);
        return all;
      }
      sort_take(std::max(k, kRefinedCandidates));
      for (PlaceMatch& m : all) {
        const PlaceEntry& e = entries_[static_cast<std::size_t>(m.entry)];
        const PoseAlignment a =
            AlignPose(query, e.view, max_range_m_, search.radius_m, search.min_step_m, colour);
        const double c = std::cos(e.heading_rad), s = std::sin(e.heading_rad);
        m.distance = a.cost;
        m.heading_rad = core::NormalizeAngle(e.heading_rad + a.heading_rad);
        m.position_m = Eigen::Vector2d(e.x_m + c * a.position_m.x() - s * a.position_m.y(),
                                       e.y_m + s * a.position_m.x() + c * a.position_m.y());
      }
      sort_take(k);
      return all;
    }
  }
  return {};
}

}  // namespace pirouette::localize
