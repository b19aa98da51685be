#include "pirouette/io/place_table_file.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <optional>
#include <sstream>
#include <vector>

#include "pirouette/core/colour_class.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::io {
namespace {

constexpr int kBins = mapping::kRadialProfileBins;

char KindChar(core::ReadingKind kind) {
  switch (kind) {
    case core::ReadingKind::kHit:
      return 'h';
    case core::ReadingKind::kClear:
      return 'c';
    case core::ReadingKind::kBlind:
      return 'b';
  }
  return 'h';
}

std::optional<core::ReadingKind> KindFromChar(char c) {
  switch (c) {
    case 'h':
      return core::ReadingKind::kHit;
    case 'c':
      return core::ReadingKind::kClear;
    case 'b':
      return core::ReadingKind::kBlind;
    default:
      return std::nullopt;
  }
}

// Reads YAML field by field, naming the file, line and field in errors.
struct Reader {
  const std::string& path;

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& field,
                         const std::string& problem) const {
    throw core::InputError(path, node.IsDefined() ? node.Mark().line + 1 : 0, field, problem);
  }

  YAML::Node Field(const YAML::Node& map, const std::string& key, const std::string& field) const {
    const YAML::Node node = map[key];
    if (!node) Fail(map, field, "missing");
    return node;
  }

  template <typename T>
  T As(const YAML::Node& node, const std::string& field, const char* what) const {
    try {
      return node.as<T>();
    } catch (const YAML::Exception&) {
      Fail(node, field, std::string("must be ") + what);
    }
  }

  double Number(const YAML::Node& node, const std::string& field) const {
    const auto v = As<double>(node, field, "a number");
    if (!std::isfinite(v)) Fail(node, field, "must be a finite number");
    return v;
  }
};

}  // namespace

void SavePlaceTable(const localize::PlaceTable& table, const std::string& path) {
  std::ostringstream out;
  out.precision(6);
  out << "format: " << kPlaceTableFormat << "\n";
  {
    YAML::Emitter world;  // quoted as YAML needs
    world << YAML::DoubleQuoted << table.world();
    out << "world: " << world.c_str() << "\n";
  }
  // Every digit: a table is reused only for the max range it was made with.
  out << "max_range_m: " << std::setprecision(17) << table.max_range_m() << std::setprecision(6)
      << "\n";
  out << "places:\n";
  for (const localize::PlaceEntry& e : table.entries()) {
    out << std::fixed;
    out.precision(4);
    out << "  - {x: " << e.x_m << ", y: " << e.y_m << ", heading_deg: ";
    out.precision(3);
    out << e.heading_rad * 180.0 / std::numbers::pi << ",\n     ranges: [";
    out.precision(4);
    for (std::size_t b = 0; b < e.view.ranges_m.size(); ++b) {
      out << (b > 0 ? (b % 12 == 0 ? ",\n       " : ", ") : "") << e.view.ranges_m[b];
    }
    out << "],\n     colours: \"";
    for (const core::ColourClass c : e.view.colours) out << core::ColourClassChar(c);
    out << "\",\n     kinds: \"";
    for (const core::ReadingKind kind : e.kinds) out << KindChar(kind);
    out << "\"}\n";
  }
  WriteFileAtomically(path, out.str());
}

localize::PlaceTable LoadPlaceTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw core::InputError(path, 0, "", "cannot read the place table");
  YAML::Node root;
  try {
    root = YAML::Load(in);
  } catch (const YAML::Exception& e) {
    throw core::InputError(path, e.mark.line + 1, "", "not YAML: " + e.msg);
  }
  const Reader r{path};
  if (!root.IsMap()) r.Fail(root, "format", "the file must be a YAML map");
  const YAML::Node format = r.Field(root, "format", "format");
  if (r.As<std::string>(format, "format", "a string") != kPlaceTableFormat) {
    r.Fail(format, "format", std::string("must be ") + kPlaceTableFormat);
  }
  const auto world = r.As<std::string>(r.Field(root, "world", "world"), "world", "a string");
  const YAML::Node max_range_node = r.Field(root, "max_range_m", "max_range_m");
  const double max_range = r.Number(max_range_node, "max_range_m");
  if (!(max_range > 0.0)) r.Fail(max_range_node, "max_range_m", "must be > 0");
  const YAML::Node places = r.Field(root, "places", "places");
  if (!places.IsSequence()) r.Fail(places, "places", "must be a list");
  std::vector<localize::PlaceEntry> entries;
  for (std::size_t i = 0; i < places.size(); ++i) {
    const YAML::Node p = places[i];
    const std::string at = "places[" + std::to_string(i) + "]";
    if (!p.IsMap()) r.Fail(p, at, "must be a map");
    localize::PlaceEntry e;
    e.x_m = r.Number(r.Field(p, "x", at + ".x"), at + ".x");
    e.y_m = r.Number(r.Field(p, "y", at + ".y"), at + ".y");
    e.heading_rad = r.Number(r.Field(p, "heading_deg", at + ".heading_deg"), at + ".heading_deg") *
                    std::numbers::pi / 180.0;
    const std::string ranges_field = at + ".ranges";
    const YAML::Node ranges = r.Field(p, "ranges", ranges_field);
    if (!ranges.IsSequence() || static_cast<int>(ranges.size()) != kBins) {
      r.Fail(ranges, ranges_field, "must be a list of " + std::to_string(kBins) + " ranges");
    }
    for (const YAML::Node& v : ranges) {
      const double range = r.Number(v, ranges_field);
      if (range < 0.0) r.Fail(v, ranges_field, "ranges must be >= 0");
      e.view.ranges_m.push_back(range);
    }
    const std::string colours_field = at + ".colours";
    const YAML::Node colours = r.Field(p, "colours", colours_field);
    const auto colour_chars = r.As<std::string>(colours, colours_field, "a string");
    if (!colour_chars.empty() && static_cast<int>(colour_chars.size()) != kBins) {
      r.Fail(colours, colours_field, "must be empty or one character a bin");
    }
    for (const char c : colour_chars) {
      const std::optional<core::ColourClass> colour = core::ColourClassFromChar(c);
      if (!colour) r.Fail(colours, colours_field, std::string("'") + c + "' is not a colour class");
      e.view.colours.push_back(*colour);
    }
    const std::string kinds_field = at + ".kinds";
    const YAML::Node kinds = r.Field(p, "kinds", kinds_field);
    const auto kind_chars = r.As<std::string>(kinds, kinds_field, "a string");
    if (!kind_chars.empty() && static_cast<int>(kind_chars.size()) != kBins) {
      r.Fail(kinds, kinds_field, "must be empty or one character a bin");
    }
    for (const char c : kind_chars) {
      const std::optional<core::ReadingKind> kind = KindFromChar(c);
      if (!kind) r.Fail(kinds, kinds_field, std::string("'") + c + "' is not h, c or b");
      e.kinds.push_back(*kind);
    }
    entries.push_back(std::move(e));
  }
  return {world, max_range, std::move(entries)};
}

}  // namespace pirouette::io
