#pragma once
// Colours of the "see the cut" views (issue 19): a qualitative palette that tells pieces
// apart, and the fixed colours of cut faces, of the last cut's touched tets, of a picked tet
// and of resected chips drawn without piece colours.
//
// Piece p is drawn in piecePalette(p): the palette's ten hues (Tableau 10, in an order that
// puts the most different hues first) for p = 0..9, then the same hues darker, lighter,
// darker still, ... for the next tens. The colour of a piece depends on its index alone, so a piece
// keeps its colour as long as its index stays (TissueDisplay numbers the tissue's pieces first, in
// the order of their lowest node, then the chips in the order they were resected). None of the
// palette's colours is close to kCutFaceColour.

#include <array>

namespace resect {

using Rgb = std::array<double, 3>; ///< red, green, blue in [0, 1]

/// Number of hues before the palette repeats them lighter or darker.
inline constexpr int kPieceHues = 10;

/// The colour of piece `piece` (>= 0; a negative index gives the first colour).
Rgb piecePalette(int piece);

/// (1 - t) a + t b: `a` faded towards `b` by t in [0, 1].
Rgb mixColours(const Rgb& a, const Rgb& b, double t);

/// Cut faces on the tet mesh: a pale cream, like the inside of cut tissue.
inline constexpr Rgb kCutFaceColour{0.99, 0.94, 0.80};
/// Edges of the tets the last cut produced or changed.
inline constexpr Rgb kTouchedColour{1.00, 0.84, 0.05};
/// Outline of the picked tet.
inline constexpr Rgb kPickedColour{0.10, 0.95, 1.00};
/// Resected chips in the quality colouring: a neutral grey, so that they do not read as tissue.
inline constexpr Rgb kResectedColour{0.62, 0.62, 0.64};

} // namespace resect
