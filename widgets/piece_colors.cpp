#include "widgets/piece_colors.h"

#include <algorithm>

namespace resect {

namespace {

/// Tableau 10, reordered: blue, orange, green, red, purple, teal, yellow, brown, pink, grey.
constexpr std::array<Rgb, kPieceHues> kHues{{
    {0.306, 0.475, 0.655}, // #4E79A7
    {0.949, 0.557, 0.169}, // #F28E2B
    {0.349, 0.631, 0.310}, // #59A14F
    {0.882, 0.341, 0.349}, // #E15759
    {0.690, 0.478, 0.631}, // #B07AA1
    {0.463, 0.718, 0.698}, // #76B7B2
    {0.929, 0.788, 0.282}, // #EDC948
    {0.612, 0.459, 0.373}, // #9C755F
    {1.000, 0.616, 0.655}, // #FF9DA7
    {0.729, 0.690, 0.675}, // #BAB0AC
}};

} // namespace

Rgb piecePalette(int piece) {
    const int p = std::max(piece, 0);
    const Rgb& hue = kHues[p % kPieceHues];
    // 0: as is; then alternately darker and lighter, a little more each round.
    const int round = p / kPieceHues;
    if (round == 0)
        return hue;
    const double amount = std::min(0.25 + 0.1 * ((round - 1) / 2), 0.6);
    Rgb c;
    for (int i = 0; i < 3; ++i)
        c[i] = round % 2 == 1 ? hue[i] * (1 - amount) : hue[i] + (1 - hue[i]) * amount;
    return c;
}

Rgb mixColours(const Rgb& a, const Rgb& b, double t) {
    const double s = std::clamp(t, 0.0, 1.0);
    return {(1 - s) * a[0] + s * b[0], (1 - s) * a[1] + s * b[1], (1 - s) * a[2] + s * b[2]};
}

} // namespace resect
