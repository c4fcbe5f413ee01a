#pragma once
// Statistics of a screenshot region, used to decide whether a 3-D view actually rendered
// something (a blank, single-colour or placeholder image fails).

#include <QColor>
#include <QImage>
#include <QRect>
#include <QString>

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

/// One line describing the statistics, for test output.
QString describe(const ImageStats& stats);

/// Empty if the statistics show a rendered 3-D view: its most frequent colour is the view's
/// own `background` (VTK rendered, not the placeholder or Qt's fill), it has at least 50
/// colours, and 10 % to 95 % of its pixels differ from the background (a framed mesh, not
/// an empty or a filled view). Otherwise what is wrong, with describe().
QString renderedViewProblem(const ImageStats& stats, QRgb background);

} // namespace resect
