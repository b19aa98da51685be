#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "pirouette/sim/world.h"

namespace pirouette::sim {

// One vertex of the flat-shaded triangle list that the renderer draws.
struct SceneVertex {
  float position[3];  // world frame, metres
  float normal[3];    // the face's outward unit normal
  float colour[3];    // albedo, 0..1
  float textured;     // 1 on the floor (its grain applies), else 0
};

// The colour of the ground beyond the floor's rectangle (seen where a world
// has no boundary walls): a neutral grey that differs from most floors.
inline constexpr core::Rgb kOutsideColour{120, 120, 120};

// How far above the floor a chessboard is drawn, so that the depth test never
// confuses it with the floor beneath (0.2 mm: below what any view resolves,
// far above the depth buffer's resolution within a few metres).
inline constexpr double kChessboardLift = 0.0002;

// The world as triangles: the floor, the ground around it, the chessboards
// (Chessboard: squares and margin, kChessboardLift above the floor), and every
// solid as a prism (its top and its sides; the bottom is never seen).
std::vector<SceneVertex> BuildSceneMesh(const World& world);

// Triangulates a simple counter-clockwise polygon by ear clipping; returns
// index triples into `polygon`.
std::vector<std::array<int, 3>> TriangulatePolygon(const std::vector<Eigen::Vector2d>& polygon);

}  // namespace pirouette::sim
