#pragma once
// QualityCurve: the remaining tissue's worst tet against the cut number (issue 16; `resect bench
// resection` draws the same curve over its passes). y is the smallest radius ratio
// (3 r_in / R_circ, reference configuration) of the tissue after a cut over that of the tissue
// as created (Tissue::inputWorstRatio): 1 at cut 0, the input, and below 1 where the cuts left
// a worse tet than the input had. x is the cut number, 0 .. the cuts applied. A pending cut's
// point is drawn apart: hollow, joined by a dashed line. A dotted line marks the input's level.
// Painted with QPainter, so it shows (and can be grabbed) under the `offscreen` platform;
// hovering shows a point's figures as a tooltip.
//
// The values come from the studio's tissue states (TissueState::worstRatios, one per cut);
// the widget only draws them.

#include <QPointF>
#include <QRectF>
#include <QWidget>

#include <limits>
#include <optional>
#include <vector>

namespace resect {

class QualityCurve : public QWidget {
    Q_OBJECT

public:
    explicit QualityCurve(QWidget* parent = nullptr);

    /// `input`: the worst radius ratio of the tissue as created (the curve is empty unless it
    /// is finite and > 0); `afterCuts`: the worst ratio after each applied cut, in order;
    /// `pending`: after a pending cut too (NaN: none). Non-finite values are not drawn.
    void setValues(double input, std::vector<double> afterCuts,
                   double pending = std::numeric_limits<double>::quiet_NaN());
    void clear();
    bool isEmpty() const { return !(m_input > 0); }

    /// The worst ratio of the input (0 when empty).
    double inputRatio() const { return isEmpty() ? 0 : m_input; }
    /// The applied cuts' points as drawn, the input's first: x the cut number (0 = the input),
    /// y the worst ratio over the input's (so the first point is (0, 1)). Empty when empty.
    std::vector<QPointF> points() const;
    /// The pending cut's point (x: the applied cuts + 1), if there is one.
    std::optional<QPointF> pendingPoint() const;

    /// Where the point of `value` (x: cut number, y: relative ratio) is drawn (widget
    /// coordinates).
    QPointF pixelOf(QPointF value) const;
    /// The index into points() of the point nearest to `pixel` within a few pixels, points()
    /// .size() for the pending point; -1 for none.
    int pointAt(QPointF pixel) const;
    /// The tooltip of point `index` (as pointAt numbers them); empty for an invalid index.
    QString pointToolTip(int index) const;
    /// The area inside the axes (widget coordinates).
    QRectF plotRect() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    bool event(QEvent* event) override;

private:
    /// The axes' ranges (from 0): x in cuts, y in input ratios, with y's tick step.
    struct Ranges {
        double xHi = 1, yHi = 1, yStep = 0.2;
    };
    Ranges ranges() const;

    double m_input = 0;
    std::vector<double> m_afterCuts;
    double m_pending = std::numeric_limits<double>::quiet_NaN();
};

} // namespace resect
