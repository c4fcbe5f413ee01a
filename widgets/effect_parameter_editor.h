#pragma once
// EffectParameterEditor: the parameters of one effect of the scenario (the table in
// scenario/scenario_document.h) as controls, for the simulation dock:
//   deformation   its terms as check boxes: "termDistance", "termVolume", "termArea"
//   gravity       the acceleration in m/s^2 (the file's mm/s^2 / 1000) as "gravityX",
//                 "gravityY", "gravityZ", and its magnitude "gravityMagnitude" (a new
//                 magnitude scales the vector; a zero vector points down the z axis); the
//                 editor offers up to 1000 m/s^2 (100 g) per component
//   tool-contact  the wire's radius in mm: "toolRadius", (0, EffectLimits::kMaxToolRadius]
//   damping       the coefficient in 1/s: "dampingCoefficient",
//                 (0, EffectLimits::kMaxDampingCoefficient]
//   fixed         nothing here (its regions are the tissue's: FixedRegionEditor)
// setParameters() shows an effect's parameters (absent keys show defaultEffectParameters,
// scenario/scene_defaults.h, which is what the simulation takes for them); an edit emits
// edited() with the whole new parameter object (keys the editor does not know are kept). The
// editor never writes to the document itself: the panel passes edits on
// (ScenarioDocument::setEffectParameters, undoable).

#include <QJsonObject>
#include <QWidget>

#include <string>

class QCheckBox;
class QDoubleSpinBox;

namespace resect {

class EffectParameterEditor : public QWidget {
    Q_OBJECT

public:
    explicit EffectParameterEditor(const std::string& effect, QWidget* parent = nullptr);

    const std::string& effect() const { return m_effect; }
    /// True if the effect has parameters to edit here.
    bool hasControls() const { return m_hasControls; }

    /// Shows `parameters` (no signal).
    void setParameters(const QJsonObject& parameters);
    /// The parameters as shown.
    QJsonObject parameters() const;

signals:
    /// The author changed a value: the effect's new parameters.
    void edited(const QJsonObject& parameters);

private:
    void buildDeformation();
    void buildGravity();
    void buildToolContact();
    void buildDamping();
    /// A value changed: emits edited() unless the controls are being set.
    void onEdited();
    /// The magnitude changed: scales the vector to it.
    void onMagnitudeEdited(double magnitude);
    void showMagnitude();

    std::string m_effect;
    bool m_hasControls = false;
    bool m_syncing = false;
    QJsonObject m_parameters; ///< as last shown or edited (keeps unknown keys)

    QCheckBox* m_distance = nullptr;
    QCheckBox* m_volume = nullptr;
    QCheckBox* m_area = nullptr;
    QDoubleSpinBox* m_gravity[3] = {nullptr, nullptr, nullptr};
    QDoubleSpinBox* m_magnitude = nullptr;
    QDoubleSpinBox* m_radius = nullptr;
    QDoubleSpinBox* m_coefficient = nullptr;
};

} // namespace resect
