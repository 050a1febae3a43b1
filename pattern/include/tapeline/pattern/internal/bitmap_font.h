// The bitmap font now lives in core (core/internal/bitmap_font.h) so that modules other than
// pattern can draw text without depending on pattern; these names keep pattern's spelling.
#pragma once

#include <tapeline/core/internal/bitmap_font.h>

namespace tapeline::pattern::internal {

using tapeline::internal::Glyph;
using tapeline::internal::glyph_for;
using tapeline::internal::kBitmapFont;
using tapeline::internal::kFontPixelsPerEm;
using tapeline::internal::kGlyphAdvance;
using tapeline::internal::kGlyphColumns;
using tapeline::internal::kGlyphRows;
using tapeline::internal::kGlyphRowsAboveBaseline;
using tapeline::internal::kPlaceholderGlyph;
using tapeline::internal::text_glyphs;

}  // namespace tapeline::pattern::internal
