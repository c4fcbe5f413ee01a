#include "widgets/quality_panel.h"

#include "core/mesh/quality.h"
#include "widgets/camera_ray.h"
#include "widgets/quality_curve.h"
#include "widgets/quality_histogram.h"
#include "widgets/quality_summary_table.h"
#include "widgets/tet_inspector.h"
#include "widgets/vtk_viewport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSlider>
#include <QTabWidget>
#include <QVBoxLayout>

#include <vtkScalarBarActor.h>

#include <algorithm>
#include <limits>

namespace resect {

namespace {

constexpr int kClipSliderSteps = 1000;

/// Default "worse than" threshold of the filter for its measure.
double defaultThreshold(QualityMeasure measure) {
    return measure == QualityMeasure::MinDihedral ? 15.0 : 0.3;
}

} // namespace

QualityPanel::QualityPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("qualityPanel"));
    auto* layout = new QVBoxLayout(this);

    // --- display and overlay ---
    auto* display = new QGroupBox(tr("Display"), this);
    auto* form = new QFormLayout(display);
    m_displayMode = new QComboBox(display);
    m_displayMode->setObjectName(QStringLiteral("displayMode"));
    m_displayMode->addItem(tr("Surface"));
    m_displayMode->addItem(tr("Wireframe"));
    m_displayMode->addItem(tr("Shrunk tets"));
    form->addRow(tr("Mode"), m_displayMode);

    m_measure = new QComboBox(display);
    m_measure->setObjectName(QStringLiteral("overlayMeasure"));
    for (QualityMeasure m :
         {QualityMeasure::None, QualityMeasure::RadiusRatio, QualityMeasure::MinDihedral})
        m_measure->addItem(qualityMeasureTitle(m));
    m_measure->setCurrentIndex(static_cast<int>(QualityMeasure::RadiusRatio));
    form->addRow(tr("Colour by"), m_measure);

    auto* rangeRow = new QHBoxLayout;
    m_rangeMin = new QDoubleSpinBox(display);
    m_rangeMin->setObjectName(QStringLiteral("rangeMin"));
    m_rangeMax = new QDoubleSpinBox(display);
    m_rangeMax->setObjectName(QStringLiteral("rangeMax"));
    for (QDoubleSpinBox* box : {m_rangeMin, m_rangeMax}) {
        box->setRange(-1e6, 1e6);
        box->setDecimals(3);
        box->setKeyboardTracking(false);
    }
    m_rangeAuto = new QPushButton(tr("Auto"), display);
    m_rangeAuto->setObjectName(QStringLiteral("rangeAuto"));
    m_rangeAuto->setToolTip(tr("Set the colour range to the range of the data"));
    rangeRow->addWidget(m_rangeMin);
    rangeRow->addWidget(m_rangeMax);
    rangeRow->addWidget(m_rangeAuto);
    form->addRow(tr("Range"), rangeRow);

    auto* filterRow = new QHBoxLayout;
    m_filterEnabled = new QCheckBox(tr("Only tets worse than"), display);
    m_filterEnabled->setObjectName(QStringLiteral("filterEnabled"));
    m_filterThreshold = new QDoubleSpinBox(display);
    m_filterThreshold->setObjectName(QStringLiteral("filterThreshold"));
    m_filterThreshold->setKeyboardTracking(false);
    filterRow->addWidget(m_filterEnabled);
    filterRow->addWidget(m_filterThreshold);
    form->addRow(tr("Filter"), filterRow);

    auto* clipRow = new QHBoxLayout;
    m_clipEnabled = new QCheckBox(tr("Clip"), display);
    m_clipEnabled->setObjectName(QStringLiteral("clipEnabled"));
    m_clipAxis = new QComboBox(display);
    m_clipAxis->setObjectName(QStringLiteral("clipAxis"));
    m_clipAxis->addItems({tr("x"), tr("y"), tr("z"), tr("view direction")});
    m_clipPosition = new QSlider(Qt::Horizontal, display);
    m_clipPosition->setObjectName(QStringLiteral("clipPosition"));
    m_clipPosition->setRange(0, kClipSliderSteps);
    m_clipPosition->setValue(kClipSliderSteps / 2);
    clipRow->addWidget(m_clipEnabled);
    clipRow->addWidget(m_clipAxis);
    clipRow->addWidget(m_clipPosition, 1);
    form->addRow(tr("Clipping"), clipRow);

    m_pickEnabled = new QPushButton(tr("Inspect tets by clicking"), display);
    m_pickEnabled->setObjectName(QStringLiteral("pickEnabled"));
    m_pickEnabled->setCheckable(true);
    form->addRow(QString(), m_pickEnabled);
    layout->addWidget(display);

    // --- embedded views ---
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("qualityTabs"));
    auto* histogramPage = new QWidget(m_tabs);
    auto* histogramLayout = new QVBoxLayout(histogramPage);
    m_histogram = new QualityHistogram(histogramPage);
    m_logScale = new QCheckBox(tr("Logarithmic counts"), histogramPage);
    m_logScale->setObjectName(QStringLiteral("histogramLogScale"));
    histogramLayout->addWidget(m_histogram, 1);
    histogramLayout->addWidget(m_logScale);
    m_tabs->addTab(histogramPage, tr("Histogram"));
    m_table = new QualitySummaryTable(m_tabs);
    m_tabs->addTab(m_table, tr("Summary"));
    m_curve = new QualityCurve(m_tabs);
    m_curve->setToolTip(tr("The worst radius ratio of the tissue after each cut, relative to the "
                           "tissue as created (a pending cut: hollow)"));
    m_tabs->addTab(m_curve, tr("Per cut"));
    m_inspector = new TetInspector(m_tabs);
    m_tabs->addTab(m_inspector, tr("Tet"));
    layout->addWidget(m_tabs, 1);

    configureThreshold(QualityMeasure::RadiusRatio);
    syncRangeControls();

    connect(m_displayMode, &QComboBox::currentIndexChanged, this,
            &QualityPanel::onDisplayModeChanged);
    connect(m_measure, &QComboBox::currentIndexChanged, this, &QualityPanel::onMeasureChanged);
    connect(m_rangeMin, &QDoubleSpinBox::valueChanged, this, &QualityPanel::onRangeChanged);
    connect(m_rangeMax, &QDoubleSpinBox::valueChanged, this, &QualityPanel::onRangeChanged);
    connect(m_rangeAuto, &QPushButton::clicked, this, &QualityPanel::onAutoRange);
    connect(m_filterEnabled, &QCheckBox::toggled, this, &QualityPanel::onFilterChanged);
    connect(m_filterThreshold, &QDoubleSpinBox::valueChanged, this, &QualityPanel::onFilterChanged);
    connect(m_clipEnabled, &QCheckBox::toggled, this, &QualityPanel::applyClip);
    connect(m_clipAxis, &QComboBox::currentIndexChanged, this, &QualityPanel::applyClip);
    connect(m_clipPosition, &QSlider::valueChanged, this, &QualityPanel::applyClip);
    connect(m_pickEnabled, &QPushButton::toggled, this, &QualityPanel::onPickToggled);
    connect(m_logScale, &QCheckBox::toggled, m_histogram, &QualityHistogram::setLogScale);
    connect(&m_picker, &TetPicker::tetPicked, this, &QualityPanel::onPicked);
    connect(&m_picker, &TetPicker::toolDeactivated, this, [this] {
        const QSignalBlocker block(m_pickEnabled);
        m_pickEnabled->setChecked(false);
    });
}

QualityPanel::~QualityPanel() {
    attach(nullptr);
}

TetMeshActor* QualityPanel::actor() const {
    return m_viewport != nullptr ? &m_viewport->tetMeshActor() : nullptr;
}

void QualityPanel::attach(VtkViewport* viewport) {
    if (viewport == m_viewport)
        return;
    if (m_viewport != nullptr) {
        disconnect(m_cameraConnection);
        m_viewport->removeProp(m_legend.actor());
        if (m_viewport->tool() == &m_picker)
            m_viewport->setTool(nullptr);
    }
    m_viewport = viewport;
    if (m_viewport == nullptr)
        return;
    m_viewport->addProp(m_legend.actor());
    m_cameraConnection = connect(m_viewport, &VtkViewport::cameraChanged, this, [this] {
        if (m_clipEnabled->isChecked() && clipAxis() == ClipAxis::View)
            applyClip();
    });
    // Apply every setting to the actor.
    TetMeshActor* a = actor();
    a->setDisplayMode(displayMode());
    a->setOverlayMeasure(overlayMeasure());
    a->setColorRange(m_rangeMin->value(), m_rangeMax->value());
    a->setQualityFilter(m_filterEnabled->isChecked(), m_filterThreshold->value());
    if (m_pickEnabled->isChecked())
        m_viewport->setTool(&m_picker);
    applyClip();
    updateLegend();
    m_viewport->requestRender();
}

void QualityPanel::meshChanged() {
    applyClip();
    updateLegend();
}

TetDisplayMode QualityPanel::displayMode() const {
    return static_cast<TetDisplayMode>(std::max(0, m_displayMode->currentIndex()));
}

QualityMeasure QualityPanel::overlayMeasure() const {
    return static_cast<QualityMeasure>(std::max(0, m_measure->currentIndex()));
}

QualityPanel::ClipAxis QualityPanel::clipAxis() const {
    return static_cast<ClipAxis>(std::max(0, m_clipAxis->currentIndex()));
}

double QualityPanel::clipPosition() const {
    return double(m_clipPosition->value()) / double(kClipSliderSteps);
}

void QualityPanel::onDisplayModeChanged() {
    if (TetMeshActor* a = actor())
        a->setDisplayMode(displayMode());
    changed();
}

void QualityPanel::onMeasureChanged() {
    const QualityMeasure measure = overlayMeasure();
    if (TetMeshActor* a = actor())
        a->setOverlayMeasure(measure);
    syncRangeControls();
    const QualityMeasure filterMeasure =
        measure == QualityMeasure::None ? QualityMeasure::RadiusRatio : measure;
    if (filterMeasure != m_thresholdMeasure) {
        configureThreshold(filterMeasure);
        if (TetMeshActor* a = actor())
            a->setQualityFilter(m_filterEnabled->isChecked(), m_filterThreshold->value());
    }
    m_histogram->setMeasure(filterMeasure);
    updateLegend();
    changed();
}

void QualityPanel::syncRangeControls() {
    const TetMeshActor* a = actor();
    const auto range = a != nullptr ? a->colorRange() : defaultQualityRange(overlayMeasure());
    const bool dihedral = overlayMeasure() == QualityMeasure::MinDihedral;
    const QSignalBlocker blockMin(m_rangeMin);
    const QSignalBlocker blockMax(m_rangeMax);
    for (QDoubleSpinBox* box : {m_rangeMin, m_rangeMax}) {
        box->setDecimals(dihedral ? 1 : 3);
        box->setSingleStep(dihedral ? 1.0 : 0.05);
    }
    m_rangeMin->setValue(range.first);
    m_rangeMax->setValue(range.second);
    const bool coloured = overlayMeasure() != QualityMeasure::None;
    m_rangeMin->setEnabled(coloured);
    m_rangeMax->setEnabled(coloured);
    m_rangeAuto->setEnabled(coloured);
}

void QualityPanel::configureThreshold(QualityMeasure filterMeasure) {
    m_thresholdMeasure = filterMeasure;
    const QSignalBlocker block(m_filterThreshold);
    if (filterMeasure == QualityMeasure::MinDihedral) {
        m_filterThreshold->setRange(0.0, 180.0);
        m_filterThreshold->setDecimals(1);
        m_filterThreshold->setSingleStep(1.0);
        m_filterThreshold->setSuffix(QStringLiteral(" °"));
    } else {
        m_filterThreshold->setRange(-1.0, 1.0);
        m_filterThreshold->setDecimals(3);
        m_filterThreshold->setSingleStep(0.05);
        m_filterThreshold->setSuffix(QString());
    }
    m_filterThreshold->setValue(defaultThreshold(filterMeasure));
}

void QualityPanel::onRangeChanged() {
    if (TetMeshActor* a = actor()) {
        a->setColorRange(m_rangeMin->value(), m_rangeMax->value());
        updateLegend();
    }
    changed();
}

void QualityPanel::onAutoRange() {
    TetMeshActor* a = actor();
    if (a == nullptr)
        return;
    const auto range = a->autoRange();
    a->setColorRange(range.first, range.second);
    syncRangeControls();
    updateLegend();
    changed();
}

void QualityPanel::onFilterChanged() {
    if (TetMeshActor* a = actor())
        a->setQualityFilter(m_filterEnabled->isChecked(), m_filterThreshold->value());
    changed();
}

void QualityPanel::applyClip() {
    TetMeshActor* a = actor();
    if (a == nullptr)
        return;
    const Bounds b = a->bounds();
    if (!m_clipEnabled->isChecked() || !validBounds(b)) {
        if (a->clipEnabled())
            a->setClipPlane(false, Vec3::Zero(), Vec3::UnitX());
        changed();
        return;
    }
    const double t = clipPosition();
    const ClipAxis axis = clipAxis();
    Vec3 normal = Vec3::UnitX();
    if (axis == ClipAxis::View)
        normal = -viewDirection(m_viewport->camera()); // towards the camera
    else
        normal = Vec3::Unit(static_cast<int>(axis));
    // Extent of the bounding box along the normal; the plane moves from its far end (t = 0:
    // everything clipped) to its near end (t = 1: nothing clipped).
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p(b[(corner & 1) ? 1 : 0], b[(corner & 2) ? 3 : 2], b[(corner & 4) ? 5 : 4]);
        lo = std::min(lo, p.dot(normal));
        hi = std::max(hi, p.dot(normal));
    }
    const Vec3 origin = (lo + t * (hi - lo)) * normal;
    a->setClipPlane(true, origin, normal);
    changed();
}

void QualityPanel::onPickToggled(bool on) {
    if (m_viewport == nullptr)
        return;
    if (on)
        m_viewport->setTool(&m_picker);
    else if (m_viewport->tool() == &m_picker)
        m_viewport->setTool(nullptr);
}

void QualityPanel::onPicked(int tet) {
    if (m_meshProvider) {
        const TetMesh* mesh = m_meshProvider();
        const TetMeshActor* a = actor();
        if (mesh != nullptr) {
            inspectTet(*mesh, tet, a != nullptr ? a->tetScheme(tet) : Scheme::None);
            if (tet >= 0)
                m_tabs->setCurrentWidget(m_inspector);
        }
    }
    emit tetPicked(tet);
}

void QualityPanel::setBeforeMesh(const TetMesh& mesh, double stableDt, double overlap) {
    m_histogram->setQualities(QualityHistogram::Series::Before, resect::tetQualities(mesh));
    m_table->setSummary(QualitySummaryTable::Before, summarizeQuality(mesh), stableDt, overlap);
}

void QualityPanel::setAfterMesh(const TetMesh& mesh, double stableDt, double overlap) {
    m_histogram->setQualities(QualityHistogram::Series::After, resect::tetQualities(mesh));
    m_table->setSummary(QualitySummaryTable::After, summarizeQuality(mesh), stableDt, overlap);
}

void QualityPanel::clearBefore() {
    m_histogram->clearSeries(QualityHistogram::Series::Before);
    m_table->clearSummary(QualitySummaryTable::Before);
}

void QualityPanel::clearAfter() {
    m_histogram->clearSeries(QualityHistogram::Series::After);
    m_table->clearSummary(QualitySummaryTable::After);
}

void QualityPanel::setCutCurve(double input, std::vector<double> afterCuts, double pending) {
    m_curve->setValues(input, std::move(afterCuts), pending);
}

void QualityPanel::clearCutCurve() {
    m_curve->clear();
}

void QualityPanel::inspectTet(const TetMesh& mesh, int tet, Scheme scheme) {
    m_inspector->setTet(mesh, tet, scheme);
}

void QualityPanel::selectTet(int tet) {
    onPicked(tet);
}

void QualityPanel::setMeshProvider(std::function<const TetMesh*()> provider) {
    m_meshProvider = std::move(provider);
}

void QualityPanel::updateLegend() {
    if (const TetMeshActor* a = actor())
        m_legend.update(*a);
}

void QualityPanel::changed() {
    if (m_viewport != nullptr)
        m_viewport->requestRender();
    emit settingsChanged();
}

} // namespace resect
