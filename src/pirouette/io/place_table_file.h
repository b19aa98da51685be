#pragma once

#include <string>

#include "pirouette/localize/place_table.h"

// The place table's file: the adapter between localize::PlaceTable and YAML
// on disk, kept out of the localize layer (DESIGN.md: file I/O at the edges).

namespace pirouette::io {

// The file format's name, its first field.
inline constexpr const char* kPlaceTableFormat = "pirouette-places/1";

// Writes the table as YAML (format: pirouette-places/1; world; max_range_m;
// places: a list of {x, y, heading_deg, ranges: [metres…], colours: one
// ColourClassChar a bin, kinds: 'h' hit, 'c' clear, 'b' blind a bin}),
// atomically (WriteFileAtomically): to a temporary file in the same folder,
// then renamed over `path`. Throws std::runtime_error naming the path when it
// cannot.
void SavePlaceTable(const localize::PlaceTable& table, const std::string& path);

// Reads a file SavePlaceTable wrote. Throws core::InputError naming the file,
// the line and the field for a missing file, bad YAML, another format, or a
// missing or malformed field.
localize::PlaceTable LoadPlaceTable(const std::string& path);

}  // namespace pirouette::io
