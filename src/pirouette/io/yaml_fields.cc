#include "pirouette/io/yaml_fields.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "pirouette/core/input_error.h"

namespace pirouette::io {
namespace {

bool IsDecimal(std::string_view s) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t start = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i - start;
  };
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < s.size() && s[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == s.size();
}

bool IsNonFinite(std::string_view s) {
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  return s == ".inf" || s == ".Inf" || s == ".INF" || s == ".nan" || s == ".NaN" || s == ".NAN";
}

// The whole of a file, or an InputError naming it.
std::string ReadFileText(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) ThrowInputError(path, 0, "", "no such file");
  if (fs::is_directory(status)) ThrowInputError(path, 0, "", "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) ThrowInputError(path, 0, "", std::string("cannot open: ") + std::strerror(errno));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) ThrowInputError(path, 0, "", "cannot read");
  return text;
}

}  // namespace

void ThrowInputError(const std::string& file, int line, const std::string& path,
                     const std::string& problem) {
  throw core::InputError(file, line, path, problem);
}

void ThrowInputError(const std::string& file, const YamlField& field, const std::string& problem) {
  ThrowInputError(file, field.line, field.path, problem);
}

int LineOf(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

std::string JoinFieldPath(const std::string& prefix, std::string_view key) {
  return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

ScalarKind ScalarKindOf(const YAML::Node& node) {
  if (node.IsNull()) return ScalarKind::kNull;
  if (node.Tag() == "!") return ScalarKind::kString;  // quoted: a string whatever it reads
  const std::string& s = node.Scalar();
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") return ScalarKind::kNull;
  if (s == "true" || s == "True" || s == "TRUE" || s == "false" || s == "False" || s == "FALSE") {
    return ScalarKind::kBool;
  }
  if (IsDecimal(s) || IsNonFinite(s)) return ScalarKind::kNumber;
  return ScalarKind::kString;
}

std::string DescribeNode(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  switch (ScalarKindOf(node)) {
    case ScalarKind::kNull:
      return "nothing";
    case ScalarKind::kBool:
      return "the boolean " + node.Scalar();
    case ScalarKind::kNumber:
      return "the number " + node.Scalar();
    case ScalarKind::kString:
      break;
  }
  return "the string '" + node.Scalar() + "'";
}

YamlMap::YamlMap(std::string file, const YamlField& field) : file_(std::move(file)), field_(field) {
  if (!field.node.IsMap()) {
    ThrowInputError(file_, field_, "expected a map of fields, got " + DescribeNode(field.node));
  }
  for (auto it = field.node.begin(); it != field.node.end(); ++it) {
    const YAML::Node key = it->first;
    const YAML::Node value = it->second;
    const int key_line = LineOf(key);
    if (!key.IsScalar()) {
      ThrowInputError(file_, key_line, field_.path,
                      "a key must be a name, got " + DescribeNode(key));
    }
    const std::string& name = key.Scalar();
    for (const Entry& entry : entries_) {
      if (entry.key == name) {
        ThrowInputError(file_, key_line, JoinFieldPath(field_.path, name),
                        fmt::format("duplicate key (first given on line {})", entry.key_line));
      }
    }
    entries_.push_back({name, value, key_line});
  }
}

std::vector<YamlMap::Key> YamlMap::Keys() const {
  std::vector<Key> keys;
  for (const Entry& entry : entries_) keys.push_back({entry.key, entry.key_line});
  return keys;
}

void YamlMap::AllowOnly(std::initializer_list<std::string_view> allowed) const {
  for (const Entry& entry : entries_) {
    if (std::find(allowed.begin(), allowed.end(), entry.key) == allowed.end()) {
      std::string known;
      for (const std::string_view key : allowed) {
        known += (known.empty() ? "" : ", ") + std::string(key);
      }
      ThrowInputError(file_, entry.key_line, JoinFieldPath(field_.path, entry.key),
                      "unknown key (known keys: " + known + ")");
    }
  }
}

std::optional<YamlField> YamlMap::Optional(std::string_view key) const {
  for (const Entry& entry : entries_) {
    if (entry.key == key) {
      // A null value's mark is where the next token starts: report the key's line.
      const int line = entry.value.IsNull() ? entry.key_line : LineOf(entry.value);
      return YamlField{entry.value, JoinFieldPath(field_.path, key), line};
    }
  }
  return std::nullopt;
}

YamlField YamlMap::Required(std::string_view key) const {
  std::optional<YamlField> field = Optional(key);
  if (!field) {
    ThrowInputError(file_, field_.line, JoinFieldPath(field_.path, key), "missing required key");
  }
  return *field;
}

YamlMap ReadMap(const std::string& file, const YamlField& field,
                std::initializer_list<std::string_view> allowed) {
  YamlMap map(file, field);
  map.AllowOnly(allowed);
  return map;
}

double ReadNumber(const std::string& file, const YamlField& field, const std::string& item) {
  const YAML::Node& node = field.node;
  if (!node.IsScalar() || ScalarKindOf(node) != ScalarKind::kNumber) {
    ThrowInputError(file, field, item + "expected a number, got " + DescribeNode(node));
  }
  std::string_view text = node.Scalar();
  if (IsNonFinite(text)) {
    ThrowInputError(file, field, item + "expected a finite number, got " + node.Scalar());
  }
  if (text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    ThrowInputError(file, field, item + "the number " + node.Scalar() + " is out of range");
  }
  return value;
}

int ReadWholeNumber(const std::string& file, const YamlField& field, const std::string& item) {
  const double value = ReadNumber(file, field, item);
  if (value != std::floor(value) || std::fabs(value) > 1e9) {
    ThrowInputError(file, field, item + "expected a whole number, got " + field.node.Scalar());
  }
  return static_cast<int>(value);
}

std::vector<YamlField> ReadList(const std::string& file, const YamlField& field,
                                const std::string& what) {
  if (!field.node.IsSequence()) {
    ThrowInputError(file, field, "expected " + what + ", got " + DescribeNode(field.node));
  }
  std::vector<YamlField> items;
  for (const YAML::Node& item : field.node) {
    const int line = LineOf(item);
    items.push_back({item, field.path, line > 0 ? line : field.line});
  }
  return items;
}

NumberList ReadNumbers(const std::string& file, const YamlField& field, std::size_t count) {
  const std::string what = fmt::format("a list of {} numbers", count);
  NumberList numbers{{}, ReadList(file, field, what)};
  if (numbers.items.size() != count) {
    ThrowInputError(file, field,
                    fmt::format("expected {}, got {} items", what, numbers.items.size()));
  }
  for (std::size_t i = 0; i < count; ++i) {
    numbers.values.push_back(
        ReadNumber(file, numbers.items[i], fmt::format("item {} of {}: ", i + 1, count)));
  }
  return numbers;
}

std::string ReadName(const std::string& file, const YamlField& field) {
  if (!field.node.IsScalar() || ScalarKindOf(field.node) == ScalarKind::kNull) {
    ThrowInputError(file, field, "expected a string, got " + DescribeNode(field.node));
  }
  return field.node.Scalar();
}

std::string ReadString(const std::string& file, const YamlField& field) {
  if (!field.node.IsScalar() || ScalarKindOf(field.node) != ScalarKind::kString) {
    ThrowInputError(file, field, "expected a string, got " + DescribeNode(field.node));
  }
  return field.node.Scalar();
}

YAML::Node ParseYaml(const std::string& text, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    ThrowInputError(file, e.mark.is_null() ? 0 : e.mark.line + 1, "", "malformed YAML: " + e.msg);
  } catch (const YAML::Exception& e) {
    ThrowInputError(file, 0, "", std::string("malformed YAML: ") + e.what());
  }
  if (!root.IsDefined() || root.IsNull()) ThrowInputError(file, 0, "", "the file is empty");
  return root;
}

YAML::Node LoadYamlFile(const std::string& path) { return ParseYaml(ReadFileText(path), path); }

}  // namespace pirouette::io
