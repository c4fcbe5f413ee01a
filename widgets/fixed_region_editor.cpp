#include "widgets/fixed_region_editor.h"

#include "scenario/scene_defaults.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include <QDoubleSpinBox>
#include <QFrame>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace resect {

namespace {

/// mm: the range of a corner's coordinate in the editor (a metre: beyond any anatomy, and
/// narrow enough for the dock).
constexpr double kMaxCoordinateMm = 1e3;

} // namespace

FixedRegionEditor::FixedRegionEditor(ScenarioDocument& document, TissueSession& session,
                                     QWidget* parent)
    : QWidget(parent), m_document(document), m_session(session) {
    setObjectName(QStringLiteral("fixedRegionEditor"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_rowsLayout = new QVBoxLayout;
    m_rowsLayout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(m_rowsLayout);
    auto* bottom = new QHBoxLayout;
    m_add = new QPushButton(tr("Add base box"));
    m_add->setObjectName(QStringLiteral("addFixedRegion"));
    m_add->setToolTip(
        tr("A box around the bottom %1 % of the tissue's height").arg(100 * kBaseRegionFraction));
    bottom->addWidget(m_add);
    m_inView = new QPushButton(tr("Place in view"));
    m_inView->setObjectName(QStringLiteral("editRegionsInView"));
    m_inView->setCheckable(true);
    m_inView->setToolTip(tr("Draws the boxes in the view: drag a face's handle to move that face "
                            "(red x, green y, blue z); drag elsewhere to turn the view"));
    bottom->addWidget(m_inView);
    m_anchoredLabel = new QLabel;
    m_anchoredLabel->setObjectName(QStringLiteral("anchoredNodes"));
    m_anchoredLabel->setWordWrap(true);
    bottom->addWidget(m_anchoredLabel, 1);
    layout->addLayout(bottom);

    connect(m_add, &QPushButton::clicked, this, &FixedRegionEditor::addBaseRegion);
    connect(m_inView, &QPushButton::toggled, this, [this](bool on) {
        if (!m_syncing)
            emit editInViewToggled(on);
    });
    connect(&m_document, &ScenarioDocument::fixedRegionsChanged, this,
            &FixedRegionEditor::syncFromDocument);
    connect(&m_document, &ScenarioDocument::documentReset, this,
            &FixedRegionEditor::syncFromDocument);
    connect(&m_session, &TissueSession::currentChanged, this, &FixedRegionEditor::updateCounts);
    connect(&m_session, &TissueSession::baseChanged, this, &FixedRegionEditor::updateCounts);
    syncFromDocument();
}

QDoubleSpinBox* FixedRegionEditor::coordinateBox(int region, bool max, int axis) const {
    if (region < 0 || region >= regionCount() || axis < 0 || axis > 2)
        return nullptr;
    return m_rows[static_cast<std::size_t>(region)]
        .coordinates[static_cast<std::size_t>((max ? 3 : 0) + axis)];
}

std::optional<FixedRegion> FixedRegionEditor::baseRegionOfTissue() const {
    const auto base = m_session.base();
    if (!base || base->tissue.empty())
        return std::nullopt;
    return baseRegion(base->mesh().referencePositions());
}

void FixedRegionEditor::setEditingInView(bool editing) {
    m_syncing = true;
    m_inView->setChecked(editing);
    m_syncing = false;
}

void FixedRegionEditor::addRow(int index) {
    Row row;
    row.widget = new QFrame;
    row.widget->setObjectName(QStringLiteral("region%1").arg(index));
    auto* grid = new QGridLayout(row.widget);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("Box %1 (mm)").arg(index + 1)), 0, 0);
    const char* axes = "XYZ";
    for (int k = 0; k < 3; ++k)
        grid->addWidget(new QLabel(QString(QLatin1Char(axes[k]))), 0, 1 + k, Qt::AlignHCenter);
    for (int corner = 0; corner < 2; ++corner) {
        grid->addWidget(new QLabel(corner == 0 ? tr("min") : tr("max")), 1 + corner, 0);
        for (int k = 0; k < 3; ++k) {
            auto* box = new QDoubleSpinBox;
            box->setObjectName(QStringLiteral("region%1%2%3")
                                   .arg(index)
                                   .arg(corner == 0 ? QStringLiteral("Min") : QStringLiteral("Max"))
                                   .arg(QLatin1Char(axes[k])));
            box->setRange(-kMaxCoordinateMm, kMaxCoordinateMm);
            box->setDecimals(2);
            box->setSingleStep(0.5);
            box->setKeyboardTracking(false);
            grid->addWidget(box, 1 + corner, 1 + k);
            row.coordinates[static_cast<std::size_t>(3 * corner + k)] = box;
            connect(box, &QDoubleSpinBox::valueChanged, this,
                    [this, index] { onCoordinateEdited(index); });
        }
    }
    row.nodes = new QLabel;
    row.nodes->setObjectName(QStringLiteral("region%1Nodes").arg(index));
    grid->addWidget(row.nodes, 3, 0, 1, 3);
    auto* remove = new QPushButton(tr("Remove"));
    remove->setObjectName(QStringLiteral("region%1Remove").arg(index));
    grid->addWidget(remove, 3, 3);
    connect(remove, &QPushButton::clicked, this,
            [this, index] { m_document.removeFixedRegion(index); });
    m_rowsLayout->addWidget(row.widget);
    m_rows.push_back(row);
}

void FixedRegionEditor::syncFromDocument() {
    const std::vector<FixedRegion>& regions = m_document.fixedRegions();
    m_syncing = true;
    if (regions.size() != m_rows.size()) {
        // Later: the Remove button that asked for this may still be in its clicked().
        for (Row& row : m_rows) {
            m_rowsLayout->removeWidget(row.widget);
            row.widget->hide();
            row.widget->setParent(nullptr); // out of findChild's reach at once
            row.widget->deleteLater();
        }
        m_rows.clear();
        for (std::size_t i = 0; i < regions.size(); ++i)
            addRow(static_cast<int>(i));
    }
    for (std::size_t i = 0; i < regions.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            m_rows[i].coordinates[static_cast<std::size_t>(k)]->setValue(regions[i].min[k]);
            m_rows[i].coordinates[static_cast<std::size_t>(3 + k)]->setValue(regions[i].max[k]);
        }
    m_syncing = false;
    m_add->setEnabled(!m_document.scenario().tissues.empty());
    updateCounts();
}

void FixedRegionEditor::onCoordinateEdited(int region) {
    if (m_syncing || region >= regionCount())
        return;
    FixedRegion r = m_document.fixedRegions()[static_cast<std::size_t>(region)];
    const Row& row = m_rows[static_cast<std::size_t>(region)];
    for (int k = 0; k < 3; ++k) {
        r.min[k] = row.coordinates[static_cast<std::size_t>(k)]->value();
        r.max[k] = row.coordinates[static_cast<std::size_t>(3 + k)]->value();
    }
    m_document.setFixedRegion(region, r);
}

void FixedRegionEditor::addBaseRegion() {
    const std::optional<FixedRegion> base = baseRegionOfTissue();
    if (!base) {
        emit notice(tr("A box can be added once the tissue is loaded."));
        return;
    }
    m_document.addFixedRegion(*base);
}

void FixedRegionEditor::updateCounts() {
    const auto base = m_session.base();
    const std::vector<FixedRegion>& regions = m_document.fixedRegions();
    for (std::size_t i = 0; i < m_rows.size() && i < regions.size(); ++i) {
        if (!base) {
            m_rows[i].nodes->clear();
            continue;
        }
        int inside = 0;
        for (const Vec3& p : base->mesh().referencePositions())
            inside += regions[i].contains(p) ? 1 : 0;
        m_rows[i].nodes->setText(inside == 1 ? tr("1 node of the uncut tissue")
                                             : tr("%1 nodes of the uncut tissue").arg(inside));
    }
    const auto current = m_session.current();
    m_anchored = current ? static_cast<int>(current->tissue.anchors().nodes().size()) : -1;
    if (m_anchored < 0)
        m_anchoredLabel->setText(tr("Anchored nodes: not derived yet"));
    else if (regions.empty())
        m_anchoredLabel->setText(tr("No fixed region: nothing is anchored."));
    else
        m_anchoredLabel->setText(m_anchored == 1 ? tr("1 node anchored")
                                                 : tr("%1 nodes anchored").arg(m_anchored));
}

} // namespace resect
