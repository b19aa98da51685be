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

// The floor is never nearer the walls in the picture than
// kMinPictureContrast. Throws std::runtime_error if no draw is (it has never
// come near).
WorldStyle DrawStyle(SeededRandom& random, const StyleScale& scale);

// An obstacle's colour: mostly saturated, sometimes close to the floor's or
// the walls' colour, sometimes grey; never nearer the floor in the picture
// than kMinPictureContrast. Throws std::runtime_error if no draw is (it has
// never come near).
core::Rgb DrawObstacleColour(SeededRandom& random, const WorldStyle& style);

// An obstacle's height, to the millimetre: sometimes exactly the camera's.
double DrawObstacleHeight(SeededRandom& random, const StyleScale& scale);

// The brightness the renderer gives a surface of unit normal `normal` (its
// flat shading: ambient + intensity · the cosine towards the light).
double Shade(const Light& light, const Eigen::Vector3d& normal);

// The least difference a generated world keeps, in grey levels of the
// picture, between the lit floor and every face of its walls and obstacles
// (PictureContrast): four times the simulated camera's noise
// (RenderOptions::noise_sigma, 2 levels). Nearer than that a face is lost in
// the camera's noise, and no camera that finds the floor by its look could
// tell it from the floor: such a world would test the camera, not the map.
// The hard cases (a floor close to the walls' colour, or to the colour they
// shade to) are drawn as close as this, not closer.
inline constexpr double kMinPictureContrast = 8.0;

// How unlike the floor a surface of `colour` looks to the camera under
// `light`: over its faces (vertical ones facing any way, and a top, as a
// thing lower than the camera shows it), the least of the largest channel's
// difference between the face's shaded colour and the floor's (lit from
// above), in grey levels, each clamped to 255 as the renderer does; within
// half a grey level.
double PictureContrast(const Light& light, const core::Rgb& colour, const core::Rgb& floor);

}  // namespace pirouette::sim
