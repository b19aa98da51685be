#include "pirouette/sim/scene_mesh.h"

#include <array>
#include <cmath>

#include "pirouette/core/geometry2.h"

namespace pirouette::sim {
namespace {

using core::Cross;

constexpr double kOutsideExtent = 60.0;  // metres of ground drawn around the floor

bool InTriangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                const Eigen::Vector2d& c) {
  return Cross(b - a, p - a) >= 0.0 && Cross(c - b, p - b) >= 0.0 && Cross(a - c, p - c) >= 0.0;
}

class MeshBuilder {
 public:
  void Triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                const Eigen::Vector3d& normal, core::Rgb colour, bool textured) {
    for (const Eigen::Vector3d* p : {&a, &b, &c}) {
      SceneVertex v{};
      for (int i = 0; i < 3; ++i) {
        v.position[i] = static_cast<float>((*p)[i]);
        v.normal[i] = static_cast<float>(normal[i]);
      }
      v.colour[0] = colour.r / 255.0f;
      v.colour[1] = colour.g / 255.0f;
      v.colour[2] = colour.b / 255.0f;
      v.textured = textured ? 1.0f : 0.0f;
      vertices_.push_back(v);
    }
  }

  // An axis-aligned rectangle of the ground plane, facing up.
  void GroundRectangle(double x0, double y0, double x1, double y1, core::Rgb colour,
                       bool textured) {
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d a(x0, y0, 0), b(x1, y0, 0), c(x1, y1, 0), d(x0, y1, 0);
    Triangle(a, b, c, up, colour, textured);
    Triangle(a, c, d, up, colour, textured);
  }

  // The board's squares and its margin, one quad per cell of a
  // (cols + 3) × (rows + 3) grid (the outer ring is the margin), facing up at
  // z = kChessboardLift.
  void Board(const Chessboard& board) {
    const Eigen::Vector2d along(std::cos(board.yaw_rad), std::sin(board.yaw_rad));
    const Eigen::Vector2d across(-along.y(), along.x());
    // The lower left corner of square (0, 0), the board's first square.
    const Eigen::Vector2d origin = board.centre - board.square * ((board.cols + 1) / 2.0 * along +
                                                                  (board.rows + 1) / 2.0 * across);
    const auto at = [&](int i, int j) -> Eigen::Vector3d {
      const Eigen::Vector2d p = origin + board.square * (i * along + j * across);
      return {p.x(), p.y(), kChessboardLift};
    };
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    for (int j = -1; j <= board.rows + 1; ++j) {
      for (int i = -1; i <= board.cols + 1; ++i) {
        const bool on_board = i >= 0 && i <= board.cols && j >= 0 && j <= board.rows;
        const core::Rgb colour = on_board && (i + j) % 2 == 0 ? board.dark : board.light;
        Triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1), up, colour, false);
        Triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1), up, colour, false);
      }
    }
  }

  void Prism(const Solid& solid) {
    const auto& poly = solid.footprint;
    const double h = solid.height;
    for (const auto& t : TriangulatePolygon(poly)) {
      Triangle({poly[t[0]].x(), poly[t[0]].y(), h}, {poly[t[1]].x(), poly[t[1]].y(), h},
               {poly[t[2]].x(), poly[t[2]].y(), h}, Eigen::Vector3d::UnitZ(), solid.colour, false);
    }
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Eigen::Vector2d& p = poly[i];
      const Eigen::Vector2d& q = poly[(i + 1) % poly.size()];
      const Eigen::Vector2d edge = q - p;
      if (edge.norm() == 0.0) continue;
      // Counter-clockwise footprint: the outside is on the edge's right.
      Eigen::Vector3d normal(edge.y(), -edge.x(), 0.0);
      normal.normalize();
      const Eigen::Vector3d p0(p.x(), p.y(), 0), q0(q.x(), q.y(), 0), p1(p.x(), p.y(), h),
          q1(q.x(), q.y(), h);
      Triangle(p0, q0, q1, normal, solid.colour, false);
      Triangle(p0, q1, p1, normal, solid.colour, false);
    }
  }

  std::vector<SceneVertex> Take() { return std::move(vertices_); }

 private:
  std::vector<SceneVertex> vertices_;
};

}  // namespace

std::vector<std::array<int, 3>> TriangulatePolygon(const std::vector<Eigen::Vector2d>& polygon) {
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> remaining(polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i) remaining[i] = static_cast<int>(i);
  // Ear clipping (Meisters 1975): O(n³) at worst, fine for footprints of a few sides.
  while (remaining.size() > 3) {
    bool clipped = false;
    const std::size_t n = remaining.size();
    for (std::size_t i = 0; i < n && !clipped; ++i) {
      const int ia = remaining[(i + n - 1) % n];
      const int ib = remaining[i];
      const int ic = remaining[(i + 1) % n];
      const auto &a = polygon[ia], &b = polygon[ib], &c = polygon[ic];
      if (Cross(b - a, c - b) <= 0.0) continue;  // reflex or degenerate corner
      bool ear = true;
      for (const int j : remaining) {
        if (j != ia && j != ib && j != ic && InTriangle(polygon[j], a, b, c)) {
          ear = false;
          break;
        }
      }
      if (!ear) continue;
      triangles.push_back({ia, ib, ic});
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) break;  // not simple, or collinear leftovers: stop rather than loop
  }
  if (remaining.size() == 3) triangles.push_back({remaining[0], remaining[1], remaining[2]});
  return triangles;
}

std::vector<SceneVertex> BuildSceneMesh(const World& world) {
  MeshBuilder mesh;
  const double x = world.floor().size.x();
  const double y = world.floor().size.y();
  mesh.GroundRectangle(0.0, 0.0, x, y, world.floor().colour, true);
  const double e = kOutsideExtent;
  mesh.GroundRectangle(-e, -e, x + e, 0.0, kOutsideColour, false);
  mesh.GroundRectangle(-e, y, x + e, y + e, kOutsideColour, false);
  mesh.GroundRectangle(-e, 0.0, 0.0, y, kOutsideColour, false);
  mesh.GroundRectangle(x, 0.0, x + e, y, kOutsideColour, false);
  for (const Chessboard& board : world.chessboards()) mesh.Board(board);
  for (const Solid& solid : world.solids()) mesh.Prism(solid);
  return mesh.Take();
}

}  // namespace pirouette::sim
