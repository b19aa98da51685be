#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pirouette/core/grid_geometry.h"

#include "pirouette/mapping/trinary_map.h"

// Map files as ROS's map_server reads and writes them (SPEC.md, "Map files"):
// a YAML file of metadata beside a greyscale image, one pixel a cell.

namespace pirouette::io {

// The thresholds written to every map.yaml are the grid's own
// (mapping::kOccupiedThreshold, mapping::kFreeThreshold): with them
// map_server reads 254 as free, 0 as occupied and 205 as unknown
// ((255 - 205) / 255 = 0.19608 lies between them).

// The pixel values of map.pgm.
inline constexpr unsigned char kPgmFree = 254;
inline constexpr unsigned char kPgmOccupied = 0;
inline constexpr unsigned char kPgmUnknown = 205;

// The text of map.yaml for `map`, its `image` field naming `image_name` (the
// PGM's file name, relative to the YAML's folder): mode trinary, the map's
// resolution, origin [x, y, 0] (the world position of the lower-left cell's
// lower-left corner), negate 0 and the thresholds above. Numbers are written
// in the shortest form that reads back to the same double.
std::string RosMapYaml(const mapping::TrinaryMap& map, const std::string& image_name);

// The bytes of map.pgm for `map`: binary PGM, header exactly
// "P5\n<width> <height>\n255\n", then one byte a cell, the first row the map's
// top (its largest y); kPgmFree, kPgmOccupied, kPgmUnknown.
std::string RosMapPgm(const mapping::TrinaryMap& map);

// Writes the map to `yaml_path` (DIR/STEM.yaml) and its image to DIR/STEM.pgm,
// both atomically (the PGM first, so that a YAML never names a missing
// image); the YAML's `image` field is the PGM's file name. Throws
// std::invalid_argument when `yaml_path` ends in ".pgm" (the two would be one
// file), std::runtime_error naming the path when a file cannot be written.
void WriteRosMap(const mapping::TrinaryMap& map, const std::string& yaml_path);

// map_server's three ways of reading an image (the yaml's `mode`).
enum class MapMode { kTrinary, kScale, kRaw };

// The cell values of a nav_msgs/OccupancyGrid.
inline constexpr std::int8_t kMapFree = 0;
inline constexpr std::int8_t kMapOccupied = 100;
inline constexpr std::int8_t kMapUnknown = -1;

// A map as map_server serves it: its geometry (the origin's x, y) and one
// value a cell, row-major from the bottom row (as `geometry.Flat`): 0 free,
// 100 occupied, -1 unknown, and in scale and raw modes the values between.
struct MapServerMap {
  core::GridGeometry geometry;
  MapMode mode = MapMode::kTrinary;
  std::vector<std::int8_t> cells;
};

// Reads a map exactly as map_server does (nav2's map_io, loadMapYaml and
// loadMapFromFile). The YAML needs `image` (relative to the YAML's folder,
// or absolute), `resolution` (> 0), `origin` ([x, y, yaw], yaw 0: rotated
// maps are refused), `negate` (0 / 1 or false / true), `occupied_thresh` and
// `free_thresh` (0..1, free_thresh <= occupied_thresh); `mode` is optional
// (trinary, the default, scale or raw). Other keys are ignored, as
// map_server ignores them.
//
// The image is a PGM (binary P5 or plain P2, maxval up to 65535), or any
// other picture OpenCV reads (PNG with or without alpha, ...). Its colour
// channels are averaged to a shade s in 0..1 (in trinary mode an alpha
// channel is averaged in as a fourth); occ = s when negated, else 1 - s.
//  - trinary: 100 when occ > occupied_thresh, 0 when occ < free_thresh, else -1;
//  - scale: -1 where the pixel is not opaque, then as trinary, but between
//    the thresholds rint(100 · (occ - free_thresh) / (occupied_thresh - free_thresh));
//  - raw: round(255 · s) where that is 0..100, else -1 (negate ignored).
// The image's first row is the map's top.
//
// Throws core::InputError naming the file, the line and the field for a
// missing or unreadable file, malformed YAML, a missing or wrong field, and a
// missing, unreadable or malformed image.
MapServerMap ReadMapServerMap(const std::string& yaml_path);

// ReadMapServerMap for a trinary map (pirouette's own, `locate`'s input):
// 0 free, 100 occupied, -1 unknown. Throws core::InputError naming `mode`
// for a scale or raw map, whose in-between values a TrinaryMap cannot hold.
mapping::TrinaryMap ReadRosMap(const std::string& yaml_path);

}  // namespace pirouette::io
