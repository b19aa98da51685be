#include "pirouette/sim/world_style.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace pirouette::sim {
namespace {

// How often each kind of floor, wall and obstacle colour is drawn. The hard
// cases for a camera that finds the floor by its colour (a floor like the
// walls, or like what the walls shade to) are a third of all floors.
constexpr double kFloorDark = 0.20;  // the paper's soccer field: a dark floor, light walls
constexpr double kFloorWood = 0.15;
constexpr double kFloorCarpet = 0.20;  // any hue, muted
constexpr double kFloorLight = 0.10;   // pale tiles or concrete
constexpr double kFloorNearWall = 0.175;
// (the rest: near the colour one face of the walls shades to)

constexpr double kWallLight = 0.60;
constexpr double kWallPastel = 0.20;
constexpr double kWallSaturated = 0.10;
// (the rest: dark walls)

// Wall heights: exactly the camera's (its tops seen edge-on, the issue's
// failing maze), lower than the camera (it sees over them), or taller.
constexpr double kWallsAsHighAsTheCamera = 0.25;
constexpr double kWallsLowerThanTheCamera = 0.15;
constexpr double kLowWallMin = 0.5;  // times the camera's height
constexpr double kLowWallMax = 0.9;

// Inner walls of another colour than the boundary's, some of the time.
constexpr double kInnerWallsOtherColour = 0.2;

constexpr double kNoTexture = 0.2;  // the rest: texture in [kTextureMin, kTextureMax]
constexpr double kTextureMin = 0.01;
constexpr double kTextureMax = 0.12;

// The light: dim to bright, from anywhere above within ~40° of overhead.
constexpr double kAmbientMin = 0.25;
constexpr double kAmbientMax = 0.60;
constexpr double kIntensityMin = 0.25;
constexpr double kIntensityMax = 0.75;
constexpr double kLightSlopeMax = 0.8;  // |x|, |y| of the direction, z being -1

constexpr double kObstacleSaturated = 0.60;
constexpr double kObstacleNearFloor = 0.15;
constexpr double kObstacleNearWall = 0.10;
// (the rest: grey)

// Obstacles exactly as high as the camera, some of the time.
constexpr double kObstacleAsHighAsTheCamera = 0.1;

// Draws of a colour of one kind before the kind itself is drawn again, and
// of kinds before the generator gives up (it has never come near either).
constexpr int kColourTries = 20;
constexpr int kKindTries = 50;

// `value` to `decimals` places, as the double nearest that decimal (so that
// it prints short: 0.11, not 0.11000000000000001).
double RoundTo(double value, int decimals) {
  const double scale = decimals == 2 ? 100.0 : 1000.0;
  return std::round(value * scale) / scale;
}

// +0.0 for -0.0 (a file would say "-0").
double Positive0(double value) { return value + 0.0; }

std::uint8_t Channel(double value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 255.0)));
}

core::Rgb FromDoubles(double r, double g, double b) { return {Channel(r), Channel(g), Channel(b)}; }

// HSV (hue in degrees, saturation and value in [0, 1]) to 0..255 channels.
core::Rgb FromHsv(double hue_deg, double saturation, double value) {
  const double h = std::fmod(hue_deg, 360.0) / 60.0;
  const int sector = std::min(5, static_cast<int>(h));
  const double f = h - sector;
  const double v = 255.0 * value;
  const double p = v * (1.0 - saturation);
  const double q = v * (1.0 - saturation * f);
  const double t = v * (1.0 - saturation * (1.0 - f));
  const std::array<std::array<double, 3>, 6> rgb = {
      {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}}};
  return FromDoubles(rgb[sector][0], rgb[sector][1], rgb[sector][2]);
}

// A grey of `value` (0..255) with a slight tint of up to ±`tint` a channel.
core::Rgb Tinted(SeededRandom& random, double value, double tint) {
  const double r = value + random.Uniform(-tint, tint);
  const double g = value + random.Uniform(-tint, tint);
  const double b = value + random.Uniform(-tint, tint);
  return FromDoubles(r, g, b);
}

// `base` moved by one common offset in ±`shift` and a per-channel one in ±`jitter`.
core::Rgb Near(SeededRandom& random, const core::Rgb& base, double shift, double jitter) {
  const double common = random.Uniform(-shift, shift);
  const double r = base.r + common + random.Uniform(-jitter, jitter);
  const double g = base.g + common + random.Uniform(-jitter, jitter);
  const double b = base.b + common + random.Uniform(-jitter, jitter);
  return FromDoubles(r, g, b);
}

// A colour of random hue, saturation in [s_lo, s_hi) and value in [v_lo, v_hi).
core::Rgb DrawHsv(SeededRandom& random, double s_lo, double s_hi, double v_lo, double v_hi) {
  const double hue = random.Uniform(0.0, 360.0);
  const double saturation = random.Uniform(s_lo, s_hi);
  const double value = random.Uniform(v_lo, v_hi);
  return FromHsv(hue, saturation, value);
}

std::string ColourText(const core::Rgb& c) { return fmt::format("({}, {}, {})", c.r, c.g, c.b); }

struct Drawn {
  core::Rgb colour;
  std::string words;
};

Drawn DrawWallColour(SeededRandom& random) {
  const double pick = random.Unit();
  if (pick < kWallLight) return {Tinted(random, random.Uniform(200.0, 250.0), 8.0), "light"};
  if (pick < kWallLight + kWallPastel) {
    return {DrawHsv(random, 0.12, 0.35, 0.7, 0.95), "pastel"};
  }
  if (pick < kWallLight + kWallPastel + kWallSaturated) {
    return {DrawHsv(random, 0.45, 0.85, 0.35, 0.8), "coloured"};
  }
  return {Tinted(random, random.Uniform(30.0, 90.0), 6.0), "dark"};
}

struct WallHeight {
  double metres;
  std::string words;
};

WallHeight DrawWallHeight(SeededRandom& random, const StyleScale& scale) {
  const double pick = random.Unit();
  const double camera = scale.camera_height_m;
  if (pick < kWallsAsHighAsTheCamera) {
    return {RoundTo(camera, 3), fmt::format("as high as the camera ({} m)", camera)};
  }
  if (pick < kWallsAsHighAsTheCamera + kWallsLowerThanTheCamera) {
    const double h = RoundTo(camera * random.Uniform(kLowWallMin, kLowWallMax), 3);
    return {h, fmt::format("lower than the camera ({} m)", h)};
  }
  const double h = RoundTo(random.Uniform(scale.tall_wall_min_m, scale.tall_wall_max_m), 3);
  return {h, fmt::format("taller than the camera ({} m)", h)};
}

Light DrawLight(SeededRandom& random) {
  Light light;
  light.ambient = RoundTo(random.Uniform(kAmbientMin, kAmbientMax), 2);
  light.intensity = RoundTo(random.Uniform(kIntensityMin, kIntensityMax), 2);
  const double x = Positive0(RoundTo(random.Uniform(-kLightSlopeMax, kLightSlopeMax), 2));
  const double y = Positive0(RoundTo(random.Uniform(-kLightSlopeMax, kLightSlopeMax), 2));
  light.direction = {x, y, -1.0};
  return light;
}

// A floor colour of the kind `pick` (in [0, 1): the shares above) names;
// `walls` and `light` for the floors drawn to look like the walls.
Drawn DrawFloorColourOfKind(SeededRandom& random, double pick, const core::Rgb& walls,
                            const Light& light) {
  if (pick < kFloorDark) return {Tinted(random, random.Uniform(12.0, 60.0), 6.0), "dark"};
  double below = kFloorDark + kFloorWood;
  if (pick < below) {
    const double r = random.Uniform(110.0, 175.0);
    const double g = r * random.Uniform(0.62, 0.75);
    const double b = r * random.Uniform(0.35, 0.5);
    return {FromDoubles(r, g, b), "wood"};
  }
  below += kFloorCarpet;
  if (pick < below) {
    return {DrawHsv(random, 0.2, 0.65, 0.25, 0.7), "carpet"};
  }
  below += kFloorLight;
  if (pick < below) return {Tinted(random, random.Uniform(165.0, 225.0), 8.0), "pale"};
  below += kFloorNearWall;
  if (pick < below) return {Near(random, walls, 25.0, 6.0), "close to the walls' colour"};
  // What one face of the walls (facing +x, -x, +y or -y) shades to, seen beside the lit floor.
  static const std::array<Eigen::Vector3d, 4> kFaces = {
      Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
      -Eigen::Vector3d::UnitY()};
  const std::uint64_t face = random.Below(4);
  const double ratio = Shade(light, kFaces[face]) / Shade(light, Eigen::Vector3d::UnitZ());
  const core::Rgb shaded = FromDoubles(walls.r * ratio, walls.g * ratio, walls.b * ratio);
  return {Near(random, shaded, 4.0, 8.0), "close to the colour the walls shade to"};
}

// An obstacle colour of the kind `pick` (in [0, 1): the shares above) names.
core::Rgb DrawObstacleColourOfKind(SeededRandom& random, double pick, const WorldStyle& style) {
  if (pick < kObstacleSaturated) {
    return DrawHsv(random, 0.5, 0.95, 0.35, 0.95);
  }
  if (pick < kObstacleSaturated + kObstacleNearFloor) {
    // Not the floor's own colour: 15..35 away, one way or the other.
    const double magnitude = random.Uniform(15.0, 35.0);
    const double shift = random.Chance(0.5) ? magnitude : -magnitude;
    const core::Rgb f = style.floor.colour;
    return FromDoubles(f.r + shift, f.g + shift, f.b + shift);
  }
  if (pick < kObstacleSaturated + kObstacleNearFloor + kObstacleNearWall) {
    return Near(random, style.walls.colour, 10.0, 4.0);
  }
  return Tinted(random, random.Uniform(20.0, 240.0), 4.0);
}

// The first colour `draw_of_kind` draws (given a kind: a pick in [0, 1)) that
// `stands_out` accepts, each kind drawn again up to kColourTries times before
// another kind is picked; throws std::runtime_error naming `what` after
// kKindTries kinds.
template <typename Colour, typename DrawOfKind, typename StandsOut>
Colour DrawStandingOut(SeededRandom& random, const DrawOfKind& draw_of_kind,
                       const StandsOut& stands_out, const char* what) {
  for (int kind = 0; kind < kKindTries; ++kind) {
    const double pick = random.Unit();
    for (int i = 0; i < kColourTries; ++i) {
      Colour colour = draw_of_kind(pick);
      if (stands_out(colour)) return colour;
    }
  }
  throw std::runtime_error(std::string("world generator: found no ") + what);
}

// The floor's colour: as close to the walls' as the hard kinds draw it, but
// never closer in the picture than kMinPictureContrast.
Drawn DrawFloorColour(SeededRandom& random, const core::Rgb& walls, const core::Rgb& inner_walls,
                      const Light& light) {
  return DrawStandingOut<Drawn>(
      random, [&](double pick) { return DrawFloorColourOfKind(random, pick, walls, light); },
      [&](const Drawn& floor) {
        return PictureContrast(light, walls, floor.colour) >= kMinPictureContrast &&
               PictureContrast(light, inner_walls, floor.colour) >= kMinPictureContrast;
      },
      "floor colour that the camera tells from the walls");
}

}  // namespace

double PictureContrast(const Light& light, const core::Rgb& colour, const core::Rgb& floor) {
  // A vertical face facing the light's way gets the most light, one facing
  // away the ambient alone, and every shade between faces some way round:
  // sampled finely enough (a step of at most 1/kShadeSteps of the light's
  // range) to come within half a grey level of the least.
  constexpr int kShadeSteps = 512;
  const Eigen::Vector3d& d = light.direction;
  const double horizontal = std::hypot(d.x(), d.y()) / d.norm();
  const double up = Shade(light, Eigen::Vector3d::UnitZ());
  const auto lit = [](std::uint8_t channel, double shade) {
    return std::min(255.0, static_cast<double>(channel) * shade);
  };
  const auto contrast = [&](double shade) {
    return std::max({std::abs(lit(colour.r, shade) - lit(floor.r, up)),
                     std::abs(lit(colour.g, shade) - lit(floor.g, up)),
                     std::abs(lit(colour.b, shade) - lit(floor.b, up))});
  };
  double least = contrast(up);  // a top
  for (int i = 0; i <= kShadeSteps; ++i) {
    const double towards = horizontal * static_cast<double>(i) / kShadeSteps;
    least = std::min(least, contrast(light.ambient + light.intensity * towards));
  }
  return least;
}

double Shade(const Light& light, const Eigen::Vector3d& normal) {
  const Eigen::Vector3d& d = light.direction;
  const double towards = -(normal.x() * d.x() + normal.y() * d.y() + normal.z() * d.z()) /
                         std::sqrt(d.x() * d.x() + d.y() * d.y() + d.z() * d.z());
  return light.ambient + light.intensity * std::max(0.0, towards);
}

WorldStyle DrawStyle(SeededRandom& random, const StyleScale& scale) {
  WorldStyle style;
  const Drawn walls = DrawWallColour(random);
  const WallHeight height = DrawWallHeight(random, scale);
  const int thickness_mm = 2 * static_cast<int>(random.Between(scale.wall_thickness_min_mm / 2,
                                                               scale.wall_thickness_max_mm / 2));
  style.walls = {height.metres, thickness_mm / 1000.0, walls.colour};
  style.inner_wall_colour = walls.colour;
  std::string inner;
  if (random.Chance(kInnerWallsOtherColour)) {
    const Drawn other = DrawWallColour(random);
    style.inner_wall_colour = other.colour;
    inner = fmt::format("; inner walls {} {}", other.words, ColourText(other.colour));
  }
  style.light = DrawLight(random);
  const Drawn floor = DrawFloorColour(random, walls.colour, style.inner_wall_colour, style.light);
  style.floor.colour = floor.colour;
  style.floor.texture =
      random.Chance(kNoTexture) ? 0.0 : RoundTo(random.Uniform(kTextureMin, kTextureMax), 2);
  style.description = fmt::format("floor {} {}, texture {}; walls {} {}, {}{}", floor.words,
                                  ColourText(floor.colour), style.floor.texture, walls.words,
                                  ColourText(walls.colour), height.words, inner);
  return style;
}

core::Rgb DrawObstacleColour(SeededRandom& random, const WorldStyle& style) {
  return DrawStandingOut<core::Rgb>(
      random, [&](double pick) { return DrawObstacleColourOfKind(random, pick, style); },
      [&](const core::Rgb& colour) {
        return PictureContrast(style.light, colour, style.floor.colour) >= kMinPictureContrast;
      },
      "obstacle colour that the camera tells from the floor");
}

double DrawObstacleHeight(SeededRandom& random, const StyleScale& scale) {
  if (random.Chance(kObstacleAsHighAsTheCamera)) return RoundTo(scale.camera_height_m, 3);
  return RoundTo(random.Uniform(scale.obstacle_height_min_m, scale.obstacle_height_max_m), 3);
}

}  // namespace pirouette::sim
