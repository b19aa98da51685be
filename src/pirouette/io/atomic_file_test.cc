#include "pirouette/io/atomic_file.h"
#include "pirouette/testing/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace pirouette::io {
namespace {

std::string ReadAll(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AtomicFileTest, WritesAndReplacesWithoutLeavingTemporaries) {
  const testing::TempDir temp("pirouette_atomic_file");
  const std::filesystem::path& dir = temp.path();
  const auto path = dir / "out.txt";
  WriteFileAtomically(path.string(), "first");
  WriteFileAtomically(path.string(), "second, longer");
  EXPECT_EQ(ReadAll(path), "second, longer");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

TEST(AtomicFileTest, MissingFolderIsAClearError) {
  try {
    WriteFileAtomically("/nonexistent-folder/x/out.txt", "x");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/x/out.txt"), std::string::npos);
  }
}

}  // namespace
}  // namespace pirouette::io
