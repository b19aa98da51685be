// Fuzzes the pose graph's file (g2o text, io/graph_file.h): only
// core::InputError answers a bad file; a graph that parses writes back to a
// text that parses to the same counts.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include "pirouette/core/input_error.h"
#include "pirouette/io/graph_file.h"
#include "pirouette/testing/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(pirouette::testing::FuzzText(data, size));
  std::optional<pirouette::localize::PoseGraph> graph;
  try {
    graph = pirouette::io::ParseG2o(text, "graph.g2o");
  } catch (const pirouette::core::InputError&) {
    return 0;
  }
  // What G2oText writes must parse (an InputError here escapes).
  const pirouette::localize::PoseGraph again =
      pirouette::io::ParseG2o(pirouette::io::G2oText(*graph), "again.g2o");
  if (again.NodeCount() != graph->NodeCount() || again.edges().size() != graph->edges().size()) {
    std::abort();
  }
  return 0;
}
