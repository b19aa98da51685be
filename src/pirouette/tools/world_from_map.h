#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>

#include "pirouette/io/map_file.h"

namespace pirouette::tools {

// What `pirouette world from-map` was asked (SPEC.md, "Worlds nobody drew by hand").
struct WorldFromMapRequest {
  std::string map_path;                    // a map_server map's yaml
  std::string out_path;                    // the world file to write
  double radius_m = 0.15;                  // the robot's (the apartment robot's by default)
  std::optional<std::string> camera_path;  // default: worlds/webcam640.yaml's camera
  double height_m = 0.9;                   // the blocks' height (the apartment's walls)
  // The start (x, y in the map's frame, heading in degrees); none: chosen
  // (sim::ChooseGridStart).
  std::optional<Eigen::Vector3d> start;
  bool seal = true;  // close gaps narrower than the robot (sim::SealUnreachable)
};

// What from-map made, for its report.
struct WorldFromMapResult {
  std::string text;  // the world file
  io::MapServerMap map;
  Eigen::Vector2d start_map = Eigen::Vector2d::Zero();    // in the map's frame
  Eigen::Vector2d start_world = Eigen::Vector2d::Zero();  // in the world's
  std::size_t free_cells = 0;                             // the map's free cells, before sealing
  std::size_t sealed_cells = 0;                           // of those, made blocks by sealing
  std::size_t boxes = 0;                                  // the blocks merged into boxes
};

// The world of a map: its floor the map's extent, the map's frame moved so
// that its lower-left corner (the yaml's origin) is the world's (0, 0); one
// `grid` obstacle naming the map (relative to the world file's folder where
// it can be, else absolute), blocks request.height_m tall; the robot at the
// given start or the chosen one, its camera inline. Checks the world as
// io::LoadWorldFile will (the start's disc fits). Throws core::InputError
// naming the map's file and field for a bad map, naming --start for a start
// that does not fit, naming --map when the disc fits nowhere, naming --radius
// or --height for a value that is not positive; std::runtime_error when the
// world file cannot be written.
WorldFromMapResult RunWorldFromMap(const WorldFromMapRequest& request);

}  // namespace pirouette::tools
