#pragma once
// TetInspector: the measures of one tet (issue 8, "click a tet to inspect it"): its index,
// its four nodes (index and reference position), signed reference and current volume,
// radius ratio, min/max dihedral angle (degrees), min/max edge length (reference), and the
// decomposition scheme (Figure 4) that produced it ("original" when none).
//
// Every value is a QLabel with an objectName, its text a plain number (QString::number,
// 'g', 6 significant digits, locale independent) so that tests and tools can read it back:
//   "tetIndex", "tetNode0".."tetNode3" ("index: (x, y, z)"), "referenceVolume",
//   "currentVolume", "radiusRatio", "minDihedral", "maxDihedral", "minEdge", "maxEdge",
//   "tetScheme". Cleared (every value "—") by setTet(mesh, -1) or clear().

#include "core/cut/cut_types.h"
#include "core/mesh/tet_mesh.h"

#include <QWidget>

#include <array>

class QFormLayout;
class QLabel;

namespace resect {

class TetInspector : public QWidget {
    Q_OBJECT

public:
    explicit TetInspector(QWidget* parent = nullptr);

    /// Shows tet `tet` of the mesh (quality in the reference configuration, see
    /// core/mesh/quality.h); an index outside the mesh clears the view.
    void setTet(const TetMesh& mesh, int tet, Scheme scheme = Scheme::None);
    void clear();
    /// The tet shown, -1 when cleared.
    int tet() const { return m_tet; }

    /// Text shown for a scheme: "original" for Scheme::None, else its letter (schemeName).
    static QString schemeText(Scheme scheme);

private:
    QLabel* addValue(const QString& objectName, const QString& label);

    int m_tet = -1;
    QLabel* m_index = nullptr;
    std::array<QLabel*, 4> m_nodes{};
    QLabel* m_refVolume = nullptr;
    QLabel* m_curVolume = nullptr;
    QLabel* m_radiusRatio = nullptr;
    QLabel* m_minDihedral = nullptr;
    QLabel* m_maxDihedral = nullptr;
    QLabel* m_minEdge = nullptr;
    QLabel* m_maxEdge = nullptr;
    QLabel* m_scheme = nullptr;
    QFormLayout* m_form = nullptr;
};

} // namespace resect
