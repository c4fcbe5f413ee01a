#include "widgets/effect_parameter_editor.h"

#include "scenario/scenario_document.h"
#include "scenario/scene_defaults.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QLabel>

#include <cmath>

namespace resect {

namespace {

/// mm/s^2 in the file, m/s^2 in the editor.
constexpr double kMmPerM = 1000.0;
/// m/s^2: the range of the editor's components and magnitude (100 g; the file allows up to
/// EffectLimits::kMaxAcceleration, which a spin box that wide would not fit the dock).
constexpr double kMaxEditorAcceleration = 1000.0;

QDoubleSpinBox* numberBox(const QString& name, double min, double max, double step, int decimals,
                          const QString& suffix) {
    auto* box = new QDoubleSpinBox;
    box->setObjectName(name);
    box->setRange(min, max);
    box->setSingleStep(step);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    return box;
}

} // namespace

EffectParameterEditor::EffectParameterEditor(const std::string& effect, QWidget* parent)
    : QWidget(parent), m_effect(effect) {
    setObjectName(QStringLiteral("parameters_") + QString::fromStdString(effect));
    if (effect == "deformation")
        buildDeformation();
    else if (effect == "gravity")
        buildGravity();
    else if (effect == "tool-contact")
        buildToolContact();
    else if (effect == "damping")
        buildDamping();
    setParameters(defaultEffectParameters(effect));
}

void EffectParameterEditor::buildDeformation() {
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    m_distance = new QCheckBox(tr("Springs"));
    m_distance->setObjectName(QStringLiteral("termDistance"));
    m_distance->setToolTip(tr("Springs on the edges (distance term)"));
    m_volume = new QCheckBox(tr("Volume"));
    m_volume->setObjectName(QStringLiteral("termVolume"));
    m_volume->setToolTip(tr("Volume preservation of every tet"));
    m_area = new QCheckBox(tr("Area"));
    m_area->setObjectName(QStringLiteral("termArea"));
    m_area->setToolTip(tr("Area preservation of the boundary triangles"));
    for (QCheckBox* box : {m_distance, m_volume, m_area}) {
        row->addWidget(box);
        connect(box, &QCheckBox::toggled, this, &EffectParameterEditor::onEdited);
    }
    row->addStretch(1);
    m_hasControls = true;
}

void EffectParameterEditor::buildGravity() {
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    const double max = kMaxEditorAcceleration;
    const char* names[3] = {"gravityX", "gravityY", "gravityZ"};
    const QString axes[3] = {tr("x "), tr("y "), tr("z ")};
    for (int k = 0; k < 3; ++k) {
        m_gravity[k] = numberBox(QString::fromLatin1(names[k]), -max, max, 0.5, 2, QString());
        m_gravity[k]->setPrefix(axes[k]);
        row->addWidget(m_gravity[k]);
        connect(m_gravity[k], &QDoubleSpinBox::valueChanged, this, [this] {
            if (m_syncing)
                return;
            showMagnitude();
            onEdited();
        });
    }
    row->addWidget(new QLabel(tr("m/s²")));
    form->addRow(row);
    m_magnitude = numberBox(QStringLiteral("gravityMagnitude"), 0, max, 0.5, 2, tr(" m/s²"));
    m_magnitude->setToolTip(tr("The length of the acceleration; its direction is kept"));
    form->addRow(tr("Magnitude"), m_magnitude);
    connect(m_magnitude, &QDoubleSpinBox::valueChanged, this,
            &EffectParameterEditor::onMagnitudeEdited);
    m_hasControls = true;
}

void EffectParameterEditor::buildToolContact() {
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    m_radius = numberBox(QStringLiteral("toolRadius"), 0.01, EffectLimits::kMaxToolRadius, 0.05, 2,
                         tr(" mm"));
    m_radius->setToolTip(
        tr("Radius of the loop's wire: surface nodes closer to the tool's curve are pushed out"));
    form->addRow(tr("Wire radius"), m_radius);
    connect(m_radius, &QDoubleSpinBox::valueChanged, this, &EffectParameterEditor::onEdited);
    m_hasControls = true;
}

void EffectParameterEditor::buildDamping() {
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    m_coefficient = numberBox(QStringLiteral("dampingCoefficient"), 0.01,
                              EffectLimits::kMaxDampingCoefficient, 1.0, 2, tr(" 1/s"));
    m_coefficient->setToolTip(tr("Mass-proportional damping f = -c m v: kinetic energy decays with "
                                 "the time constant 1/(2c)"));
    form->addRow(tr("Coefficient"), m_coefficient);
    connect(m_coefficient, &QDoubleSpinBox::valueChanged, this, &EffectParameterEditor::onEdited);
    m_hasControls = true;
}

void EffectParameterEditor::setParameters(const QJsonObject& parameters) {
    m_parameters = parameters;
    EffectSpec spec;
    spec.parameters = parameters;
    const EffectSpec defaults{m_effect, defaultEffectParameters(m_effect), {}};
    m_syncing = true;
    if (m_distance) {
        m_distance->setChecked(spec.flag("distance", true));
        m_volume->setChecked(spec.flag("volume", true));
        m_area->setChecked(spec.flag("area", true));
    }
    if (m_gravity[0]) {
        const Vec3 g = spec.vector("acceleration", defaults.vector("acceleration", Vec3::Zero()));
        for (int k = 0; k < 3; ++k)
            m_gravity[k]->setValue(g[k] / kMmPerM);
        showMagnitude();
    }
    if (m_radius)
        m_radius->setValue(spec.number("radius", defaults.number("radius", 0)));
    if (m_coefficient)
        m_coefficient->setValue(spec.number("coefficient", defaults.number("coefficient", 0)));
    m_syncing = false;
}

QJsonObject EffectParameterEditor::parameters() const {
    QJsonObject p = m_parameters;
    if (m_distance) {
        p["distance"] = m_distance->isChecked();
        p["volume"] = m_volume->isChecked();
        p["area"] = m_area->isChecked();
    }
    if (m_gravity[0])
        p["acceleration"] =
            QJsonArray{m_gravity[0]->value() * kMmPerM, m_gravity[1]->value() * kMmPerM,
                       m_gravity[2]->value() * kMmPerM};
    if (m_radius)
        p["radius"] = m_radius->value();
    if (m_coefficient)
        p["coefficient"] = m_coefficient->value();
    return p;
}

void EffectParameterEditor::onEdited() {
    if (m_syncing)
        return;
    m_parameters = parameters();
    emit edited(m_parameters);
}

void EffectParameterEditor::onMagnitudeEdited(double magnitude) {
    if (m_syncing)
        return;
    Vec3 g(m_gravity[0]->value(), m_gravity[1]->value(), m_gravity[2]->value());
    const double length = g.norm();
    g = length > 0 ? Vec3(g * (magnitude / length)) : Vec3(0, 0, -magnitude);
    m_syncing = true;
    for (int k = 0; k < 3; ++k)
        m_gravity[k]->setValue(g[k]);
    m_syncing = false;
    onEdited();
}

void EffectParameterEditor::showMagnitude() {
    const Vec3 g(m_gravity[0]->value(), m_gravity[1]->value(), m_gravity[2]->value());
    const bool wasSyncing = m_syncing;
    m_syncing = true;
    m_magnitude->setValue(g.norm());
    m_syncing = wasSyncing;
}

} // namespace resect
