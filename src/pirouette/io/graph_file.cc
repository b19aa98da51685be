#include "pirouette/io/graph_file.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "pirouette/core/input_error.h"

namespace pirouette::io {
namespace {

constexpr const char* kLoopClosures = "# loop closures";

void WriteEdge(std::string& out, const localize::PoseGraphEdge& e) {
  const Eigen::Matrix3d& i = e.information;
  out += fmt::format("EDGE_SE2 {} {} {} {} {} {} {} {} {} {} {}\n", e.from, e.to, e.from_T_to.x(),
                     e.from_T_to.y(), e.from_T_to.heading(), i(0, 0), i(0, 1), i(0, 2), i(1, 1),
                     i(1, 2), i(2, 2));
}

// `count` finite numbers from the rest of the line.
std::vector<double> Numbers(std::istringstream& in, std::size_t count, const std::string& path,
                            int line, const std::string& tag) {
  std::vector<double> values;
  std::string word;
  while (in >> word) {
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(word, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != word.size() || !std::isfinite(v)) {
      throw core::InputError(path, line, tag, fmt::format("'{}' is not a finite number", word));
    }
    values.push_back(v);
  }
  if (values.size() != count) {
    throw core::InputError(path, line, tag,
                           fmt::format("expected {} numbers, got {}", count, values.size()));
  }
  return values;
}

int Id(double v, const std::string& path, int line, const std::string& tag) {
  if (v != std::floor(v) || v < 0.0 || v > 1e9) {
    throw core::InputError(path, line, tag, fmt::format("{} is not a node id", v));
  }
  return static_cast<int>(v);
}

}  // namespace

std::string G2oText(const localize::PoseGraph& graph) {
  std::string out;
  for (std::size_t id = 0; id < graph.NodeCount(); ++id) {
    const core::Pose2& p = graph.poses()[id];
    out += fmt::format("VERTEX_SE2 {} {} {} {}\n", id, p.x(), p.y(), p.heading());
  }
  for (const localize::PoseGraphEdge& e : graph.edges()) {
    if (e.kind != localize::EdgeKind::kLoopClosure) WriteEdge(out, e);
  }
  out += std::string(kLoopClosures) + "\n";
  for (const localize::PoseGraphEdge& e : graph.edges()) {
    if (e.kind == localize::EdgeKind::kLoopClosure) WriteEdge(out, e);
  }
  return out;
}

localize::PoseGraph ParseG2o(const std::string& text, const std::string& path) {
  localize::PoseGraph graph;
  std::istringstream lines(text);
  bool closures = false;
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == kLoopClosures) {
      closures = true;
      continue;
    }
    std::istringstream in(line);
    std::string tag;
    if (!(in >> tag) || tag[0] == '#') continue;
    if (tag == "VERTEX_SE2") {
      const std::vector<double> v = Numbers(in, 4, path, number, tag);
      const int id = Id(v[0], path, number, tag);
      if (id != static_cast<int>(graph.NodeCount())) {
        throw core::InputError(
            path, number, tag,
            fmt::format("node {} out of order: expected {}", id, graph.NodeCount()));
      }
      graph.AddNode(core::Pose2(v[1], v[2], v[3]));
    } else if (tag == "EDGE_SE2") {
      const std::vector<double> v = Numbers(in, 11, path, number, tag);
      localize::PoseGraphEdge edge;
      edge.from = Id(v[0], path, number, tag);
      edge.to = Id(v[1], path, number, tag);
      edge.from_T_to = core::Pose2(v[2], v[3], v[4]);
      edge.information << v[5], v[6], v[7], v[6], v[8], v[9], v[7], v[9], v[10];
      edge.kind = localize::EdgeKind::kScanMatch;
      if (closures) {
        edge.kind = localize::EdgeKind::kLoopClosure;
      } else if (edge.to == edge.from + 1) {
        bool has_odometry = false;
        for (const localize::PoseGraphEdge& e : graph.edges()) {
          has_odometry = has_odometry || (e.kind == localize::EdgeKind::kOdometry &&
                                          e.from == edge.from && e.to == edge.to);
        }
        if (!has_odometry) edge.kind = localize::EdgeKind::kOdometry;
      }
      try {
        graph.AddEdge(edge);
      } catch (const std::invalid_argument& e) {
        throw core::InputError(path, number, tag, e.what());
      }
    } else {
      throw core::InputError(path, number, tag,
                             "unknown tag (expected VERTEX_SE2, EDGE_SE2 or a # comment)");
    }
  }
  return graph;
}

}  // namespace pirouette::io
