#include "widgets/quality_histogram.h"

#include <QPaintEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace resect {

namespace {

const QColor kBeforeColour(70, 130, 200, 150);
const QColor kAfterColour(230, 120, 40, 150);

} // namespace

QualityHistogram::QualityHistogram(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("qualityHistogram"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
}

void QualityHistogram::setMeasure(QualityMeasure measure) {
    if (measure == QualityMeasure::None)
        measure = QualityMeasure::RadiusRatio;
    m_measure = measure;
    m_range = defaultQualityRange(measure);
    update();
}

void QualityHistogram::setRange(double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
        return;
    m_range = {lo, hi};
    update();
}

void QualityHistogram::setBinCount(int bins) {
    m_bins = std::max(1, bins);
    update();
}

void QualityHistogram::setLogScale(bool on) {
    m_log = on;
    update();
}

void QualityHistogram::setQualities(Series series, std::vector<TetQuality> qualities) {
    if (series == Series::Before) {
        m_before = std::move(qualities);
        m_hasBefore = true;
    } else {
        m_after = std::move(qualities);
        m_hasAfter = true;
    }
    update();
}

void QualityHistogram::clearSeries(Series series) {
    if (series == Series::Before) {
        m_before.clear();
        m_hasBefore = false;
    } else {
        m_after.clear();
        m_hasAfter = false;
    }
    update();
}

bool QualityHistogram::hasSeries(Series series) const {
    return series == Series::Before ? m_hasBefore : m_hasAfter;
}

const std::vector<TetQuality>& QualityHistogram::data(Series series) const {
    return series == Series::Before ? m_before : m_after;
}

std::vector<int> QualityHistogram::binCounts(Series series) const {
    if (!hasSeries(series))
        return {};
    std::vector<int> counts(static_cast<std::size_t>(m_bins), 0);
    const double width = m_range.second - m_range.first;
    for (const TetQuality& q : data(series)) {
        const double v = qualityMeasureValue(m_measure, q);
        int bin = 0;
        if (std::isfinite(v)) {
            const double x = std::floor((v - m_range.first) / width * m_bins);
            bin = static_cast<int>(std::clamp(x, 0.0, double(m_bins - 1)));
        }
        ++counts[static_cast<std::size_t>(bin)];
    }
    return counts;
}

double QualityHistogram::binEdge(int i) const {
    return m_range.first + (m_range.second - m_range.first) * double(i) / double(m_bins);
}

QSize QualityHistogram::sizeHint() const {
    return {320, 180};
}

QSize QualityHistogram::minimumSizeHint() const {
    return {160, 100};
}

void QualityHistogram::paintEvent(QPaintEvent* /*event*/) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().base());
    const QFontMetrics fm = painter.fontMetrics();
    const int margin = 6;
    const int textH = fm.height();
    // Plot area: room for the legend on top and the axis labels below.
    const QRect plot(margin + fm.horizontalAdvance(QStringLiteral("00000")), margin + textH,
                     width() - 2 * margin - fm.horizontalAdvance(QStringLiteral("00000")),
                     height() - 2 * margin - 2 * textH - 4);
    if (plot.width() < 10 || plot.height() < 10)
        return;

    const std::vector<int> before = binCounts(Series::Before);
    const std::vector<int> after = binCounts(Series::After);
    int maxCount = 1;
    for (int c : before)
        maxCount = std::max(maxCount, c);
    for (int c : after)
        maxCount = std::max(maxCount, c);
    auto barHeight = [&](int count) {
        const double f = m_log ? std::log1p(double(count)) / std::log1p(double(maxCount))
                               : double(count) / double(maxCount);
        return f * plot.height();
    };
    auto drawSeries = [&](const std::vector<int>& counts, const QColor& colour) {
        painter.setPen(colour.darker(140));
        painter.setBrush(colour);
        for (int i = 0; i < static_cast<int>(counts.size()); ++i) {
            if (counts[i] == 0)
                continue;
            const double x0 = plot.left() + plot.width() * double(i) / m_bins;
            const double x1 = plot.left() + plot.width() * double(i + 1) / m_bins;
            const double h = barHeight(counts[i]);
            painter.drawRect(QRectF(x0, plot.bottom() - h, x1 - x0, h));
        }
    };
    drawSeries(before, kBeforeColour);
    drawSeries(after, kAfterColour);

    // Axes and labels.
    painter.setPen(palette().color(QPalette::Text));
    painter.setBrush(Qt::NoBrush);
    painter.drawLine(plot.bottomLeft(), plot.bottomRight());
    painter.drawLine(plot.bottomLeft(), plot.topLeft());
    const int labelY = plot.bottom() + 2;
    painter.drawText(QRect(plot.left(), labelY, plot.width(), textH), Qt::AlignLeft,
                     QString::number(m_range.first, 'g', 3));
    painter.drawText(QRect(plot.left(), labelY, plot.width(), textH), Qt::AlignHCenter,
                     qualityMeasureTitle(m_measure));
    painter.drawText(QRect(plot.left(), labelY, plot.width(), textH), Qt::AlignRight,
                     QString::number(m_range.second, 'g', 3));
    painter.drawText(QRect(0, plot.top(), plot.left() - 3, textH), Qt::AlignRight,
                     QString::number(maxCount));
    painter.drawText(QRect(0, plot.bottom() - textH, plot.left() - 3, textH), Qt::AlignRight,
                     QStringLiteral("0"));

    // Legend.
    int x = plot.left();
    auto legendEntry = [&](const QString& text, const QColor& colour) {
        painter.fillRect(QRect(x, margin + 2, textH - 4, textH - 4), colour);
        x += textH;
        painter.drawText(QPoint(x, margin + fm.ascent()), text);
        x += fm.horizontalAdvance(text) + 12;
    };
    if (m_hasBefore)
        legendEntry(tr("before"), kBeforeColour);
    if (m_hasAfter)
        legendEntry(tr("after"), kAfterColour);
    if (m_log)
        legendEntry(tr("log scale"), Qt::transparent);
}

} // namespace resect
