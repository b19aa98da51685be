#pragma once

#include <Eigen/Core>
#include <vector>

#include "pirouette/core/colour_class.h"
#include "pirouette/core/grid_geometry.h"

namespace pirouette::localize {

// One colour sighting: where (map frame) the camera saw the base of an
// obstacle, and the colour class of what stood there (Taylor, Geva & Boles
// 2005, §5.1's colour ROP, kept on the map).
struct ColourSighting {
  Eigen::Vector2d p_m = Eigen::Vector2d::Zero();
  core::ColourClass colour = core::ColourClass::kNone;
};

// The colours of a map's cells: what a run's camera saw standing on each
// cell, so that a later pirouette's colour ROP can be compared with the map
// (a symmetric room's mirror image then looks different). One class a cell,
// kNone where nothing coloured was seen. Row-major, row 0 the lowest y, as
// mapping::TrinaryMap.
class ColourMap {
 public:
  // An empty map: every cell kNone.
  ColourMap() = default;
  // cells must hold geometry.CellCount() classes (std::invalid_argument).
  ColourMap(core::GridGeometry geometry, std::vector<core::ColourClass> cells);

  // The map of `sightings` on `geometry`: each sighting votes for its class
  // in its cell and the 8 around it (its own cell twice), so that a wall's
  // cells take the colour seen at their neighbours' (an obstacle's base is
  // read to a cell or so); a cell takes the class with the most votes (the
  // lowest class on a tie), kNone without votes. Sightings off the geometry
  // are dropped (ColourVotes counts them one at a time).
  static ColourMap FromSightings(const core::GridGeometry& geometry,
                                 const std::vector<ColourSighting>& sightings);

  // This map on another geometry (of the same cell size, e.g. a crop of
  // it): each cell the class at its centre here, kNone off this map.
  ColourMap On(const core::GridGeometry& geometry) const;

  bool empty() const { return cells_.empty(); }
  const core::GridGeometry& geometry() const { return geometry_; }
  const std::vector<core::ColourClass>& cells() const { return cells_; }
  // kNone off the map and for an empty map.
  core::ColourClass At(const core::CellIndex& c) const;

 private:
  core::GridGeometry geometry_{1.0, Eigen::Vector2d::Zero(), 1, 1};
  std::vector<core::ColourClass> cells_;
};

}  // namespace pirouette::localize
