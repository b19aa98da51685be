#include "pirouette/io/yaml_fields.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "pirouette/core/input_error.h"
#include "pirouette/testing/input_error.h"

namespace pirouette::io {
namespace {

constexpr char kFile[] = "test.yaml";

// The document in `text` as the root field (path "", at its line).
YamlField Root(const std::string& text) {
  const YAML::Node node = ParseYaml(text, kFile);
  return {node, "", LineOf(node)};
}

using testing::ExpectInputError;

TEST(YamlFieldsTest, ScalarKindsFollowTheCoreSchema) {
  const YAML::Node node = YAML::Load(
      "[1, -2.5e3, +.5, .inf, -.NaN, 0x1F, 1e, yes, 'true', True, ~, null, '', '42', abc]");
  const std::vector<ScalarKind> expected = {
      ScalarKind::kNumber, ScalarKind::kNumber, ScalarKind::kNumber, ScalarKind::kNumber,
      ScalarKind::kNumber, ScalarKind::kString, ScalarKind::kString, ScalarKind::kString,
      ScalarKind::kString, ScalarKind::kBool,   ScalarKind::kNull,   ScalarKind::kNull,
      ScalarKind::kString, ScalarKind::kString, ScalarKind::kString};
  ASSERT_EQ(node.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(ScalarKindOf(node[i]), expected[i]) << "item " << i << ": " << node[i].Scalar();
  }
}

TEST(YamlFieldsTest, DescribeNodeSaysWhatANodeIs) {
  const YAML::Node node = YAML::Load("{a: [1], b: {c: 1}, d: 3, e: false, f: '3', g: ~}");
  EXPECT_EQ(DescribeNode(node["a"]), "a list");
  EXPECT_EQ(DescribeNode(node["b"]), "a map");
  EXPECT_EQ(DescribeNode(node["d"]), "the number 3");
  EXPECT_EQ(DescribeNode(node["e"]), "the boolean false");
  EXPECT_EQ(DescribeNode(node["f"]), "the string '3'");
  EXPECT_EQ(DescribeNode(node["g"]), "nothing");
  EXPECT_EQ(DescribeNode(node["missing"]), "nothing");
}

TEST(YamlFieldsTest, MapFieldsCarryTheirPathAndLine) {
  const YamlMap root(kFile, Root("top:\n  x: 1\n  empty:\n  y: 2\n"));
  const YamlMap top(kFile, root.Required("top"));
  const YamlField y = top.Required("y");
  EXPECT_EQ(y.path, "top.y");
  EXPECT_EQ(y.line, 4);
  // A null value is reported at its key's line, not where the next token starts.
  EXPECT_EQ(top.Optional("empty")->line, 3);
  EXPECT_FALSE(top.Optional("z").has_value());
  ASSERT_EQ(top.Keys().size(), 3U);
  EXPECT_EQ(top.Keys()[1].name, "empty");
  EXPECT_EQ(top.Keys()[1].line, 3);
}

TEST(YamlFieldsTest, MissingKeyIsReportedAtTheMap) {
  const YamlMap root(kFile, Root("a: 0\ntop:\n  x: 1\n"));
  const YamlField top = root.Required("top");
  const core::InputError error = ExpectInputError([&] { YamlMap(kFile, top).Required("y"); });
  EXPECT_EQ(error.file(), kFile);
  EXPECT_EQ(error.field(), "top.y");
  EXPECT_EQ(error.line(), 3);
  EXPECT_STREQ(error.what(), "test.yaml:3: field 'top.y': missing required key");
}

TEST(YamlFieldsTest, DuplicateAndUnknownKeysAreRefused) {
  const core::InputError duplicate =
      ExpectInputError([] { YamlMap(kFile, Root("a: 1\nb: 2\na: 3\n")); });
  EXPECT_EQ(duplicate.field(), "a");
  EXPECT_EQ(duplicate.line(), 3);
  EXPECT_NE(std::string(duplicate.what()).find("first given on line 1"), std::string::npos);

  const core::InputError unknown = ExpectInputError([] {
    ReadMap(kFile, Root("a: 1\nc: 2\n"), {"a", "b"});
  });
  EXPECT_EQ(unknown.field(), "c");
  EXPECT_EQ(unknown.line(), 2);
  EXPECT_NE(std::string(unknown.what()).find("known keys: a, b"), std::string::npos);

  const core::InputError not_a_map = ExpectInputError([] { YamlMap(kFile, Root("[1, 2]")); });
  EXPECT_NE(std::string(not_a_map.what()).find("expected a map of fields, got a list"),
            std::string::npos);
}

TEST(YamlFieldsTest, NumbersMustBeFiniteAndUnquoted) {
  const YamlMap map(kFile, Root("a: +2.5\nb: .inf\nc: 1e999\nd: '3'\ne: 3.0\nf: 3.5\n"));
  EXPECT_EQ(ReadNumber(kFile, map.Required("a")), 2.5);
  EXPECT_EQ(ReadWholeNumber(kFile, map.Required("e")), 3);
  const auto problem = [&](auto read) { return std::string(ExpectInputError(read).what()); };
  EXPECT_EQ(problem([&] { ReadNumber(kFile, map.Required("b")); }),
            "test.yaml:2: field 'b': expected a finite number, got .inf");
  EXPECT_EQ(problem([&] { ReadNumber(kFile, map.Required("c")); }),
            "test.yaml:3: field 'c': the number 1e999 is out of range");
  EXPECT_EQ(problem([&] { ReadNumber(kFile, map.Required("d")); }),
            "test.yaml:4: field 'd': expected a number, got the string '3'");
  EXPECT_EQ(problem([&] { ReadWholeNumber(kFile, map.Required("f")); }),
            "test.yaml:6: field 'f': expected a whole number, got 3.5");
}

TEST(YamlFieldsTest, NumberListReportsABadItemAtItsLine) {
  const YamlMap map(kFile, Root("k:\n  - 1\n  - x\n  - 3\nshort: [1, 2]\n"));
  const core::InputError item = ExpectInputError([&] { ReadNumbers(kFile, map.Required("k"), 3); });
  EXPECT_EQ(item.field(), "k");
  EXPECT_EQ(item.line(), 3);
  EXPECT_NE(std::string(item.what()).find("item 2 of 3: expected a number, got the string 'x'"),
            std::string::npos);
  const core::InputError count =
      ExpectInputError([&] { ReadNumbers(kFile, map.Required("short"), 3); });
  EXPECT_NE(std::string(count.what()).find("expected a list of 3 numbers, got 2 items"),
            std::string::npos);
  const NumberList numbers = ReadNumbers(kFile, map.Required("short"), 2);
  EXPECT_EQ(numbers.values, (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(numbers.items.size(), 2U);
}

TEST(YamlFieldsTest, NamesTakeAnyScalarButStringsOnlyStrings) {
  const YamlMap map(kFile, Root("n: 42\ns: '42'\nz: ~\n"));
  EXPECT_EQ(ReadName(kFile, map.Required("n")), "42");
  EXPECT_EQ(ReadString(kFile, map.Required("s")), "42");
  EXPECT_EQ(std::string(ExpectInputError([&] { ReadString(kFile, map.Required("n")); }).what()),
            "test.yaml:1: field 'n': expected a string, got the number 42");
  EXPECT_EQ(ExpectInputError([&] { ReadName(kFile, map.Required("z")); }).line(), 3);
}

TEST(YamlFieldsTest, BadDocumentsAndFilesAreInputErrors) {
  const core::InputError malformed = ExpectInputError([] { ParseYaml("a: 1\nb: [1, 2\n", kFile); });
  EXPECT_EQ(malformed.file(), kFile);
  EXPECT_GT(malformed.line(), 0);
  EXPECT_NE(std::string(malformed.what()).find("malformed YAML"), std::string::npos);
  EXPECT_STREQ(ExpectInputError([] { ParseYaml("# only a comment\n", kFile); }).what(),
               "test.yaml: the file is empty");
  const core::InputError missing =
      ExpectInputError([] { LoadYamlFile("/nonexistent/pirouette/camera.yaml"); });
  EXPECT_EQ(missing.line(), 0);
  EXPECT_STREQ(missing.what(), "/nonexistent/pirouette/camera.yaml: no such file");
}

}  // namespace
}  // namespace pirouette::io
