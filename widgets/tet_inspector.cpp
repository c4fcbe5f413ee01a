#include "widgets/tet_inspector.h"

#include "core/mesh/quality.h"

#include <QFormLayout>
#include <QLabel>

#include <numbers>

namespace resect {

namespace {

QString number(double v) {
    return QString::number(v, 'g', 6);
}

const QString kNone = QStringLiteral("—");

} // namespace

TetInspector::TetInspector(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("tetInspector"));
    m_form = new QFormLayout(this);
    m_index = addValue(QStringLiteral("tetIndex"), tr("Tet"));
    for (int k = 0; k < 4; ++k)
        m_nodes[k] = addValue(QStringLiteral("tetNode%1").arg(k), tr("Node %1").arg(k));
    m_refVolume = addValue(QStringLiteral("referenceVolume"), tr("Reference volume"));
    m_curVolume = addValue(QStringLiteral("currentVolume"), tr("Current volume"));
    m_radiusRatio = addValue(QStringLiteral("radiusRatio"), tr("Radius ratio"));
    m_minDihedral = addValue(QStringLiteral("minDihedral"), tr("Min. dihedral (°)"));
    m_maxDihedral = addValue(QStringLiteral("maxDihedral"), tr("Max. dihedral (°)"));
    m_minEdge = addValue(QStringLiteral("minEdge"), tr("Min. edge"));
    m_maxEdge = addValue(QStringLiteral("maxEdge"), tr("Max. edge"));
    m_scheme = addValue(QStringLiteral("tetScheme"), tr("Scheme"));
    clear();
}

QLabel* TetInspector::addValue(const QString& objectName, const QString& label) {
    auto* value = new QLabel(this);
    value->setObjectName(objectName);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_form->addRow(label, value);
    return value;
}

QString TetInspector::schemeText(Scheme scheme) {
    if (scheme == Scheme::None)
        return tr("original");
    return QString::fromLatin1(schemeName(scheme));
}

void TetInspector::clear() {
    m_tet = -1;
    for (QLabel* label : findChildren<QLabel*>()) {
        if (!label->objectName().isEmpty())
            label->setText(kNone);
    }
}

void TetInspector::setTet(const TetMesh& mesh, int tet, Scheme scheme) {
    if (tet < 0 || tet >= mesh.tetCount()) {
        clear();
        return;
    }
    m_tet = tet;
    const Tet& nodes = mesh.tet(tet);
    m_index->setText(QString::number(tet));
    for (int k = 0; k < 4; ++k) {
        const Vec3& p = mesh.ref(nodes[k]);
        m_nodes[k]->setText(QStringLiteral("%1: (%2, %3, %4)")
                                .arg(nodes[k])
                                .arg(number(p.x()), number(p.y()), number(p.z())));
    }
    const TetQuality q =
        tetQuality(mesh.ref(nodes[0]), mesh.ref(nodes[1]), mesh.ref(nodes[2]), mesh.ref(nodes[3]));
    constexpr double kDeg = 180.0 / std::numbers::pi;
    m_refVolume->setText(number(mesh.referenceVolume(tet)));
    m_curVolume->setText(number(mesh.currentVolume(tet)));
    m_radiusRatio->setText(number(q.radiusRatio));
    m_minDihedral->setText(number(q.minDihedral * kDeg));
    m_maxDihedral->setText(number(q.maxDihedral * kDeg));
    m_minEdge->setText(number(q.minEdge));
    m_maxEdge->setText(number(q.maxEdge));
    m_scheme->setText(schemeText(scheme));
}

} // namespace resect
