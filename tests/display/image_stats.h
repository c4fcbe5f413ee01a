#pragma once
// Statistics of a screenshot region, used to decide whether a 3-D view actually rendered
// something (a blank, single-colour or placeholder image fails).

#include <QColor>
#include <QImage>
#include <QRect>

namespace resect {

struct ImageStats {
    int pixels = 0;             ///< pixels in the region
    int distinctColours = 0;    ///< distinct RGB values in the region
    QRgb background = 0;        ///< most frequent RGB value in the region
    double backgroundShare = 0; ///< fraction of pixels equal to `background`
    /// Fraction of pixels whose largest channel difference to `reference` exceeds the
    /// tolerance given to analyseRegion().
    double differingFraction = 0;
};

/// Largest difference of the red, green and blue channels of two colours.
int colourDistance(QRgb a, QRgb b);

/// Analyses `region` (clipped to the image) against `reference` (e.g. the view's
/// background colour); channel differences up to `tolerance` count as equal.
ImageStats analyseRegion(const QImage& image, const QRect& region, QRgb reference, int tolerance);

/// The middle of a window screenshot, clear of menu bar, status bar and borders: the
/// central `fraction` of the width and height.
QRect centralRegion(const QImage& image, double fraction);

} // namespace resect
