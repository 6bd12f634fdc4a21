#pragma once
// A terrain as heights on a regular grid, lab 04's input (bump-mapped terrain: normals from a height texture).
// No GL here, so all of it is testable without a context.
//
// Units are real ones, because normals depend on them: a slope is a height difference over a GROUND
// distance, so the grid carries the distance between neighbouring samples in metres along x (columns) and
// y (rows), and heights are metres too. A model on a latitude/longitude grid has dx_m != dy_m; using one for
// both would tilt every normal.
//
// Sample (x, y) stands for the ground point ((x + 0.5) dx_m, (y + 0.5) dy_m) of the rectangle
// [0, width dx_m] x [0, height dy_m]: the centre of its cell, as a texel's value is at its centre in GL.
// Row 0 is the SOUTH (bottom) row, GL's texture order; for real models, columns run west to east.
//
// The .height file format (also described in data/README.md, where the real models' sources are):
//   an ASCII line  "GSVHEIGHT 1 <width> <height> <dx_m> <dy_m>\n"  (magic, format version 1, decimal sizes
//   1..8192, then the sample spacings in metres as decimal numbers, positive and finite),
//   then width*height little-endian IEEE 754 float32 heights in metres, row-major with row 0 = the south
//   (bottom) row, every one finite, and nothing after them.
#include <glm/glm.hpp>

#include <filesystem>
#include <vector>

namespace gsv {

// Far above what a lab uploads, but a bound, so a corrupt header is refused before it allocates anything.
inline constexpr int kMaxHeightSide = 8192;

struct HeightField {
    int width = 0, height = 0;
    double dx_m = 1, dy_m = 1;   // ground distance between neighbouring samples along x and along y
    std::vector<float> heights;  // metres, width*height of them, row-major, row 0 = the south row

    // Height of sample (x, y), y counted from the south row. Throws gsv::Error outside the grid.
    float at(int x, int y) const;
    // The lowest and highest heights; 0 for an empty field.
    float min_height() const;
    float max_height() const;
};

// Ground position in metres (x, along columns; y, along rows) of sample (x, y)'s centre. Throws gsv::Error
// outside the grid.
glm::dvec2 sample_position(const HeightField& field, int x, int y);

// Reads a .height file (format above). Throws gsv::Error with one line naming the file for: a missing or
// unreadable file, one that is not a .height file, an unsupported version, a size outside 1..8192, a
// spacing that is not a positive finite number, too few bytes of heights ("expected N bytes of heights,
// found M"), bytes after them, or a NaN or infinite height (naming its sample).
HeightField load_height_field(const std::filesystem::path& path);

// Writes `field` as a .height file, byte-for-byte the same on every host; the spacings are written as the
// shortest decimal text that reads back exactly (as scripts/convert-dem.py writes them). Throws gsv::Error,
// before creating the file, for a field load_height_field would refuse (bad size or spacing, a height count
// that is not width*height, a non-finite height), or if the file cannot be written.
void save_height_field(const std::filesystem::path& path, const HeightField& field);

}  // namespace gsv
