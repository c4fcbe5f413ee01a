#include "image_stats.h"

#include <QHash>

#include <algorithm>
#include <cstdlib>

namespace resect {

int colourDistance(QRgb a, QRgb b) {
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

ImageStats analyseRegion(const QImage& image, const QRect& region, QRgb reference, int tolerance) {
    ImageStats stats;
    const QRect r = region.intersected(image.rect());
    if (r.isEmpty())
        return stats;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    QHash<QRgb, int> counts;
    int differing = 0;
    for (int y = r.top(); y <= r.bottom(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
        for (int x = r.left(); x <= r.right(); ++x) {
            const QRgb c = line[x] | 0xff000000u;
            ++counts[c];
            if (colourDistance(c, reference) > tolerance)
                ++differing;
        }
    }
    stats.pixels = r.width() * r.height();
    stats.distinctColours = static_cast<int>(counts.size());
    int best = 0;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it) {
        if (it.value() > best) {
            best = it.value();
            stats.background = it.key();
        }
    }
    stats.backgroundShare = double(best) / stats.pixels;
    stats.differingFraction = double(differing) / stats.pixels;
    return stats;
}

QRect centralRegion(const QImage& image, double fraction) {
    const int w = static_cast<int>(image.width() * fraction);
    const int h = static_cast<int>(image.height() * fraction);
    return QRect((image.width() - w) / 2, (image.height() - h) / 2, w, h);
}

QString describe(const ImageStats& stats) {
    return QStringLiteral("%1 distinct colours, %2 of pixels differ from the background, "
                          "most frequent colour #%3 (%4 of pixels)")
        .arg(stats.distinctColours)
        .arg(stats.differingFraction)
        .arg(stats.background & 0xffffffu, 6, 16, QLatin1Char('0'))
        .arg(stats.backgroundShare);
}

QString renderedViewProblem(const ImageStats& stats, QRgb background) {
    if (colourDistance(stats.background, background) > 6)
        return QStringLiteral("the most frequent colour is not the view's background: ") + describe(stats);
    if (stats.distinctColours < 50)
        return QStringLiteral("too few colours: ") + describe(stats);
    if (stats.differingFraction < 0.10 || stats.differingFraction > 0.95)
        return QStringLiteral("the mesh covers too little or too much of the view: ") + describe(stats);
    return {};
}

} // namespace resect
