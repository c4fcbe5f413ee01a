#pragma once
// CutPanel: the cut method and its parameters (the document's cut settings: method, face
// triangulation, the cut-node threshold d, snapping, relaxation weights, steps, damping and
// rings; the mesh improvement after the cut, on or off, and its three factors, whose spin
// boxes take CutLimits' ranges) and the live preview of the pending cut: its counts (the
// improvement's collapsed edges, smoothed nodes and removed tets among them), the pieces and
// the resected chips (count, volume, mass), the quality and stable time step before and after,
// and the time of each stage; Apply adds the cut to the document, Discard drops it.
//
// Edits go through the ScenarioDocument (undoable; consecutive changes of one number merge
// into one undo step); the panel follows the document on undo and redo. The pending cut and
// its preview are CutPreview's, which recomputes the preview whenever the current tissue
// (TissueSession) changes, settings included; Apply and Discard ask it. Apply is enabled only
// while the preview on show succeeded and is up to date (CutPreview::canApply); otherwise the
// preview's status line (previewStatus) says why, in place.
//
// A preview that would wreck the simulation warns in the preview area ("previewWarning", its
// text "previewWarningText"; CutPreview::warnings): when it divides the stable time step by
// more than CutPreview::kStepDropWarning, or when snapping refused every cut node. The tets
// that limit the step are one click away: "inspectWorstTet" asks for the worst
// (inspectTetRequested: the main window shows it in the quality dock's tet inspector), and
// each further click for the next of TissueState::stepLimitingTets.
//
// The notice line (cutNotice) shows, in place of a dialog, why the document refused the last
// edit (TissueSession::editRefused: a stroke, sweep or setting whose cuts fail was undone) or
// why its tissue fails; it clears at the next edit or a new document.

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSpinBox;

namespace resect {

class CutPreview;
class ScenarioDocument;
class TissueSession;

class CutPanel : public QWidget {
    Q_OBJECT

public:
    CutPanel(ScenarioDocument& document, TissueSession& session, CutPreview& preview, QWidget* parent = nullptr);

    /// The preview's figures as shown, by key ("tets", "added_tets", "cut_edges",
    /// "cut_nodes", "snapped_nodes", "decomposed_tets", "separated_tets", "collapsed_edges",
    /// "smoothed_nodes", "removed_tets", "pieces", "chips", "resected_volume",
    /// "resected_mass", "min_radius_ratio", "stable_dt", "stage_ms", "relax_ms", "surface_ms",
    /// "improve_ms", "total_ms"); empty when there is no preview.
    QString previewValue(const QString& key) const;
    /// The notice line's text (empty when there is nothing to report).
    QString notice() const;
    /// The preview's warning (empty when it does not warn).
    QString warning() const;

signals:
    /// Apply failed (no pending cut, or an invalid one); `message` says why.
    void applyFailed(const QString& message);
    /// The author asked to see tet `tet` of the preview (a tet that limits its time step).
    void inspectTetRequested(int tet);

private:
    void syncFromDocument();
    void updatePreview();
    void apply();
    void setNotice(const QString& text);
    /// Shows or hides the warning of the preview on show.
    void updateWarning();
    void inspectNextWorstTet();
    QLabel* addValue(QFormLayout* form, const QString& key, const QString& label);

    ScenarioDocument& m_document;
    TissueSession& m_session;
    CutPreview& m_preview;
    bool m_syncing = false;

    QComboBox* m_method = nullptr;
    QComboBox* m_triangulation = nullptr;
    QDoubleSpinBox* m_d = nullptr;
    QCheckBox* m_snap = nullptr;
    QSpinBox* m_relaxSteps = nullptr;
    QDoubleSpinBox* m_wSpring = nullptr;
    QDoubleSpinBox* m_wParticle = nullptr;
    QDoubleSpinBox* m_relaxDamping = nullptr;
    QSpinBox* m_rings = nullptr;
    QCheckBox* m_improve = nullptr;
    QDoubleSpinBox* m_improveQuality = nullptr;
    QDoubleSpinBox* m_improveShortEdge = nullptr;
    QDoubleSpinBox* m_improveCoarsen = nullptr;

    QLabel* m_notice = nullptr;
    QLabel* m_previewStatus = nullptr;
    QWidget* m_warning = nullptr;
    QLabel* m_warningText = nullptr;
    QPushButton* m_inspectWorst = nullptr;
    const void* m_warnedPreview = nullptr; ///< the preview the warning is about
    int m_nextWorst = 0;                   ///< index into its stepLimitingTets
    QPushButton* m_apply = nullptr;
    QPushButton* m_discard = nullptr;
    std::vector<std::pair<QString, QLabel*>> m_values;
};

} // namespace resect
