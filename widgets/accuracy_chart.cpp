#include "widgets/accuracy_chart.h"
#include "widgets/chart_axes.h"

#include <QHelpEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <cmath>
#include <limits>

namespace resect {

namespace {

constexpr double kPickRadius = 6.0; ///< px: how near a click must be to a point
constexpr double kMarkerSize = 4.5; ///< px: half the marker's width
constexpr double kLeft = 64, kRight = 16,
                 kBottom = 44;     ///< px: margins around the axes (top: the legend)
constexpr double kLegendLine = 18; ///< px: one line of the legend
constexpr double kSymbolWidth = 2 * kMarkerSize + 5; ///< px: a legend symbol and its gap
/// Points nearer than this (px) to each other are spread on a circle of kSpreadRadius.
constexpr double kCoincident = 1.5;
constexpr double kSpreadRadius = 2.2 * kMarkerSize;
/// A drag smaller than this (px) either way is a click, not a zoom rectangle.
constexpr double kMinZoomDrag = 6.0;

const char* const kKnownMethods[] = {"subdivision", "hybrid-standard", "hybrid-enhanced"};

void drawMarker(QPainter& painter, const std::string& method, QPointF c, double s) {
    if (method == "subdivision") {
        painter.drawRect(QRectF(c.x() - s, c.y() - s, 2 * s, 2 * s));
    } else if (method == "hybrid-standard") {
        const QPointF tri[3] = {{c.x(), c.y() - 1.2 * s},
                                {c.x() - 1.1 * s, c.y() + 0.9 * s},
                                {c.x() + 1.1 * s, c.y() + 0.9 * s}};
        painter.drawPolygon(tri, 3);
    } else if (method == "hybrid-enhanced") {
        painter.drawEllipse(c, s, s);
    } else {
        const QPointF diamond[4] = {{c.x(), c.y() - 1.3 * s},
                                    {c.x() + 1.3 * s, c.y()},
                                    {c.x(), c.y() + 1.3 * s},
                                    {c.x() - 1.3 * s, c.y()}};
        painter.drawPolygon(diamond, 4);
    }
}

} // namespace

AccuracyChart::AccuracyChart(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("accuracyChart"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setMouseTracking(true);
}

void AccuracyChart::setRows(std::vector<StudyRow> rows) {
    m_rows = std::move(rows);
    m_selected = -1;
    if (m_rows.empty()) // a new study or tissue: show all of what comes
        m_zoom.reset();
    m_dragStart.reset();
    update();
}

void AccuracyChart::setCostAxis(CostAxis axis) {
    if (axis != m_axis)
        m_zoom.reset(); // the zoomed x range was of the other cost
    m_axis = axis;
    update();
}

double AccuracyChart::cost(const StudyRow& row) const {
    return m_axis == CostAxis::CutMs ? row.cutMs : row.simMsPerSecond;
}

void AccuracyChart::setSelectedRow(int row) {
    m_selected = row >= 0 && row < static_cast<int>(m_rows.size()) ? row : -1;
    update();
}

QString AccuracyChart::methodLabel(const std::string& method) {
    if (method == "subdivision")
        return tr("Subdivision");
    if (method == "hybrid-standard")
        return tr("Hybrid, standard triangulation");
    if (method == "hybrid-enhanced")
        return tr("Hybrid, enhanced triangulation");
    return QString::fromStdString(method);
}

QColor AccuracyChart::methodColour(const std::string& method) {
    if (method == "subdivision")
        return QColor(200, 70, 60);
    if (method == "hybrid-standard")
        return QColor(60, 120, 200);
    if (method == "hybrid-enhanced")
        return QColor(40, 160, 90);
    return QColor(130, 130, 130);
}

std::vector<std::string> AccuracyChart::methods() const {
    std::vector<std::string> out;
    for (const char* m : kKnownMethods)
        if (std::any_of(m_rows.begin(), m_rows.end(),
                        [&](const StudyRow& r) { return r.method == m; }))
            out.emplace_back(m);
    for (const StudyRow& r : m_rows)
        if (std::find(out.begin(), out.end(), r.method) == out.end())
            out.push_back(r.method);
    return out;
}

std::vector<AccuracyChart::LegendItem> AccuracyChart::legendLayout(double& height) const {
    std::vector<LegendItem> items;
    for (const std::string& method : methods())
        items.push_back({method, methodLabel(method), {}});
    if (!items.empty())
        items.push_back({std::string(), tr("Pareto front"), {}});
    const QFontMetricsF fm(font());
    const double right = std::max(kLeft + 100, width() - kRight);
    double x = kLeft, y = 4 + kLegendLine / 2;
    for (LegendItem& item : items) {
        const double w = kSymbolWidth + fm.horizontalAdvance(item.label) + 16;
        if (x > kLeft && x + w > right) {
            x = kLeft;
            y += kLegendLine;
        }
        item.position = QPointF(x, y);
        x += w;
    }
    height = y + kLegendLine / 2 + 6;
    return items;
}

QRectF AccuracyChart::plotRect() const {
    double top = 0;
    legendLayout(top);
    top = std::max(top, 30.0);
    return QRectF(kLeft, top, std::max(10.0, width() - kLeft - kRight),
                  std::max(10.0, height() - top - kBottom));
}

double AccuracyChart::logCost(const StudyRow& row) const {
    const double c = cost(row);
    return std::isfinite(c) && c > 0 ? std::log10(c) : std::numeric_limits<double>::quiet_NaN();
}

AccuracyChart::Ranges AccuracyChart::ranges() const {
    if (m_zoom)
        return *m_zoom;
    Ranges r;
    double xLo = std::numeric_limits<double>::infinity(), xHi = -xLo, yHi = 0;
    for (const StudyRow& row : m_rows) {
        const double x = logCost(row);
        if (std::isfinite(x)) {
            xLo = std::min(xLo, x);
            xHi = std::max(xHi, x);
        }
        if (std::isfinite(row.sweepErrorMax))
            yHi = std::max(yHi, row.sweepErrorMax);
    }
    if (!(xLo <= xHi)) {
        xLo = 0;
        xHi = 1;
    }
    // At least 0.4 decades wide, with a margin of a tenth of a decade on either side.
    const double mid = 0.5 * (xLo + xHi);
    const double half = std::max(0.2, 0.5 * (xHi - xLo) + 0.1);
    r.xLo = mid - half;
    r.xHi = mid + half;
    const double step = niceStep(std::max(0.01, 1.1 * yHi) / 5);
    r.yHi = step * std::ceil(std::max(0.01, 1.1 * yHi) / step - 1e-9);
    r.yLo = -0.03 * r.yHi; // exact cuts (error 0) just above the axis
    return r;
}

QPointF AccuracyChart::toPixel(double x, double y, const Ranges& r, const QRectF& plot) const {
    if (!std::isfinite(x))
        x = r.xLo; // no cost measured: on the left edge
    if (!std::isfinite(y))
        y = r.yHi; // no error measured: on the top edge
    const double fx = (x - r.xLo) / (r.xHi - r.xLo);
    // Unzoomed, every point is inside the ranges (clamped for safety); zoomed, points outside
    // fall outside the plot, where painting clips them and picking ignores them.
    const double fy = ((m_zoom ? y : std::clamp(y, r.yLo, r.yHi)) - r.yLo) / (r.yHi - r.yLo);
    return {plot.left() + fx * plot.width(), plot.bottom() - fy * plot.height()};
}

QPointF AccuracyChart::dataPosition(int row) const {
    if (row < 0 || row >= static_cast<int>(m_rows.size()))
        return {-1, -1};
    const StudyRow& r = m_rows[static_cast<std::size_t>(row)];
    return toPixel(logCost(r), r.sweepErrorMax, ranges(), plotRect());
}

std::vector<QPointF> AccuracyChart::drawnPositions() const {
    const Ranges r = ranges();
    const QRectF plot = plotRect();
    std::vector<QPointF> at;
    at.reserve(m_rows.size());
    for (const StudyRow& row : m_rows)
        at.push_back(toPixel(logCost(row), row.sweepErrorMax, r, plot));
    // Groups of coincident points (each point joins the group of the first earlier point it
    // coincides with), spread evenly on a circle around the group's place.
    const std::size_t n = at.size();
    std::vector<std::size_t> group(n);
    for (std::size_t i = 0; i < n; ++i) {
        group[i] = i;
        for (std::size_t j = 0; j < i; ++j)
            if (group[j] == j && std::hypot(at[i].x() - at[j].x(), at[i].y() - at[j].y()) < kCoincident) {
                group[i] = j;
                break;
            }
    }
    std::vector<int> size(n, 0), rank(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        rank[i] = size[group[i]]++;
    std::vector<QPointF> drawn = at;
    for (std::size_t i = 0; i < n; ++i) {
        const int count = size[group[i]];
        if (count < 2)
            continue;
        const double angle = 2.0 * M_PI * rank[i] / count - M_PI / 2;
        drawn[i] = at[group[i]] + QPointF(kSpreadRadius * std::cos(angle), kSpreadRadius * std::sin(angle));
    }
    return drawn;
}

QPointF AccuracyChart::pointPosition(int row) const {
    if (row < 0 || row >= static_cast<int>(m_rows.size()))
        return {-1, -1};
    return drawnPositions()[static_cast<std::size_t>(row)];
}

void AccuracyChart::zoomTo(const QRectF& pixels) {
    const QRectF box = pixels.normalized();
    if (box.width() < kMinZoomDrag || box.height() < kMinZoomDrag)
        return;
    const Ranges r = ranges();
    const QRectF plot = plotRect();
    const auto toX = [&](double px) { return r.xLo + (px - plot.left()) / plot.width() * (r.xHi - r.xLo); };
    const auto toY = [&](double py) { return r.yLo + (plot.bottom() - py) / plot.height() * (r.yHi - r.yLo); };
    Ranges z;
    z.xLo = toX(box.left());
    z.xHi = toX(box.right());
    z.yLo = toY(box.bottom());
    z.yHi = toY(box.top());
    if (!(z.xHi > z.xLo) || !(z.yHi > z.yLo))
        return;
    m_zoom = z;
    update();
}

void AccuracyChart::resetZoom() {
    m_zoom.reset();
    update();
}

QString AccuracyChart::costLabel(double logValue, const QLocale& locale) {
    const double value = std::pow(10.0, logValue);
    const int decade = static_cast<int>(std::floor(logValue + 1e-9));
    if (decade >= -3 && decade <= 4) {
        if (value >= 1.0 && std::abs(value - std::round(value)) < 1e-6 * value)
            return locale.toString(static_cast<qlonglong>(std::llround(value)));
        return locale.toString(value, 'g', 4); // below 10^5: never an exponent
    }
    static const char16_t* const digits[] = {u"\u2070", u"\u00b9", u"\u00b2", u"\u00b3", u"\u2074",
                                             u"\u2075", u"\u2076", u"\u2077", u"\u2078", u"\u2079"};
    QString exponent;
    for (const QChar c : QString::number(std::abs(decade)))
        exponent += QString::fromUtf16(digits[c.digitValue()]);
    if (decade < 0)
        exponent.prepend(QChar(0x207B)); // superscript minus
    const double mantissa = value / std::pow(10.0, decade);
    const QString power = QStringLiteral("10") + exponent;
    if (std::abs(mantissa - 1.0) < 1e-6)
        return power;
    return locale.toString(mantissa, 'g', 3) + QChar(0x00D7) + power;
}

int AccuracyChart::rowAt(QPointF pixel) const {
    const std::vector<QPointF> drawn = drawnPositions();
    int best = -1;
    double bestDist = kPickRadius;
    const QRectF visible = plotRect().adjusted(-kMarkerSize, -kMarkerSize, kMarkerSize, kMarkerSize);
    for (int i = 0; i < static_cast<int>(drawn.size()); ++i) {
        const QPointF p = drawn[static_cast<std::size_t>(i)];
        if (m_zoom && !visible.contains(p))
            continue; // zoomed out of view
        const double dist = std::hypot(p.x() - pixel.x(), p.y() - pixel.y());
        if (dist <= bestDist && (best < 0 || dist < bestDist)) {
            best = i;
            bestDist = dist;
        }
    }
    return best;
}

std::vector<int> AccuracyChart::paretoFront(const std::string& method) const {
    std::vector<int> rows;
    for (int i = 0; i < static_cast<int>(m_rows.size()); ++i) {
        const StudyRow& r = m_rows[static_cast<std::size_t>(i)];
        if (r.method == method && std::isfinite(cost(r)) && std::isfinite(r.sweepErrorMax))
            rows.push_back(i);
    }
    std::sort(rows.begin(), rows.end(), [&](int a, int b) {
        const StudyRow& ra = m_rows[static_cast<std::size_t>(a)];
        const StudyRow& rb = m_rows[static_cast<std::size_t>(b)];
        const double ca = cost(ra), cb = cost(rb);
        return ca != cb ? ca < cb : ra.sweepErrorMax < rb.sweepErrorMax;
    });
    // By increasing cost, a row is on the front if it is more accurate than every cheaper one.
    std::vector<int> front;
    double best = std::numeric_limits<double>::infinity();
    for (int i : rows) {
        const double e = m_rows[static_cast<std::size_t>(i)].sweepErrorMax;
        if (e < best) {
            front.push_back(i);
            best = e;
        }
    }
    return front;
}

QString AccuracyChart::rowToolTip(int row) const {
    if (row < 0 || row >= static_cast<int>(m_rows.size()))
        return {};
    const StudyRow& r = m_rows[static_cast<std::size_t>(row)];
    const QLocale locale;
    const auto num = [&](double v, int digits = 3) { return locale.toString(v, 'g', digits); };
    QStringList lines;
    lines << tr("%1 on %2").arg(methodLabel(r.method), QString::fromStdString(r.mesh));
    lines << tr("d = %1, snapping %2, %n relaxation step(s)", nullptr, r.relaxSteps)
                 .arg(num(r.d), r.snap ? tr("on") : tr("off"));
    lines << tr("Cut-face error: max %1, mean %2 mean edge lengths")
                 .arg(num(r.sweepErrorMax), num(r.sweepErrorMean));
    lines << tr("Tets: %1 (%2 added); worst radius ratio %3")
                 .arg(r.tets)
                 .arg(r.addedTets)
                 .arg(num(r.minRadiusRatio));
    lines << tr("Stable time step: %1 s").arg(num(r.stableDt));
    lines << tr("Cut: %1 ms; simulation: %2 ms per simulated second")
                 .arg(num(r.cutMs), num(r.simMsPerSecond));
    return lines.join(QLatin1Char('\n'));
}

QSize AccuracyChart::sizeHint() const {
    return {480, 320};
}

QSize AccuracyChart::minimumSizeHint() const {
    return {240, 160};
}

void AccuracyChart::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    const QRectF plot = plotRect();
    const Ranges r = ranges();
    const QLocale locale;
    const QColor text = palette().color(QPalette::Text);
    const QColor grid = palette().color(QPalette::Mid);
    const QFontMetricsF fm(font());

    // Grid, ticks and tick labels. x: decades, with 2 and 5 between when few decades show.
    painter.setPen(QPen(grid, 0, Qt::DotLine));
    std::vector<double> xTicks;
    const bool fine = r.xHi - r.xLo <= 2.5;
    if (r.xHi - r.xLo < 1.0) {
        // Less than a decade (zoomed in): evenly spaced round values.
        const double lo = std::pow(10.0, r.xLo), hi = std::pow(10.0, r.xHi);
        const double step = niceStep((hi - lo) / 4);
        for (double v = step * std::ceil(lo / step); v <= hi; v += step)
            xTicks.push_back(std::log10(v));
    } else {
        for (int k = static_cast<int>(std::floor(r.xLo)); k <= static_cast<int>(std::ceil(r.xHi)); ++k)
            for (double m : fine ? std::vector<double>{1, 2, 5} : std::vector<double>{1}) {
                const double x = k + std::log10(m);
                if (x >= r.xLo && x <= r.xHi)
                    xTicks.push_back(x);
            }
    }
    for (double x : xTicks) {
        const double px = toPixel(x, r.yLo, r, plot).x();
        painter.setPen(QPen(grid, 0, Qt::DotLine));
        painter.drawLine(QPointF(px, plot.top()), QPointF(px, plot.bottom()));
        painter.setPen(text);
        painter.drawLine(QPointF(px, plot.bottom()), QPointF(px, plot.bottom() + 4));
        const QString label = costLabel(x, locale);
        painter.drawText(QRectF(px - 40, plot.bottom() + 5, 80, fm.height()),
                         Qt::AlignHCenter | Qt::AlignTop, label);
    }
    const double yStep = niceStep((r.yHi - std::max(0.0, r.yLo)) / 5);
    for (double y = std::max(0.0, yStep * std::ceil(r.yLo / yStep - 1e-9)); y <= r.yHi + 1e-9 * yStep; y += yStep) {
        const double py = toPixel(r.xLo, y, r, plot).y();
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
    const QString xTitle = m_axis == CostAxis::CutMs
                               ? tr("Cut time (ms, log scale)")
                               : tr("Simulation cost (ms per simulated second, log scale)");
    painter.drawText(QRectF(plot.left(), height() - fm.height() - 2, plot.width(), fm.height()),
                     Qt::AlignHCenter, xTitle);
    painter.save();
    painter.translate(fm.height() / 2 + 2, plot.center().y());
    painter.rotate(-90);
    painter.drawText(QRectF(-plot.height() / 2, -fm.height() / 2, plot.height(), fm.height()),
                     Qt::AlignCenter, tr("Cut-face error, max (mean edge lengths)"));
    painter.restore();

    if (m_rows.empty()) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(plot, Qt::AlignCenter | Qt::TextWordWrap,
                         tr("Run the study to see what accuracy costs."));
    }

    const std::vector<std::string> present = methods();
    // Pareto fronts, then the points on top.
    painter.setClipRect(
        plot.adjusted(-kMarkerSize - 2, -kMarkerSize - 2, kMarkerSize + 2, kMarkerSize + 2));
    for (const std::string& method : present) {
        const std::vector<int> front = paretoFront(method);
        if (front.size() < 2)
            continue;
        QPainterPath path;
        for (std::size_t i = 0; i < front.size(); ++i) {
            const StudyRow& row = m_rows[static_cast<std::size_t>(front[i])];
            const QPointF p = toPixel(logCost(row), row.sweepErrorMax, r, plot);
            if (i == 0)
                path.moveTo(p);
            else
                path.lineTo(p);
        }
        painter.setPen(QPen(methodColour(method), 1.5));
        painter.setBrush(Qt::NoBrush);
        painter.drawPath(path);
    }
    const std::vector<QPointF> drawn = drawnPositions();
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        const StudyRow& row = m_rows[i];
        const QColor c = methodColour(row.method);
        // A spread point is tied to its data position by a thin line.
        const QPointF at = toPixel(logCost(row), row.sweepErrorMax, r, plot);
        if (std::hypot(drawn[i].x() - at.x(), drawn[i].y() - at.y()) > kCoincident) {
            painter.setPen(QPen(grid, 0));
            painter.drawLine(at, drawn[i]);
        }
        painter.setPen(QPen(c.darker(140), 1));
        painter.setBrush(QColor(c.red(), c.green(), c.blue(), 170));
        drawMarker(painter, row.method, drawn[i], kMarkerSize);
    }
    if (m_selected >= 0 && m_selected < static_cast<int>(drawn.size())) {
        painter.setPen(QPen(text, 2));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(drawn[static_cast<std::size_t>(m_selected)], kMarkerSize + 4, kMarkerSize + 4);
    }
    painter.setClipping(false);
    if (m_dragStart) {
        painter.setPen(QPen(palette().color(QPalette::Highlight), 1, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(QRectF(*m_dragStart, m_dragNow).normalized());
    }
    if (m_zoom) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(plot.adjusted(4, 2, -4, -2), Qt::AlignRight | Qt::AlignTop,
                         tr("Zoomed: double-click to show all"));
    }

    // Legend along the top: one marker per method present, then the front's line.
    double legendHeight = 0;
    for (const LegendItem& item : legendLayout(legendHeight)) {
        const QPointF p = item.position;
        if (item.method.empty()) {
            painter.setPen(QPen(text, 1.5));
            painter.drawLine(QPointF(p.x() - 4, p.y()), QPointF(p.x() + kSymbolWidth - 2, p.y()));
        } else {
            const QColor c = methodColour(item.method);
            painter.setPen(QPen(c.darker(140), 1));
            painter.setBrush(QColor(c.red(), c.green(), c.blue(), 170));
            drawMarker(painter, item.method, QPointF(p.x() + kMarkerSize, p.y()), kMarkerSize);
        }
        painter.setPen(text);
        painter.drawText(
            QRectF(p.x() + kSymbolWidth + 2, p.y() - fm.height() / 2, width(), fm.height()),
            Qt::AlignLeft | Qt::AlignVCenter, item.label);
    }
}

void AccuracyChart::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::RightButton && m_zoom) {
        resetZoom();
        event->accept();
        return;
    }
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    const int row = rowAt(event->position());
    if (row >= 0) {
        setSelectedRow(row);
        emit rowClicked(row);
    } else if (plotRect().contains(event->position())) {
        m_dragStart = event->position();
        m_dragNow = event->position();
    }
    event->accept();
}

void AccuracyChart::mouseMoveEvent(QMouseEvent* event) {
    if (!m_dragStart) {
        QWidget::mouseMoveEvent(event);
        return;
    }
    m_dragNow = event->position();
    update();
    event->accept();
}

void AccuracyChart::mouseReleaseEvent(QMouseEvent* event) {
    if (!m_dragStart || event->button() != Qt::LeftButton) {
        QWidget::mouseReleaseEvent(event);
        return;
    }
    const QRectF box(*m_dragStart, event->position());
    m_dragStart.reset();
    zoomTo(box); // ignored when it was a click
    update();
    event->accept();
}

void AccuracyChart::mouseDoubleClickEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) {
        QWidget::mouseDoubleClickEvent(event);
        return;
    }
    const int row = rowAt(event->position());
    if (row >= 0) {
        setSelectedRow(row);
        emit rowDoubleClicked(row);
    } else {
        m_dragStart.reset();
        resetZoom();
    }
    event->accept();
}

bool AccuracyChart::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const int row = rowAt(help->pos());
        if (row >= 0) {
            QToolTip::showText(help->globalPos(), rowToolTip(row), this);
        } else {
            QToolTip::hideText();
            event->ignore();
        }
        return true;
    }
    return QWidget::event(event);
}

} // namespace resect
