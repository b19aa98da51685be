// Fuzzes a map_server map (io/map_file.h) and its colour layer: the input is
// map.yaml, map.pgm and map_colours.png, cut at
// testing::kFuzzPartSeparator (a seed's yaml names `image: map.pgm`; the
// image may be any format OpenCV reads). Only core::InputError answers bad
// files; a map that reads has one cell per pixel.

#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "pirouette/core/input_error.h"
#include "pirouette/io/colour_map_file.h"
#include "pirouette/io/map_file.h"
#include "pirouette/testing/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pirouette::testing::FuzzFolder folder;
  folder.Reset();
  const auto parts =
      pirouette::testing::SplitFuzzInput(pirouette::testing::FuzzText(data, size), 3);
  const char* names[] = {"map.yaml", "map.pgm", "map_colours.png"};
  for (std::size_t i = 0; i < parts.size(); ++i) folder.Write(names[i], parts[i]);
  const std::string yaml = (folder.path() / "map.yaml").string();
  try {
    const pirouette::io::MapServerMap map = pirouette::io::ReadMapServerMap(yaml);
    if (map.cells.size() != map.geometry.CellCount()) std::abort();
    (void)pirouette::io::ReadColourMap(pirouette::io::ColourMapPathFor(yaml), map.geometry);
  } catch (const pirouette::core::InputError&) {
  }
  try {
    (void)pirouette::io::ReadRosMap(yaml);
  } catch (const pirouette::core::InputError&) {
  }
  return 0;
}
