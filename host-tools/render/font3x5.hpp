// A 3 x 5 pixel font for labels: digits, capitals and a few signs.
#pragma once

#include <cstdint>

namespace spinhash::host {

constexpr int kGlyphWidth = 3, kGlyphHeight = 5, kGlyphAdvance = 4;

// Rows of the glyph of c, top first, 3 bits each (bit 2 = left column);
// lower case maps to capitals; nullptr when there is no glyph.
const uint8_t* glyph_rows(char c);

}  // namespace spinhash::host
