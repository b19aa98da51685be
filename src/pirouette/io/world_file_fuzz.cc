// Fuzzes the world file (SPEC.md, `pirouette-world/1`) with the files it
// names: the input is world.yaml, camera.yaml, map.yaml and map.pgm, cut at
// testing::kFuzzPartSeparator (a seed's world names `camera: camera.yaml`
// and a grid's `map: map.yaml`). Only core::InputError answers bad files.

#include <cstddef>
#include <cstdint>

#include "pirouette/core/input_error.h"
#include "pirouette/io/world_file.h"
#include "pirouette/testing/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pirouette::testing::FuzzFolder folder;
  folder.Reset();
  const auto parts =
      pirouette::testing::SplitFuzzInput(pirouette::testing::FuzzText(data, size), 4);
  const char* names[] = {"world.yaml", "camera.yaml", "map.yaml", "map.pgm"};
  for (std::size_t i = 0; i < parts.size(); ++i) folder.Write(names[i], parts[i]);
  try {
    (void)pirouette::io::LoadWorldFile((folder.path() / "world.yaml").string());
  } catch (const pirouette::core::InputError&) {
  }
  return 0;
}
