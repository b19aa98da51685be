#pragma once

#include <string>

#include "pirouette/localize/pose_graph.h"

// The pose graph on disk (SPEC.md, "The pose graph"): g2o's text format,
// which g2o, Ceres' pose_graph_2d example and other SLAM tools read.

namespace pirouette::io {

// The text of DIR/graph.g2o: a line `VERTEX_SE2 id x y theta` a node (metres,
// radians, the map frame), then `EDGE_SE2 from to dx dy dtheta I11 I12 I13
// I22 I23 I33` an edge (the relative pose of `to` seen from `from` and the
// upper triangle of its information matrix), odometry and scan-match edges
// first, then the comment line `# loop closures` and the loop closures.
// Numbers are written as the shortest decimals that read back the same.
std::string G2oText(const localize::PoseGraph& graph);

// Reads G2oText's format back: the nodes in id order (ids 0, 1, ... each
// once, before the edges that name them), the edges after `# loop closures`
// as loop closures, the others as odometry where they join consecutive ids
// and no odometry edge joins them yet, else as scan matches. Other comment
// lines and blank lines are skipped. Throws core::InputError naming `path`
// and the line for an unknown tag, a wrong count of numbers, a number that
// does not parse or is not finite, an id out of order or unknown, and an
// information matrix that is not positive definite.
localize::PoseGraph ParseG2o(const std::string& text, const std::string& path);

}  // namespace pirouette::io
