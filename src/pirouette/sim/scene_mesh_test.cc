#include "pirouette/sim/scene_mesh.h"

#include <gtest/gtest.h>

#include "pirouette/core/angle.h"

namespace pirouette::sim {
namespace {

using Eigen::Vector2d;

double Area(const std::vector<Vector2d>& poly, const std::vector<std::array<int, 3>>& triangles) {
  double area = 0.0;
  for (const auto& t : triangles) {
    const Vector2d ab = poly[t[1]] - poly[t[0]];
    const Vector2d ac = poly[t[2]] - poly[t[0]];
    const double cross = ab.x() * ac.y() - ab.y() * ac.x();
    EXPECT_GT(cross, 0.0) << "every triangle is counter-clockwise";
    area += 0.5 * cross;
  }
  return area;
}

TEST(TriangulatePolygonTest, ConcavePolygonIsCoveredExactly) {
  // An L: area 3 (a 2×2 square less a 1×1 corner).
  const std::vector<Vector2d> l_shape = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const auto triangles = TriangulatePolygon(l_shape);
  EXPECT_EQ(triangles.size(), l_shape.size() - 2);
  EXPECT_NEAR(Area(l_shape, triangles), 3.0, 1e-12);
}

TEST(TriangulatePolygonTest, TriangleAndConvexPolygon) {
  const std::vector<Vector2d> triangle = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(TriangulatePolygon(triangle).size(), 1u);
  std::vector<Vector2d> hexagon;
  for (int i = 0; i < 6; ++i) {
    const double a = core::DegToRad(60.0 * i);
    hexagon.emplace_back(std::cos(a), std::sin(a));
  }
  EXPECT_NEAR(Area(hexagon, TriangulatePolygon(hexagon)), 1.5 * std::sqrt(3.0), 1e-12);
}

TEST(SceneMeshTest, FloorGroundAndPrismsWithOutwardNormals) {
  const camera::CameraModel camera("c", 320, 240, {277, 277, 159.5, 119.5}, {}, {0.1, 0.5, 0.0},
                                   {});
  const Solid box = MakeBox({1.0, 1.0}, {0.2, 0.4}, 0.3, 0.1, core::Rgb{200, 0, 0});
  const World world("mesh", Floor{{2.0, 2.0}, core::Rgb{20, 20, 20}, 0.1}, std::nullopt, {box},
                    Light{}, RobotSpec{core::Pose2(0.3, 0.3, 0), 0.04, camera, {}});
  const auto mesh = BuildSceneMesh(world);
  // Floor 2 + ground around it 4×2 + box top 2 + box sides 4×2 triangles.
  ASSERT_EQ(mesh.size(), 3u * (2 + 8 + 2 + 8));
  EXPECT_EQ(mesh[0].textured, 1.0f);
  int sides = 0;
  for (std::size_t i = 0; i < mesh.size(); i += 3) {
    const Eigen::Vector3f normal(mesh[i].normal);
    EXPECT_NEAR(normal.norm(), 1.0f, 1e-6f);
    if (std::abs(normal.z()) > 0.5f) continue;
    ++sides;
    // A side's normal points away from the box's centre.
    const Eigen::Vector2f centre(1.0f, 1.0f);
    const Eigen::Vector2f on_face(mesh[i].position[0], mesh[i].position[1]);
    EXPECT_GT(normal.head<2>().dot(on_face - centre), 0.0f);
  }
  EXPECT_EQ(sides, 8);
}

}  // namespace
}  // namespace pirouette::sim
