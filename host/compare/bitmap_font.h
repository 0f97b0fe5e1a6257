// A tiny 5×7 pixel font for labels in pictures tsis writes (heat-map legends):
// digits, . % + - / | and the few letters the legends use (A B e l o r).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace tsis {

constexpr int kGlyphWidth = 5, kGlyphHeight = 7;
constexpr int kGlyphAdvance = kGlyphWidth + 1;

// Whether pixel (x, y) of c's glyph is set (y = 0 is the top row). A character
// without a glyph draws as a hollow box, so a missing one is visible.
bool glyphPixel(char c, int x, int y);

// Width in pixels of `text` drawn at `scale` (pixels per font pixel).
int textWidth(const std::string& text, int scale);

// Draws `text` into an RGB8 image (row 0 = top) with its top-left corner at
// (x, y); pixels outside the image are skipped.
void drawText(std::vector<uint8_t>& rgb, int width, int height, int x, int y,
              const std::string& text, int scale, std::array<uint8_t, 3> colour);

}  // namespace tsis
