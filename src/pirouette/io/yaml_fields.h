#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// Reading checked values out of the YAML input files (SPEC.md: camera files
// and world files), shared by their two loaders. Every problem is thrown as a
// core::InputError naming the file, the 1-based line (0 when none is known)
// and the dotted field ("mount.tilt"). Scalars are typed by YAML 1.2's core
// schema, not by yaml-cpp's looser conversions: "0x1F" and "yes" are strings,
// a quoted "42" is a string.

namespace pirouette::io {

// A value in a file: the node, its dotted path for messages ("mount.tilt",
// "obstacles[2].box.size") and the line to report problems with it at.
struct YamlField {
  YAML::Node node;
  std::string path;
  int line = 0;
};

// Throws core::InputError(file, line, path, problem).
[[noreturn]] void ThrowInputError(const std::string& file, int line, const std::string& path,
                                  const std::string& problem);
// Throws core::InputError at `field`'s line and path.
[[noreturn]] void ThrowInputError(const std::string& file, const YamlField& field,
                                  const std::string& problem);

// The 1-based line of a node, or 0 when yaml-cpp knows none.
int LineOf(const YAML::Node& node);

// "prefix.key", or "key" when `prefix` is empty.
std::string JoinFieldPath(const std::string& prefix, std::string_view key);

// What a scalar means under YAML 1.2's core schema (quoted: always a string).
enum class ScalarKind { kNull, kBool, kNumber, kString };
ScalarKind ScalarKindOf(const YAML::Node& node);

// What a node is, for "expected X, got Y": "nothing", "a list", "a map",
// "the boolean true", "the number 3", "the string 'abc'".
std::string DescribeNode(const YAML::Node& node);

// The keys of a map field, checked on construction: the field is a map, its
// keys are plain scalars and none is given twice.
class YamlMap {
 public:
  YamlMap(std::string file, const YamlField& field);

  struct Key {
    std::string name;
    int line;
  };
  // The keys, in the file's order.
  std::vector<Key> Keys() const;

  // Throws for the first key not in `allowed`, listing the allowed ones.
  void AllowOnly(std::initializer_list<std::string_view> allowed) const;

  // The value of `key` (path "map.key"), or nullopt when the key is absent.
  // A null value is reported at its key's line.
  std::optional<YamlField> Optional(std::string_view key) const;
  // The same, but a missing key throws, at the line of the map that lacks it.
  YamlField Required(std::string_view key) const;

 private:
  struct Entry {
    std::string key;
    YAML::Node value;
    int key_line;
  };
  std::string file_;
  YamlField field_;
  std::vector<Entry> entries_;
};

// A YamlMap that allows only the keys in `allowed`.
YamlMap ReadMap(const std::string& file, const YamlField& field,
                std::initializer_list<std::string_view> allowed);

// A finite number. `item` (e.g. "item 2 of 3: ") prefixes the messages about
// one number of a list.
double ReadNumber(const std::string& file, const YamlField& field, const std::string& item = "");

// A whole number of at most 1e9 in magnitude (3 and 3.0 pass, 3.5 does not).
int ReadWholeNumber(const std::string& file, const YamlField& field, const std::string& item = "");

// The items of a list, each at its own line (or the list's, when it has none)
// and with the list's path. `what` names the list expected, for the message.
std::vector<YamlField> ReadList(const std::string& file, const YamlField& field,
                                const std::string& what);

// A list of exactly `count` finite numbers, and the items they came from (to
// report a problem with one of them at its line).
struct NumberList {
  std::vector<double> values;
  std::vector<YamlField> items;
};
NumberList ReadNumbers(const std::string& file, const YamlField& field, std::size_t count);

// Any scalar but null, as its text: a name (ROS writes names unquoted; a name
// of digits is still a name).
std::string ReadName(const std::string& file, const YamlField& field);

// A string proper: quoted, or plain and not a number, boolean or null.
std::string ReadString(const std::string& file, const YamlField& field);

// The document in YAML `text` read from `file`; malformed YAML (at its line)
// or an empty document throws.
YAML::Node ParseYaml(const std::string& text, const std::string& file);

// The document in the file at `path`; a missing, unreadable or empty file, a
// folder or malformed YAML throws.
YAML::Node LoadYamlFile(const std::string& path);

}  // namespace pirouette::io
