#pragma once

#include <string>

#include "pirouette/core/rgb.h"
#include "pirouette/sim/seeded_random.h"
#include "pirouette/sim/world.h"

namespace pirouette::sim {

// The sizes a world's look is drawn around: its robot's camera and the walls
// and furniture of its kind. Lengths in metres, thicknesses in whole
// millimetres (even, so that a wall's centre line lies on a millimetre).
struct StyleScale {
  double camera_height_m = 0.0;
  double tall_wall_min_m = 0.0;  // walls taller than the camera: this range
  double tall_wall_max_m = 0.0;
  int wall_thickness_min_mm = 0;
  int wall_thickness_max_mm = 0;
  double obstacle_height_min_m = 0.0;
  double obstacle_height_max_m = 0.0;
};

// How a generated world looks: what a real floor varies (SPEC.md, "Worlds
// nobody drew by hand"): the floor's colour and texture, the walls' colour,
// height and thickness, the light. Drawn so that the cases a camera finds
// hard come up often: a floor close to the walls' colour, or to the colour
// the walls shade to under the light; light walls exactly as high as the
// camera (the camera sees their tops edge-on); walls lower than the camera.
struct WorldStyle {
  Floor floor;  // colour and texture; its size is the layout's
  BoundaryWalls walls;
  core::Rgb inner_wall_colour;  // walls inside the floor (often the boundary's)
  Light light;
  // What was drawn, in words, for the world file's comment.
  std::string description;
};

WorldStyle DrawStyle(SeededRandom& random, const StyleScale& scale);

// An obstacle's colour: mostly saturated, sometimes close to the floor's or
// the walls' colour, sometimes grey.
core::Rgb DrawObstacleColour(SeededRandom& random, const WorldStyle& style);

// An obstacle's height, to the millimetre: sometimes exactly the camera's.
double DrawObstacleHeight(SeededRandom& random, const StyleScale& scale);

// The brightness the renderer gives a surface of unit normal `normal` (its
// flat shading: ambient + intensity · the cosine towards the light).
double Shade(const Light& light, const Eigen::Vector3d& normal);

}  // namespace pirouette::sim
