#include "pirouette/sim/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <optional>
#include <vector>

#include "pirouette/core/angle.h"

namespace pirouette::sim {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// The paper's camera (worlds/yujin.yaml): 320×240, 60° across, barrel
// distortion, 0.11 m up, tilted 30° down, vignetting.
camera::CameraModel PaperCamera() {
  return camera::CameraModel("yujin", 320, 240, {277.13, 277.13, 159.5, 119.5},
                             {-0.20, 0.05, 0.0, 0.0, 0.0}, {0.11, core::DegToRad(30.0), 0.03},
                             {{0.35, 0.30, 0.40}});
}

World MakeWorld(Vector2d floor_size, core::Rgb floor_colour, std::vector<Solid> obstacles,
                const camera::CameraModel& camera) {
  Floor floor{floor_size, floor_colour, 0.0};
  RobotSpec robot{core::Pose2(floor_size.x() / 2, floor_size.y() / 2, 0.0), 0.04, camera, {}};
  return World("renderer-test", floor, std::nullopt, std::move(obstacles), Light{}, robot);
}

// The shade the renderer gives a face with this normal under the world's
// light: ambient + intensity · max(0, n · towards-light).
double Shade(const Light& light, const Vector3d& normal) {
  return light.ambient + light.intensity * std::max(0.0, normal.dot(-light.direction.normalized()));
}

// The image row, with sub-pixel precision, where column u's red channel
// crosses `level` going up from the bottom of the image.
std::optional<double> CrossingRow(const core::ImageRgb8& image, int u, double level) {
  for (int v = image.height() - 1; v > 0; --v) {
    const double below = image.At(u, v).r;
    const double above = image.At(u, v - 1).r;
    if ((below - level) * (above - level) <= 0.0 && below != above) {
      return v - (level - below) / (above - below);
    }
  }
  return std::nullopt;
}

TEST(RendererTest, BoxBottomEdgeLiesWhereTheCameraModelProjectsIt) {
  const camera::CameraModel camera = PaperCamera();
  // A box 0.25 m ahead of the robot, yawed so that its front edge runs
  // across the image at a slant; the robot at the floor's centre faces +x.
  const Vector2d robot_xy(1.0, 1.0);
  const double yaw = core::DegToRad(12.0);
  Solid box = MakeBox(robot_xy + Vector2d(0.30, 0.0), Vector2d(0.10, 0.30), yaw, 0.08,
                      core::Rgb{220, 30, 30});
  const World world = MakeWorld({2.0, 2.0}, core::Rgb{25, 25, 25}, {box}, camera);
  RenderOptions options;
  options.noise_sigma = 0.0;
  Renderer renderer(world, camera, options);
  const core::Pose2 world_T_robot(robot_xy.x(), robot_xy.y(), 0.0);
  const core::ImageRgb8 image = renderer.Render(world_T_robot);

  // The box's front face: the footprint edge nearest the robot, whose
  // outward normal points back at it (-x, turned by the yaw).
  const Vector2d normal_2d(-std::cos(yaw), -std::sin(yaw));
  const Vector2d along(-std::sin(yaw), std::cos(yaw));
  const Vector2d face_centre = robot_xy + Vector2d(0.30, 0.0) + 0.05 * normal_2d;
  const double face_red = 220.0 * Shade(world.light(), Vector3d(normal_2d.x(), normal_2d.y(), 0));
  const double floor_red = 25.0 * Shade(world.light(), Vector3d::UnitZ());

  // The edge's image, densely sampled; for each integer column its row by
  // linear interpolation between the samples on either side.
  const Eigen::Isometry3d camera_T_robot = camera.robot_T_camera().inverse();
  std::vector<Vector2d> curve;
  for (double s = -0.12; s <= 0.12; s += 0.0005) {
    const Vector2d p_robot = world_T_robot.Inverse() * (face_centre + s * along);
    const auto pixel = camera.Project(camera_T_robot * Vector3d(p_robot.x(), p_robot.y(), 0.0));
    ASSERT_TRUE(pixel.has_value());
    curve.push_back(*pixel);
  }
  int checked = 0;
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const Vector2d a = curve[i];
    const Vector2d b = curve[i + 1];
    const double u = std::ceil(std::min(a.x(), b.x()));
    if (u > std::max(a.x(), b.x()) || u < 2 || u >= camera.width() - 2) continue;
    const double expected_v = a.y() + (b.y() - a.y()) * (u - a.x()) / (b.x() - a.x());
    // Vignetting darkens both sides of the edge alike: the 50% level between them.
    const double gain = camera.VignettingGain(0, {u, expected_v});
    const auto row = CrossingRow(image, static_cast<int>(u), 0.5 * (face_red + floor_red) * gain);
    ASSERT_TRUE(row.has_value()) << "no edge in column " << u;
    EXPECT_NEAR(*row, expected_v, 1.0) << "column " << u;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

// A fisheye (equidistant) of about 150° across and a wide-angle lens
// (rational_polynomial), 0.11 m up and tilted 30° down as the paper's.
camera::CameraModel FisheyeCamera() {
  const std::vector<double> k = {0.04, -0.012, 0.003, -0.0005};
  return camera::CameraModel(
      "fisheye", 320, 240, {117.0, 117.0, 159.5, 119.5},
      *camera::Distortion::FromCoefficients(camera::Distortion::Model::kEquidistant, k),
      {0.11, core::DegToRad(30.0), 0.03}, {});
}

camera::CameraModel WideAngleCamera() {
  const std::vector<double> k = {0.1, 0.01, 0.001, -0.0008, 0.0005, 0.45, 0.02, 0.0001};
  return camera::CameraModel(
      "wide", 320, 240, {208.0, 208.0, 159.5, 119.5},
      *camera::Distortion::FromCoefficients(camera::Distortion::Model::kRationalPolynomial, k),
      {0.11, core::DegToRad(30.0), 0.03}, {});
}

class WideLensRendererTest : public ::testing::TestWithParam<camera::CameraModel (*)()> {};

// Rendered, a box's bottom edge lies where the model projects it; the inverse
// perspective map takes the rendered edge back to the edge on the floor, and
// every floor point on it projects and back-projects to itself.
TEST_P(WideLensRendererTest, BoxBottomEdgeProjectsAndBackProjectsToItself) {
  const camera::CameraModel camera = GetParam()();
  const Vector2d robot_xy(1.5, 1.5);
  const double yaw = core::DegToRad(12.0);
  const Solid box = MakeBox(robot_xy + Vector2d(0.30, 0.0), Vector2d(0.10, 0.70), yaw, 0.08,
                            core::Rgb{220, 30, 30});
  const World world = MakeWorld({3.0, 3.0}, core::Rgb{25, 25, 25}, {box}, camera);
  RenderOptions options;
  options.noise_sigma = 0.0;
  Renderer renderer(world, camera, options);
  const core::Pose2 world_T_robot(robot_xy.x(), robot_xy.y(), 0.0);
  const core::ImageRgb8 image = renderer.Render(world_T_robot);

  const Vector2d normal_2d(-std::cos(yaw), -std::sin(yaw));
  const Vector2d along(-std::sin(yaw), std::cos(yaw));
  const Vector2d face_centre = robot_xy + Vector2d(0.30, 0.0) + 0.05 * normal_2d;
  const double face_red = 220.0 * Shade(world.light(), Vector3d(normal_2d.x(), normal_2d.y(), 0));
  const double floor_red = 25.0 * Shade(world.light(), Vector3d::UnitZ());
  const Vector2d face_robot = world_T_robot.Inverse() * face_centre;
  const Vector2d along_robot = along;  // the robot faces the world's +x

  const Eigen::Isometry3d camera_T_robot = camera.robot_T_camera().inverse();
  std::vector<Vector2d> curve;
  for (double s = -0.34; s <= 0.34; s += 0.0005) {
    const Vector2d p_robot = face_robot + s * along_robot;
    const auto pixel = camera.Project(camera_T_robot * Vector3d(p_robot.x(), p_robot.y(), 0.0));
    ASSERT_TRUE(pixel.has_value());
    const std::optional<Vector2d> back = camera.FloorPoint(*pixel);
    ASSERT_TRUE(back.has_value()) << pixel->transpose();
    EXPECT_NEAR((*back - p_robot).norm(), 0.0, 1e-9) << pixel->transpose();
    curve.push_back(*pixel);
  }
  int checked = 0;
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const Vector2d a = curve[i];
    const Vector2d b = curve[i + 1];
    const double u = std::ceil(std::min(a.x(), b.x()));
    if (u > std::max(a.x(), b.x()) || u < 2 || u >= camera.width() - 2) continue;
    const double expected_v = a.y() + (b.y() - a.y()) * (u - a.x()) / (b.x() - a.x());
    const auto row = CrossingRow(image, static_cast<int>(u), 0.5 * (face_red + floor_red));
    ASSERT_TRUE(row.has_value()) << "no edge in column " << u;
    EXPECT_NEAR(*row, expected_v, 1.0) << "column " << u;
    // The rendered edge's floor point lies on the edge, within a pixel's reach.
    const std::optional<Vector2d> floor = camera.FloorPoint({u, *row});
    ASSERT_TRUE(floor.has_value());
    const Vector2d offset = *floor - face_robot;
    EXPECT_NEAR(offset.x() * along_robot.y() - offset.y() * along_robot.x(), 0.0, 0.01)
        << "column " << u;
    ++checked;
  }
  EXPECT_GT(checked, 150);
}

INSTANTIATE_TEST_SUITE_P(Lenses, WideLensRendererTest,
                         ::testing::Values(&FisheyeCamera, &WideAngleCamera));

TEST(RendererTest, AFisheyesCornersBeyondItsImageCircleAreBlack) {
  const camera::CameraModel camera = FisheyeCamera();
  const World world = MakeWorld({30.0, 30.0}, core::Rgb{200, 200, 200}, {}, camera);
  RenderOptions options;
  options.noise_sigma = 0.0;
  Renderer renderer(world, camera, options);
  const core::ImageRgb8 image = renderer.Render(core::Pose2(15.0, 15.0, 0.0));
  // The bottom corners' rays lie about 90° off the axis: not rendered.
  EXPECT_FALSE(camera.SeenRay({0.0, 239.0}).has_value() &&
               camera.SeenRay({0.0, 239.0})->z() > std::cos(core::DegToRad(80.0)));
  EXPECT_EQ(image.At(0, 239).r, 0);
  // The floor straight below the centre is seen.
  EXPECT_GT(image.At(160, 200).r, 100);
}

TEST(RendererTest, FloorHasTheFloorsColourWithinTheNoise) {
  const camera::CameraModel camera = PaperCamera();
  const core::Rgb floor_colour{150, 110, 70};
  const World world = MakeWorld({30.0, 30.0}, floor_colour, {}, camera);
  RenderOptions options;
  options.noise_sigma = 2.0;
  options.seed = 7;
  Renderer renderer(world, camera, options);
  const core::ImageRgb8 image = renderer.Render(core::Pose2(15.0, 15.0, 0.3));

  const double shade = Shade(world.light(), Vector3d::UnitZ());
  const std::array<double, 3> truth = {floor_colour.r * shade, floor_colour.g * shade,
                                       floor_colour.b * shade};
  std::array<double, 3> sum{}, sum_sq{};
  int n = 0;
  // The rows that see the floor (all but the top few, which see near the horizon).
  for (int v = 60; v < camera.height(); ++v) {
    for (int u = 0; u < camera.width(); ++u) {
      const Vector2d pixel(u, v);
      const std::uint8_t* p = image.Pixel(u, v);
      for (int c = 0; c < 3; ++c) {
        const double residual = p[c] - truth[c] * camera.VignettingGain(c, pixel);
        sum[c] += residual;
        sum_sq[c] += residual * residual;
      }
      ++n;
    }
  }
  for (int c = 0; c < 3; ++c) {
    const double mean = sum[c] / n;
    const double sd = std::sqrt(sum_sq[c] / n - mean * mean);
    EXPECT_NEAR(mean, 0.0, 0.5) << "channel " << c;
    // Gaussian noise of σ = 2 plus quantisation (1/√12).
    EXPECT_NEAR(sd, std::sqrt(4.0 + 1.0 / 12.0), 0.25) << "channel " << c;
  }
}

TEST(RendererTest, CornersAreDarkenedByTheConfiguredVignetting) {
  const camera::CameraModel camera = PaperCamera();
  const World world = MakeWorld({30.0, 30.0}, core::Rgb{200, 200, 200}, {}, camera);
  RenderOptions options;
  options.noise_sigma = 0.0;
  Renderer renderer(world, camera, options);
  const core::ImageRgb8 image = renderer.Render(core::Pose2(15.0, 15.0, 0.0));

  const int w = camera.width();
  const int h = camera.height();
  const auto mean_around = [&](int u0, int v0, int c) {
    double s = 0.0;
    for (int dv = 0; dv < 3; ++dv) {
      for (int du = 0; du < 3; ++du) s += image.Pixel(u0 + du, v0 + dv)[c];
    }
    return s / 9.0;
  };
  for (int c = 0; c < 3; ++c) {
    const double centre = mean_around(w / 2 - 1, h / 2 - 1, c);
    for (const auto& [u, v] : std::vector<std::pair<int, int>>{{0, h - 3}, {w - 3, h - 3}}) {
      const double expected = camera.VignettingGain(c, {u + 1.0, v + 1.0}) /
                              camera.VignettingGain(c, {w / 2.0, h / 2.0});
      EXPECT_NEAR(mean_around(u, v, c) / centre, expected, 0.02)
          << "channel " << c << " corner (" << u << ", " << v << ")";
      EXPECT_LT(mean_around(u, v, c) / centre, 0.8);
    }
  }
}

TEST(RendererTest, SameSeedSameImagesOtherSeedOtherNoise) {
  const camera::CameraModel camera = PaperCamera();
  const World world =
      MakeWorld({3.0, 3.0}, core::Rgb{60, 60, 60},
                {MakeCylinder({2.0, 1.5}, 0.1, 0.1, core::Rgb{30, 160, 30})}, camera);
  const core::Pose2 pose(1.0, 1.4, 0.1);
  RenderOptions a;
  a.seed = 3;
  RenderOptions b = a;
  b.seed = 4;
  Renderer first(world, camera, a);
  Renderer second(world, camera, a);
  Renderer other(world, camera, b);
  const core::ImageRgb8 i1 = first.Render(pose);
  const core::ImageRgb8 i2 = second.Render(pose);
  const core::ImageRgb8 i3 = other.Render(pose);
  const core::ImageRgb8 i4 = first.Render(pose);  // the next frame: new noise
  const auto equal = [](const core::ImageRgb8& x, const core::ImageRgb8& y) {
    return std::equal(x.data(), x.data() + x.size_bytes(), y.data());
  };
  EXPECT_TRUE(equal(i1, i2));
  EXPECT_FALSE(equal(i1, i3));
  EXPECT_FALSE(equal(i1, i4));
}

TEST(RendererTest, ChessboardSquaresAreDarkAndLightWhereTheyLie) {
  // The paper's camera, higher and looking down steeply.
  const camera::CameraModel camera("steep", 320, 240, {277.13, 277.13, 159.5, 119.5},
                                   {-0.20, 0.05, 0.0, 0.0, 0.0}, {0.30, core::DegToRad(60.0), 0.03},
                                   {{0.35, 0.30, 0.40}});
  Floor floor{{2.0, 2.0}, core::Rgb{120, 120, 120}, 0.0};
  const Vector2d robot_xy(1.0, 1.0);
  Chessboard board;
  board.centre = robot_xy + Vector2d(0.20, 0.0);
  board.cols = 5;
  board.rows = 4;
  board.square = 0.025;
  board.yaw_rad = core::DegToRad(20.0);
  RobotSpec robot{core::Pose2(robot_xy.x(), robot_xy.y(), 0.0), 0.04, camera, {}};
  const World world("chessboard", floor, std::nullopt, {}, Light{}, robot, {board});
  EXPECT_TRUE(world.obstacles().empty());
  EXPECT_TRUE(world.solids().empty());
  RenderOptions options;
  options.noise_sigma = 0.0;
  Renderer renderer(world, camera, options);
  const core::Pose2 world_T_robot(robot_xy.x(), robot_xy.y(), 0.0);
  const core::ImageRgb8 image = renderer.Render(world_T_robot);

  const Eigen::Isometry3d camera_T_robot = camera.robot_T_camera().inverse();
  const auto pixel_of = [&](const Vector2d& p_world) {
    const Vector2d p_robot = world_T_robot.Inverse() * p_world;
    return camera.Project(camera_T_robot * Vector3d(p_robot.x(), p_robot.y(), 0.0));
  };
  // Square (i, j), i in [0, cols], j in [0, rows], is centred half a square
  // below and left of inner corner (i, j); the squares with i + j even are dark.
  // Beyond them, the margin is light and the floor grey.
  int dark = 0;
  int light = 0;
  for (int j = -1; j <= board.rows + 1; ++j) {
    for (int i = -1; i <= board.cols + 1; ++i) {
      const Vector2d centre =
          board.InnerCorner(i, j) - 0.5 * (board.InnerCorner(1, 1) - board.InnerCorner(0, 0));
      const auto pixel = pixel_of(centre);
      ASSERT_TRUE(pixel.has_value());
      const int u = static_cast<int>(std::lround(pixel->x()));
      const int v = static_cast<int>(std::lround(pixel->y()));
      ASSERT_TRUE(u >= 0 && u < camera.width() && v >= 0 && v < camera.height())
          << "square (" << i << ", " << j << ") is out of view";
      const double value = image.At(u, v).g / camera.VignettingGain(1, *pixel);
      const bool on_board = i >= 0 && i <= board.cols && j >= 0 && j <= board.rows;
      if (on_board && (i + j) % 2 == 0) {
        EXPECT_LT(value, 40.0) << "square (" << i << ", " << j << ")";
        ++dark;
      } else {
        EXPECT_GT(value, 200.0) << "square (" << i << ", " << j << ")";
        ++light;
      }
    }
  }
  EXPECT_EQ(dark, 15);
  EXPECT_EQ(light, 8 * 7 - 15);
  // Beyond the margin: the floor's grey.
  const auto beyond = pixel_of(board.centre + Vector2d(0.0, 0.13));
  ASSERT_TRUE(beyond.has_value());
  const double grey = image
                          .At(static_cast<int>(std::lround(beyond->x())),
                              static_cast<int>(std::lround(beyond->y())))
                          .g /
                      camera.VignettingGain(1, *beyond);
  EXPECT_NEAR(grey, 120.0 * Shade(world.light(), Vector3d::UnitZ()), 4.0);
}

}  // namespace
}  // namespace pirouette::sim
