#include "pirouette/io/graph_file.h"

#include <gtest/gtest.h>

#include <string>

#include "pirouette/core/input_error.h"

// Its own namespace: the unit tests compile together (unity batches).
namespace pirouette::io::graph_file_test {
namespace {

localize::PoseGraph SmallGraph() {
  localize::PoseGraph graph;
  graph.AddNode(core::Pose2(0.0, 0.0, 0.0));
  graph.AddNode(core::Pose2(0.5, 0.01, 0.1));
  graph.AddNode(core::Pose2(0.9, 0.3, 1.2));
  Eigen::Matrix3d info;
  info << 400, 10, 1, 10, 300, 2, 1, 2, 50;
  graph.AddEdge({0, 1, core::Pose2(0.5, 0.0, 0.1), info, localize::EdgeKind::kOdometry});
  graph.AddEdge({1, 2, core::Pose2(0.4, 0.3, 1.1), info, localize::EdgeKind::kOdometry});
  graph.AddEdge({0, 1, core::Pose2(0.49, 0.01, 0.1), info, localize::EdgeKind::kScanMatch});
  graph.AddEdge({2, 0, core::Pose2(-0.1, 1.0, -1.2), info, localize::EdgeKind::kLoopClosure});
  return graph;
}

TEST(GraphFileTest, WritesG2oLinesWithTheClosuresAfterTheirComment) {
  const std::string text = G2oText(SmallGraph());
  EXPECT_EQ(text.substr(0, text.find('\n')), "VERTEX_SE2 0 0 0 0");
  EXPECT_NE(text.find("VERTEX_SE2 1 0.5 0.01 0.1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("EDGE_SE2 0 1 0.5 0 0.1 400 10 1 300 2 50\n"), std::string::npos) << text;
  EXPECT_LT(text.find("EDGE_SE2 0 1 0.49"), text.find("# loop closures"));
  EXPECT_GT(text.find("EDGE_SE2 2 0 -0.1 1 -1.2"), text.find("# loop closures"));
}

TEST(GraphFileTest, ReadsBackTheSameGraph) {
  const localize::PoseGraph graph = SmallGraph();
  const localize::PoseGraph back = ParseG2o(G2oText(graph), "graph.g2o");
  ASSERT_EQ(back.NodeCount(), graph.NodeCount());
  for (std::size_t i = 0; i < graph.NodeCount(); ++i) {
    EXPECT_EQ(back.poses()[i].translation(), graph.poses()[i].translation());
    EXPECT_EQ(back.poses()[i].heading(), graph.poses()[i].heading());
  }
  ASSERT_EQ(back.edges().size(), graph.edges().size());
  for (std::size_t i = 0; i < graph.edges().size(); ++i) {
    EXPECT_EQ(back.edges()[i].kind, graph.edges()[i].kind) << i;
    EXPECT_EQ(back.edges()[i].information, graph.edges()[i].information) << i;
  }
  EXPECT_EQ(G2oText(back), G2oText(graph));
}

TEST(GraphFileTest, BadLinesAreNamed) {
  const auto line_of = [](const std::string& text) {
    try {
      ParseG2o(text, "g.g2o");
    } catch (const core::InputError& e) {
      EXPECT_EQ(e.file(), "g.g2o");
      return e.line();
    }
    ADD_FAILURE() << "no InputError for: " << text;
    return -1;
  };
  EXPECT_EQ(line_of("VERTEX_SE2 0 0 0 0\nVERTEX_XY 1 0 0\n"), 2);
  EXPECT_EQ(line_of("VERTEX_SE2 0 0 0\n"), 1);
  EXPECT_EQ(line_of("VERTEX_SE2 0 0 0 nan\n"), 1);
  EXPECT_EQ(line_of("VERTEX_SE2 1 0 0 0\n"), 1);
  EXPECT_EQ(line_of("VERTEX_SE2 0 0 0 0\nEDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n"), 2);
  EXPECT_EQ(line_of("VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 0 0 0\nEDGE_SE2 0 1 1 0 0 -1 0 0 1 0 1\n"),
            3);
  EXPECT_EQ(line_of("VERTEX_SE2 0.5 0 0 0\n"), 1);
}

}  // namespace
}  // namespace pirouette::io::graph_file_test
