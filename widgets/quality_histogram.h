#pragma once
// QualityHistogram: the distribution of a quality measure (radius ratio or minimum dihedral
// angle, quality_colors.h) over all tets, as two overlaid series "before" and "after" a cut,
// optionally with a logarithmic count axis. Painted with QPainter, so it shows (and can be
// grabbed) under the `offscreen` platform.
//
// The bins split range() into binCount() equal intervals; values below or above the range
// (inverted tets, whose radius ratio is negative) and non-finite values are counted in the
// first or last bin, so the counts of a series always sum to its number of tets.

#include "core/mesh/quality.h"
#include "widgets/quality_colors.h"

#include <QWidget>

#include <utility>
#include <vector>

namespace resect {

class QualityHistogram : public QWidget {
    Q_OBJECT

public:
    enum class Series { Before, After };

    explicit QualityHistogram(QWidget* parent = nullptr);

    /// The measure binned (None counts as RadiusRatio); resets the range to
    /// defaultQualityRange(measure).
    void setMeasure(QualityMeasure measure);
    QualityMeasure measure() const { return m_measure; }
    /// Bins over [lo, hi]; lo >= hi or non-finite values are ignored.
    void setRange(double lo, double hi);
    std::pair<double, double> range() const { return m_range; }
    /// Number of bins, at least 1 (default 20).
    void setBinCount(int bins);
    int binCount() const { return m_bins; }
    /// Logarithmic count axis (bar height ~ log(1 + count)).
    void setLogScale(bool on);
    bool logScale() const { return m_log; }

    /// The per-tet measures of one series (tetQualities() of the mesh before or after).
    void setQualities(Series series, std::vector<TetQuality> qualities);
    void clearSeries(Series series);
    bool hasSeries(Series series) const;
    /// Counts per bin of the series under the current measure, range and bin count; empty
    /// if the series is not set.
    std::vector<int> binCounts(Series series) const;
    /// Lower edge of bin i (i = binCount() gives the upper end of the range).
    double binEdge(int i) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    const std::vector<TetQuality>& data(Series series) const;

    QualityMeasure m_measure = QualityMeasure::RadiusRatio;
    std::pair<double, double> m_range{kQualityScaleMin, kQualityScaleMax};
    int m_bins = 20;
    bool m_log = false;
    std::vector<TetQuality> m_before;
    std::vector<TetQuality> m_after;
    bool m_hasBefore = false;
    bool m_hasAfter = false;
};

} // namespace resect
