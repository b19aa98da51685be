// Fuzzes a run log (docs/run-log.md, `pirouette-log/1`): the input is
// log.yaml, camera.yaml, frames.csv and frames/000000.png, cut at
// testing::kFuzzPartSeparator. Only core::InputError answers a bad log;
// every row of a log that reads has its frame read (the first one's image
// is the fuzzer's, the others are missing).

#include <cstddef>
#include <cstdint>

#include "pirouette/core/input_error.h"
#include "pirouette/io/run_log.h"
#include "pirouette/testing/fuzz_input.h"

namespace {

// Rows whose frames are read: enough for the first (the one with an image)
// and a few missing ones, without a long csv turning into a slow input.
constexpr std::size_t kRowsRead = 4;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pirouette::testing::FuzzFolder folder;
  folder.Reset();
  const auto parts =
      pirouette::testing::SplitFuzzInput(pirouette::testing::FuzzText(data, size), 4);
  const char* names[] = {"log.yaml", "camera.yaml", "frames.csv", "frames/000000.png"};
  for (std::size_t i = 0; i < parts.size(); ++i) folder.Write(names[i], parts[i]);
  try {
    const pirouette::io::RunLog log = pirouette::io::ReadRunLog(folder.path().string());
    for (std::size_t i = 0; i < log.rows.size() && i < kRowsRead; ++i) {
      try {
        (void)pirouette::io::ReadLogFrame(log, log.rows[i]);
      } catch (const pirouette::core::InputError&) {
      }
    }
  } catch (const pirouette::core::InputError&) {
  }
  return 0;
}
