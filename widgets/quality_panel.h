#pragma once
// QualityPanel: the controls of the quality views (issue 8) for the tet mesh shown in a
// VtkViewport: display mode, overlay measure with its colour range (and an "auto" button),
// the "worse than" filter, a clipping plane moved along x, y, z or the view direction, and
// a tet-inspection mode. It embeds, in tabs below the controls, the QualityHistogram, the
// QualitySummaryTable, the QualityCurve (the worst tet over the scenario's cuts) and the
// TetInspector (also reachable through accessors, so the main window may re-parent them
// elsewhere), and owns the viewport's QualityLegend and the TetPicker tool.
//
// The panel never owns a mesh. It applies its settings to the attached viewport's
// TetMeshActor (which keeps them across setMesh) and is given the data to summarise by
// setters: setBeforeMesh/setAfterMesh for the histogram and table, setCutCurve for the curve,
// inspectTet (or a mesh provider, setMeshProvider) for the inspector. After the viewport's
// mesh changes, call meshChanged() so that the legend and the clipping plane follow the new
// bounds.
//
// objectNames of the controls: "displayMode", "overlayMeasure", "rangeMin", "rangeMax",
// "rangeAuto", "filterEnabled", "filterThreshold", "clipEnabled", "clipAxis",
// "clipPosition", "pickEnabled", "histogramLogScale", "qualityTabs"; embedded widgets:
// "qualityHistogram", "qualitySummaryTable", "qualityCurve", "tetInspector".

#include "core/cut/cut_types.h"
#include "core/mesh/tet_mesh.h"
#include "widgets/quality_colors.h"
#include "widgets/quality_legend.h"
#include "widgets/tet_mesh_actor.h"
#include "widgets/tet_picker.h"

#include <QPointer>
#include <QWidget>

#include <functional>
#include <limits>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QPushButton;
class QSlider;
class QTabWidget;

namespace resect {

class QualityCurve;
class QualityHistogram;
class QualitySummaryTable;
class TetInspector;
class VtkViewport;

class QualityPanel : public QWidget {
    Q_OBJECT

public:
    /// Items of the "clipAxis" combo box (its index).
    enum class ClipAxis { X, Y, Z, View };

    explicit QualityPanel(QWidget* parent = nullptr);
    ~QualityPanel() override;

    /// Controls this viewport's tet mesh actor: adds the legend to it and applies the
    /// current settings. Null detaches (the legend and the picker are removed).
    void attach(VtkViewport* viewport);
    VtkViewport* viewport() const { return m_viewport; }

    /// The viewport's mesh was replaced (setTetMesh): re-place the clipping plane in the new
    /// bounds and update the legend.
    void meshChanged();
    /// The legend follows the actor's overlay and colour mode (after a change made elsewhere,
    /// e.g. colouring by piece).
    void updateLegend();

    /// Histogram series and table column "before" / "after" from a mesh (its quality in the
    /// reference configuration), its stable time step (<= 0: not computed, "—") and how deep it
    /// overlaps itself (TissueState::overlap; negative: not computed, "—").
    void setBeforeMesh(const TetMesh& mesh, double stableDt, double overlap = -1);
    void setAfterMesh(const TetMesh& mesh, double stableDt, double overlap = -1);
    void clearBefore();
    void clearAfter();
    /// The curve of the worst tet over the cuts (QualityCurve::setValues): the worst radius
    /// ratio of the tissue as created, after each applied cut, and after a pending cut (NaN:
    /// none).
    void setCutCurve(double input, std::vector<double> afterCuts,
                     double pending = std::numeric_limits<double>::quiet_NaN());
    void clearCutCurve();

    /// Shows one tet in the inspector (-1 clears it).
    void inspectTet(const TetMesh& mesh, int tet, Scheme scheme);
    /// Selects tet `tet` of the mesh on show as a click of the picker on it would: inspected
    /// (with the mesh provider), the inspector's tab raised, tetPicked() emitted.
    void selectTet(int tet);
    /// With a provider, a click of the picker fills the inspector itself, with the mesh the
    /// provider returns (null: nothing) and the scheme from the actor's tetScheme().
    void setMeshProvider(std::function<const TetMesh*()> provider);

    QualityHistogram* histogram() const { return m_histogram; }
    QualitySummaryTable* summaryTable() const { return m_table; }
    QualityCurve* cutCurve() const { return m_curve; }
    TetInspector* inspector() const { return m_inspector; }
    const QualityLegend& legend() const { return m_legend; }
    TetPicker* picker() { return &m_picker; }

    /// The current settings (as applied to the actor).
    TetDisplayMode displayMode() const;
    QualityMeasure overlayMeasure() const;
    ClipAxis clipAxis() const;
    /// Clip plane position along the axis, 0 (everything clipped) to 1 (nothing clipped).
    double clipPosition() const;

signals:
    /// Some display setting changed (the actor has been updated).
    void settingsChanged();
    /// The picker picked a tet by a click (-1: a miss).
    void tetPicked(int tet);

private:
    void onDisplayModeChanged();
    void onMeasureChanged();
    void onRangeChanged();
    void onAutoRange();
    void onFilterChanged();
    void onPickToggled(bool on);
    void onPicked(int tet);
    void applyClip();
    void syncRangeControls();
    void configureThreshold(QualityMeasure filterMeasure);
    void changed();
    TetMeshActor* actor() const;

    QPointer<VtkViewport> m_viewport;
    QualityLegend m_legend;
    TetPicker m_picker;
    std::function<const TetMesh*()> m_meshProvider;
    QMetaObject::Connection m_cameraConnection;

    QComboBox* m_displayMode = nullptr;
    QComboBox* m_measure = nullptr;
    QDoubleSpinBox* m_rangeMin = nullptr;
    QDoubleSpinBox* m_rangeMax = nullptr;
    QPushButton* m_rangeAuto = nullptr;
    QCheckBox* m_filterEnabled = nullptr;
    QDoubleSpinBox* m_filterThreshold = nullptr;
    QCheckBox* m_clipEnabled = nullptr;
    QComboBox* m_clipAxis = nullptr;
    QSlider* m_clipPosition = nullptr;
    QPushButton* m_pickEnabled = nullptr;
    QCheckBox* m_logScale = nullptr;
    QTabWidget* m_tabs = nullptr;
    QualityHistogram* m_histogram = nullptr;
    QualitySummaryTable* m_table = nullptr;
    QualityCurve* m_curve = nullptr;
    TetInspector* m_inspector = nullptr;
    QualityMeasure m_thresholdMeasure = QualityMeasure::RadiusRatio;
};

} // namespace resect
