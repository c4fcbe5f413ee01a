#include "widgets/quality_summary_table.h"

#include <QHeaderView>

#include <cmath>

namespace resect {

namespace {

const QString kMissing = QStringLiteral("—");

QString number(double v) {
    if (std::isinf(v))
        return v > 0 ? QStringLiteral("∞") : QStringLiteral("-∞");
    if (std::isnan(v))
        return kMissing;
    return QString::number(v, 'g', 6);
}

} // namespace

QualitySummaryTable::QualitySummaryTable(QWidget* parent)
    : QTableWidget(RowCount, ColumnCount, parent) {
    setObjectName(QStringLiteral("qualitySummaryTable"));
    setHorizontalHeaderLabels({tr("before"), tr("after")});
    setVerticalHeaderLabels({tr("Nodes"), tr("Edges"), tr("Tets"), tr("Min. radius ratio"),
                             tr("tet_minAR (radius ratio / 3)"), tr("Volume ratio Vmax/Vmin"),
                             tr("Edge ratio lmax/lmin"), tr("Min. dihedral (°)"),
                             tr("Max. dihedral (°)"), tr("Stable dt (s)"),
                             tr("Overlap (mm)")});
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionMode(QAbstractItemView::ContiguousSelection);
    horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    for (int r = 0; r < RowCount; ++r)
        for (int c = 0; c < ColumnCount; ++c) {
            auto* item = new QTableWidgetItem(kMissing);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            setItem(r, c, item);
        }
}

void QualitySummaryTable::setSummary(Column column, const QualitySummary& s, double stableDt, double overlap) {
    auto set = [&](Row row, const QString& text) { item(row, column)->setText(text); };
    set(Nodes, QString::number(s.nodes));
    set(Edges, QString::number(s.edges));
    set(Tets, QString::number(s.tets));
    set(MinRadiusRatio, number(s.minRadiusRatio));
    set(MinAspectRatioPaper, number(s.minAspectRatioPaper));
    set(VolumeRatio, number(s.volumeRatio));
    set(EdgeRatio, number(s.edgeRatio));
    set(MinDihedral, number(s.minDihedralDeg));
    set(MaxDihedral, number(s.maxDihedralDeg));
    set(StableTimeStep, std::isfinite(stableDt) && stableDt > 0 ? number(stableDt) : kMissing);
    set(Overlap, std::isfinite(overlap) && overlap >= 0 ? number(overlap) : kMissing);
}

void QualitySummaryTable::clearSummary(Column column) {
    for (int r = 0; r < RowCount; ++r)
        item(r, column)->setText(kMissing);
}

QString QualitySummaryTable::value(Row row, Column column) const {
    const QTableWidgetItem* cell = item(row, column);
    return cell != nullptr ? cell->text() : QString();
}

} // namespace resect
