// Fuzzes the place table's file (io/place_table_file.h,
// `pirouette-places/1`): the input is the file. Only core::InputError
// answers a bad file; a table that loads saves and loads back, the same size.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>

#include "pirouette/core/input_error.h"
#include "pirouette/io/place_table_file.h"
#include "pirouette/testing/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pirouette::testing::FuzzFolder folder;
  folder.Reset();
  const std::string path = folder.Write("places.yaml", pirouette::testing::FuzzText(data, size));
  try {
    const pirouette::localize::PlaceTable table = pirouette::io::LoadPlaceTable(path);
    const std::string again = (folder.path() / "again.yaml").string();
    pirouette::io::SavePlaceTable(table, again);
    if (pirouette::io::LoadPlaceTable(again).entries().size() != table.entries().size()) {
      std::abort();
    }
  } catch (const pirouette::core::InputError&) {
  }
  return 0;
}
