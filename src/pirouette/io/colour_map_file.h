#pragma once

#include <string>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/localize/colour_map.h"

// The colour layer of a map as a picture beside map.yaml: one pixel a cell,
// laid out as map.pgm (the first row the map's top), a cell's pixel the swatch
// of its colour class (core::ColourClassSwatch), transparent where no
// colour was seen. A person sees the map's walls in the colours they have;
// `pirouette locate` reads it to tell a symmetric place from its mirror image.

namespace pirouette::io {

// DIR/STEM_colours.png for DIR/STEM.yaml.
std::string ColourMapPathFor(const std::string& map_yaml_path);

// Writes `colours` as an RGBA PNG, atomically; throws std::runtime_error
// naming the path when it cannot.
void WriteColourMap(const localize::ColourMap& colours, const std::string& png_path);

// Reads a colour layer for a map of `geometry`: a pixel with alpha 0 is
// kNone, any other takes core::ClassifyColour of its colour (so a
// picture painted by hand reads too). Throws core::InputError naming the
// file when it is missing, not an image, or not the map's width and height.
localize::ColourMap ReadColourMap(const std::string& png_path, const core::GridGeometry& geometry);

}  // namespace pirouette::io
