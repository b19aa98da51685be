#pragma once

// For the explore tests: a shipped world's true occupancy rasterised into a
// TrinaryMap (read with yaml-cpp, without the simulator), the way SPEC.md's
// eval does: a cell is occupied where its centre lies inside an obstacle, a
// wall, or off the floor; free elsewhere.

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::testing {

struct RasterWorld {
  mapping::TrinaryMap map;
  double robot_radius_m = 0.0;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
};

inline Eigen::Vector2d Vec(const YAML::Node& n) { return {n[0].as<double>(), n[1].as<double>()}; }

// Whether p lies inside the polygon (even-odd rule).
inline bool InPolygon(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p) {
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

// A rectangle of half-sizes (hx, hy) about `centre`, turned by yaw.
inline std::vector<Eigen::Vector2d> Rectangle(const Eigen::Vector2d& centre, double hx, double hy,
                                              double yaw_rad) {
  const Eigen::Vector2d u(std::cos(yaw_rad), std::sin(yaw_rad));
  const Eigen::Vector2d v(-u.y(), u.x());
  return {centre - hx * u - hy * v, centre + hx * u - hy * v, centre + hx * u + hy * v,
          centre - hx * u + hy * v};
}

// The world file `name` in the shipped worlds, moved by `shift` (so as to
// meet the grid at another alignment), on a grid of `resolution_m` whose
// origin is `cells` cells below and left of the world origin.
inline RasterWorld RasteriseWorld(const std::string& name, double resolution_m, int cells,
                                  const Eigen::Vector2d& shift = Eigen::Vector2d::Zero()) {
  const YAML::Node world = YAML::LoadFile(std::string(PIROUETTE_WORLDS_DIR) + "/" + name);
  const Eigen::Vector2d floor = Vec(world["floor"]["size"]);
  std::vector<std::vector<Eigen::Vector2d>> polygons;
  struct Disc {
    Eigen::Vector2d centre;
    double radius;
  };
  std::vector<Disc> discs;
  for (const YAML::Node& item : world["obstacles"]) {
    if (item["box"]) {
      const YAML::Node b = item["box"];
      const Eigen::Vector2d size = Vec(b["size"]);
      const double yaw = b["yaw"] ? b["yaw"].as<double>() * std::numbers::pi / 180.0 : 0.0;
      polygons.push_back(Rectangle(Vec(b["centre"]), size.x() / 2, size.y() / 2, yaw));
    } else if (item["cylinder"]) {
      discs.push_back({Vec(item["cylinder"]["centre"]), item["cylinder"]["radius"].as<double>()});
    } else if (item["wall"]) {
      const YAML::Node w = item["wall"];
      const Eigen::Vector2d from = Vec(w["from"]);
      const Eigen::Vector2d to = Vec(w["to"]);
      const Eigen::Vector2d d = to - from;
      polygons.push_back(Rectangle((from + to) / 2, d.norm() / 2, w["thickness"].as<double>() / 2,
                                   std::atan2(d.y(), d.x())));
    } else if (item["prism"]) {
      std::vector<Eigen::Vector2d> points;
      for (const YAML::Node& p : item["prism"]["points"]) points.push_back(Vec(p));
      polygons.push_back(points);
    }
  }
  const double margin = cells * resolution_m;
  const core::GridGeometry g =
      core::GridGeometry::Covering(resolution_m, Eigen::Vector2d(-margin, -margin),
                                   floor + shift + Eigen::Vector2d(2 * margin, 2 * margin));
  RasterWorld out{{g, std::vector<mapping::CellState>(g.CellCount())},
                  world["robot"]["radius"].as<double>(),
                  Vec(world["robot"]["start"]) + shift};
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const Eigen::Vector2d p = g.CellCentre({x, y}) - shift;
      bool occupied = p.x() < 0 || p.y() < 0 || p.x() > floor.x() || p.y() > floor.y();
      for (const auto& poly : polygons) occupied = occupied || InPolygon(poly, p);
      for (const Disc& d : discs) occupied = occupied || (p - d.centre).norm() <= d.radius;
      out.map.cells[g.Flat({x, y})] =
          occupied ? mapping::CellState::kOccupied : mapping::CellState::kFree;
    }
  }
  return out;
}

}  // namespace pirouette::testing
