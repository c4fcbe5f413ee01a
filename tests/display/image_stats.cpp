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

} // namespace resect
