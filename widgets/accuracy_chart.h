#pragma once
// AccuracyChart: what accuracy costs in time, as a scatter of accuracy-study rows
// (scenario/accuracy_study.h). x is the cost on a logarithmic axis: the simulation's compute
// time per simulated second (sim_ms_per_second, the default) or the cut's time (cut_ms);
// y is the accuracy: how far the cut faces lie from the sweep at worst (sweep_error_max, in
// mean edge lengths; lower is better). One colour and marker per method; each method's
// Pareto front (the rows no other row of that method beats in both cost and error) is joined
// by a line; axes with ticks and labels and a legend. Painted with QPainter, so it shows (and
// can be grabbed) under the `offscreen` platform.
//
// Clicking a point selects its row and emits rowClicked, a double click emits
// rowDoubleClicked; hovering shows the row's settings and figures as a tooltip. Points that
// would cover each other (settings with the same cost and error) are spread on a small
// circle around their place, so every one can be seen and clicked. Dragging a rectangle on
// empty space zooms to it; a double click on empty space (or a right click) shows all again.

#include "scenario/accuracy_study.h"

#include <QColor>
#include <QLocale>
#include <QPointF>
#include <QRectF>
#include <QWidget>

#include <optional>
#include <vector>

namespace resect {

class AccuracyChart : public QWidget {
    Q_OBJECT

public:
    /// What the x axis shows.
    enum class CostAxis { SimMsPerSecond, CutMs };

    explicit AccuracyChart(QWidget* parent = nullptr);

    /// Replaces the rows (and clears the selection).
    void setRows(std::vector<StudyRow> rows);
    const std::vector<StudyRow>& rows() const { return m_rows; }

    void setCostAxis(CostAxis axis);
    CostAxis costAxis() const { return m_axis; }
    /// The cost of `row` on the current axis (ms per simulated second or ms).
    double cost(const StudyRow& row) const;

    /// The highlighted row, -1 for none (out-of-range values select none).
    void setSelectedRow(int row);
    int selectedRow() const { return m_selected; }

    /// The row whose point is nearest to `pixel` (widget coordinates) within a few pixels;
    /// -1 if none is.
    int rowAt(QPointF pixel) const;
    /// Where the point of `row` is drawn (widget coordinates; spread from its data position
    /// when other points coincide with it); (-1, -1) for an invalid row.
    QPointF pointPosition(int row) const;
    /// Where `row`'s cost and error are on the axes (widget coordinates), before spreading.
    QPointF dataPosition(int row) const;

    /// Zooms to the data inside `pixels` (widget coordinates); ignored if it is smaller
    /// than a few pixels either way.
    void zoomTo(const QRectF& pixels);
    /// Shows all rows again.
    void resetZoom();
    bool isZoomed() const { return m_zoom.has_value(); }

    /// A tick label of the cost axis for the cost 10^logValue: plain numbers with digit
    /// grouping from 0.001 to 99 999 ("2", "1,000", "0.05"), powers of ten beyond
    /// ("10⁶", "2×10⁷"), never "1e+03".
    static QString costLabel(double logValue, const QLocale& locale);
    /// The rows of `method` ("subdivision", ...) on its Pareto front under the current cost
    /// axis, by increasing cost (and so decreasing error).
    std::vector<int> paretoFront(const std::string& method) const;
    /// The tooltip text of `row`: its settings and figures (empty for an invalid row).
    QString rowToolTip(int row) const;
    /// The area inside the axes (widget coordinates).
    QRectF plotRect() const;

    /// The colour of a method's points ("subdivision", "hybrid-standard", "hybrid-enhanced";
    /// grey for anything else).
    static QColor methodColour(const std::string& method);
    /// The translated name of a method as the legend shows it.
    static QString methodLabel(const std::string& method);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void rowClicked(int row);
    void rowDoubleClicked(int row);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    bool event(QEvent* event) override;

private:
    /// The axes' ranges: x as log10 of the cost, y in mean edge lengths.
    struct Ranges {
        double xLo = 0, xHi = 1, yLo = 0, yHi = 1;
    };
    Ranges ranges() const;
    /// log10 of the cost, clamped into the drawable range for non-positive costs.
    double logCost(const StudyRow& row) const;
    QPointF toPixel(double logCost, double error, const Ranges& r, const QRectF& plot) const;
    /// The method names present, in a fixed order (known methods first).
    std::vector<std::string> methods() const;
    /// One legend entry (a method's marker, or the Pareto front's line when `method` is
    /// empty) and where it starts; the legend wraps onto more lines in a narrow chart.
    struct LegendItem {
        std::string method;
        QString label;
        QPointF position; ///< left end, vertical centre
    };
    std::vector<LegendItem> legendLayout(double& height) const;

    /// Every row's drawn position (pointPosition), computed together: O(rows^2).
    std::vector<QPointF> drawnPositions() const;

    std::vector<StudyRow> m_rows;
    CostAxis m_axis = CostAxis::SimMsPerSecond;
    int m_selected = -1;
    std::optional<Ranges> m_zoom;
    std::optional<QPointF> m_dragStart; ///< a zoom rectangle being dragged from here
    QPointF m_dragNow;
};

} // namespace resect
