#include "pirouette/draw/map_picture.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "pirouette/draw/palette.h"

namespace pirouette::draw {
namespace {

// A 1 m square map, all unknown, 4 px a cell; a graph over three stops: two
// odometry edges along the bottom and a loop closure back to the start.
TEST(DrawMapPicture, DrawsTheGraphsEdgesFaintlyAndItsLoopClosuresClearly) {
  const mapping::OccupancyGrid grid(core::GridGeometry(0.01, Eigen::Vector2d::Zero(), 100, 100));
  localize::PoseGraph graph;
  graph.AddNode(core::Pose2(0.2, 0.2, 0.0));
  graph.AddNode(core::Pose2(0.8, 0.2, 0.0));
  graph.AddNode(core::Pose2(0.8, 0.8, 0.0));
  localize::PoseGraphEdge edge;
  edge.from = 0;
  edge.to = 1;
  graph.AddEdge(edge);
  edge.from = 1;
  edge.to = 2;
  graph.AddEdge(edge);
  edge.from = 2;
  edge.to = 0;
  edge.kind = localize::EdgeKind::kLoopClosure;
  graph.AddEdge(edge);

  const cv::Mat3b image = DrawMapPicture(grid, {}, {}, 400, &graph);
  ASSERT_EQ(image.cols, 400);
  // How near the colour the pixels within 3 px of map point (x, y) come
  // (north up, 400 px a metre; lines are antialiased): the least distance.
  const auto nearest = [](const cv::Mat3b& picture, double x, double y, const cv::Vec3b& colour) {
    double best = 1e9;
    for (int dr = -3; dr <= 3; ++dr) {
      for (int dc = -3; dc <= 3; ++dc) {
        const cv::Vec3b p =
            picture(static_cast<int>((1.0 - y) * 400.0) + dr, static_cast<int>(x * 400.0) + dc);
        best = std::min(best, cv::norm(cv::Vec3d(p) - cv::Vec3d(colour)));
      }
    }
    return best;
  };
  constexpr double kNear = 12.0;  // of 441, the distance white to black
  EXPECT_LT(nearest(image, 0.5, 0.2, kOdometryEdgeColour), kNear);
  EXPECT_LT(nearest(image, 0.8, 0.5, kOdometryEdgeColour), kNear);
  EXPECT_LT(nearest(image, 0.5, 0.5, kLoopClosureColour), kNear);
  EXPECT_GT(nearest(image, 0.5, 0.5, kOdometryEdgeColour), kNear);  // no odometry edge there
  const cv::Mat3b without = DrawMapPicture(grid, {}, {}, 400);
  EXPECT_GT(nearest(without, 0.5, 0.5, kLoopClosureColour), kNear);
}

}  // namespace
}  // namespace pirouette::draw
