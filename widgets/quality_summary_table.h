#pragma once
// QualitySummaryTable: the rows of the paper's Table 1 (section 6) for the mesh before and
// after a cut, side by side: nodes, edges, tets, min radius ratio, the paper's tet_minAR
// (radius ratio / 3), volume ratio Vmax/Vmin, edge ratio lmax/lmin, min and max dihedral
// angle (degrees) and the stable explicit time step (core/mesh/stable_time_step.h); below
// them, how deep the mesh overlaps itself (deepestOverlap, core/mesh/validity.h: 0 for a
// conforming mesh; issue 16's known defect where both walls of a crack stay).
//
// Cells hold plain numbers (integers, or QString::number(v, 'g', 6)), "∞" for an infinite
// ratio and "—" where a column or value is missing (no "after" yet, dt not computed).

#include "core/mesh/quality.h"

#include <QTableWidget>

namespace resect {

class QualitySummaryTable : public QTableWidget {
    Q_OBJECT

public:
    /// Row order of the table.
    enum Row {
        Nodes,
        Edges,
        Tets,
        MinRadiusRatio,
        MinAspectRatioPaper,
        VolumeRatio,
        EdgeRatio,
        MinDihedral,
        MaxDihedral,
        StableTimeStep,
        Overlap,
        RowCount
    };
    enum Column { Before, After, ColumnCount };

    explicit QualitySummaryTable(QWidget* parent = nullptr);

    /// Fills a column; `stableDt` <= 0 or non-finite shows "—" (not computed), and so does a
    /// negative or non-finite `overlap` (model units).
    void setSummary(Column column, const QualitySummary& summary, double stableDt, double overlap = -1);
    /// Shows "—" in every row of the column.
    void clearSummary(Column column);

    /// The text of a cell (for tests and copying).
    QString value(Row row, Column column) const;
};

} // namespace resect
