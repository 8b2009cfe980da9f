// A 5x7 bitmap font for the labels of the validation pictures: digits, capital letters
// (lower case is drawn as capitals) and a little punctuation; other characters draw as blanks.
#pragma once
#include <string>

#include "rgb_image.hpp"

namespace dbs {

/// Advance of one character in pixels at scale 1 (5 wide plus 1 space).
constexpr int kGlyphAdvance = 6;
constexpr int kGlyphHeight = 7;

/// Draws `text` with its top-left corner at (x, y), each font pixel `scale` x `scale` image
/// pixels; pixels outside the image are skipped.
void draw_text(RgbImage& image, int x, int y, const std::string& text, Rgb colour, int scale = 1);

/// Width in pixels of `text` drawn at `scale`.
inline int text_width(const std::string& text, int scale = 1) { return static_cast<int>(text.size()) * kGlyphAdvance * scale; }

}  // namespace dbs
