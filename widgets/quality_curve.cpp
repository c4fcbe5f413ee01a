#include "widgets/quality_curve.h"
#include "widgets/chart_axes.h"

#include <QHelpEvent>
#include <QLocale>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace resect {

namespace {

constexpr double kPickRadius = 6.0; ///< px: how near the pointer must be to a point
constexpr double kMarkerSize = 3.5; ///< px: a point's radius
constexpr double kLeft = 56, kRight = 16, kTop = 14, kBottom = 40; ///< px: margins around the axes
const QColor kCurveColour(40, 160, 90); // the hybrid-enhanced colour of the accuracy chart

} // namespace

QualityCurve::QualityCurve(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("qualityCurve"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setMouseTracking(true);
}

void QualityCurve::setValues(double input, std::vector<double> afterCuts, double pending) {
    if (!(std::isfinite(input) && input > 0)) {
        clear();
        return;
    }
    m_input = input;
    m_afterCuts = std::move(afterCuts);
    m_pending = pending;
    update();
}

void QualityCurve::clear() {
    m_input = 0;
    m_afterCuts.clear();
    m_pending = std::numeric_limits<double>::quiet_NaN();
    update();
}

std::vector<QPointF> QualityCurve::points() const {
    std::vector<QPointF> out;
    if (isEmpty())
        return out;
    out.emplace_back(0.0, 1.0);
    for (std::size_t i = 0; i < m_afterCuts.size(); ++i)
        if (std::isfinite(m_afterCuts[i]))
            out.emplace_back(double(i + 1), m_afterCuts[i] / m_input);
    return out;
}

std::optional<QPointF> QualityCurve::pendingPoint() const {
    if (isEmpty() || !std::isfinite(m_pending))
        return std::nullopt;
    return QPointF(double(m_afterCuts.size() + 1), m_pending / m_input);
}

QualityCurve::Ranges QualityCurve::ranges() const {
    Ranges r;
    r.xHi = std::max(1.0, double(m_afterCuts.size() + (pendingPoint() ? 1 : 0)));
    double yMax = 1;
    for (const QPointF& p : points())
        yMax = std::max(yMax, p.y());
    if (const auto p = pendingPoint())
        yMax = std::max(yMax, p->y());
    r.yStep = niceStep(yMax / 5);
    r.yHi = r.yStep * std::ceil(1.05 * yMax / r.yStep - 1e-9);
    return r;
}

QRectF QualityCurve::plotRect() const {
    return QRectF(kLeft, kTop, std::max(10.0, width() - kLeft - kRight),
                  std::max(10.0, height() - kTop - kBottom));
}

QPointF QualityCurve::pixelOf(QPointF value) const {
    const Ranges r = ranges();
    const QRectF plot = plotRect();
    const double fx = value.x() / r.xHi;
    const double fy = std::clamp(value.y(), 0.0, r.yHi) / r.yHi;
    return {plot.left() + fx * plot.width(), plot.bottom() - fy * plot.height()};
}

int QualityCurve::pointAt(QPointF pixel) const {
    std::vector<QPointF> all = points();
    if (const auto p = pendingPoint())
        all.push_back(*p);
    int best = -1;
    double bestDist = kPickRadius;
    for (int i = 0; i < static_cast<int>(all.size()); ++i) {
        const QPointF p = pixelOf(all[static_cast<std::size_t>(i)]);
        const double dist = std::hypot(p.x() - pixel.x(), p.y() - pixel.y());
        if (dist <= bestDist) {
            best = i;
            bestDist = dist;
        }
    }
    return best;
}

QString QualityCurve::pointToolTip(int index) const {
    const std::vector<QPointF> applied = points();
    const auto pending = pendingPoint();
    const int count = static_cast<int>(applied.size());
    if (index < 0 || index > count || (index == count && !pending))
        return {};
    const QPointF p = index < count ? applied[static_cast<std::size_t>(index)] : *pending;
    const QLocale locale;
    const QString ratio = locale.toString(p.y() * m_input, 'g', 3);
    const QString relative = locale.toString(p.y(), 'g', 3);
    if (p.x() == 0)
        return tr("The tissue as created: worst radius ratio %1").arg(ratio);
    const QString line = tr("After cut %1: worst radius ratio %2 (%3 × the input's)")
                             .arg(static_cast<int>(p.x()))
                             .arg(ratio, relative);
    return index < count ? line : line + QLatin1Char('\n') + tr("Pending: not applied yet");
}

QSize QualityCurve::sizeHint() const {
    return {360, 220};
}

QSize QualityCurve::minimumSizeHint() const {
    return {200, 140};
}

void QualityCurve::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    const QRectF plot = plotRect();
    const Ranges r = ranges();
    const QLocale locale;
    const QColor text = palette().color(QPalette::Text);
    const QColor grid = palette().color(QPalette::Mid);
    const QFontMetricsF fm(font());

    // Grid, ticks and labels: whole cut numbers on x, nice steps of the input's ratio on y.
    const double xStep = std::max(1.0, niceStep(r.xHi / 8));
    for (double x = 0; x <= r.xHi + 1e-9; x += xStep) {
        const double px = pixelOf({x, 0}).x();
        painter.setPen(QPen(grid, 0, Qt::DotLine));
        painter.drawLine(QPointF(px, plot.top()), QPointF(px, plot.bottom()));
        painter.setPen(text);
        painter.drawLine(QPointF(px, plot.bottom()), QPointF(px, plot.bottom() + 4));
        painter.drawText(QRectF(px - 30, plot.bottom() + 5, 60, fm.height()),
                         Qt::AlignHCenter | Qt::AlignTop, locale.toString(int(std::lround(x))));
    }
    for (double y = 0; y <= r.yHi + 1e-9 * r.yStep; y += r.yStep) {
        const double py = pixelOf({0, y}).y();
        painter.setPen(QPen(grid, 0, Qt::DotLine));
        painter.drawLine(QPointF(plot.left(), py), QPointF(plot.right(), py));
        painter.setPen(text);
        painter.drawLine(QPointF(plot.left() - 4, py), QPointF(plot.left(), py));
        painter.drawText(QRectF(0, py - fm.height() / 2, plot.left() - 6, fm.height()),
                         Qt::AlignRight | Qt::AlignVCenter, locale.toString(y, 'g', 3));
    }

    // Axes and their titles.
    painter.setPen(text);
    painter.drawLine(plot.bottomLeft(), plot.bottomRight());
    painter.drawLine(plot.bottomLeft(), plot.topLeft());
    painter.drawText(QRectF(plot.left(), height() - fm.height() - 2, plot.width(), fm.height()),
                     Qt::AlignHCenter, tr("Cut"));
    painter.save();
    painter.translate(fm.height() / 2 + 2, plot.center().y());
    painter.rotate(-90);
    painter.drawText(QRectF(-plot.height() / 2, -fm.height() / 2, plot.height(), fm.height()),
                     Qt::AlignCenter, tr("Worst radius ratio / input's"));
    painter.restore();

    if (isEmpty()) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(plot, Qt::AlignCenter | Qt::TextWordWrap, tr("No tissue."));
        return;
    }

    // The input's level, the curve of the applied cuts, the pending cut, then the points.
    const double one = pixelOf({0, 1}).y();
    painter.setPen(QPen(text, 1, Qt::DotLine));
    painter.drawLine(QPointF(plot.left(), one), QPointF(plot.right(), one));
    const std::vector<QPointF> applied = points();
    QPainterPath path;
    path.moveTo(pixelOf(applied.front()));
    for (std::size_t i = 1; i < applied.size(); ++i)
        path.lineTo(pixelOf(applied[i]));
    painter.setPen(QPen(kCurveColour, 1.5));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(path);
    const auto pending = pendingPoint();
    if (pending) {
        painter.setPen(QPen(kCurveColour, 1.5, Qt::DashLine));
        painter.drawLine(pixelOf(applied.back()), pixelOf(*pending));
    }
    painter.setPen(QPen(kCurveColour.darker(140), 1));
    painter.setBrush(kCurveColour);
    for (const QPointF& p : applied)
        painter.drawEllipse(pixelOf(p), kMarkerSize, kMarkerSize);
    if (pending) {
        painter.setBrush(palette().base());
        painter.drawEllipse(pixelOf(*pending), kMarkerSize + 1, kMarkerSize + 1);
    }
    if (applied.size() == 1 && !pending) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(plot.adjusted(0, plot.height() / 2, 0, 0), Qt::AlignCenter | Qt::TextWordWrap,
                         tr("No cuts yet."));
    }
}

bool QualityCurve::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const int index = pointAt(help->pos());
        if (index >= 0) {
            QToolTip::showText(help->globalPos(), pointToolTip(index), this);
        } else {
            QToolTip::hideText();
            event->ignore();
        }
        return true;
    }
    return QWidget::event(event);
}

} // namespace resect
