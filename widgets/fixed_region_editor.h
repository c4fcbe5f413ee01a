#pragma once
// FixedRegionEditor: the first tissue's fixed regions (issue 19), the boxes whose nodes are
// anchored: held in place by the fixed effect, and what tells the tissue from the chips a cut
// resects. Per box its min and max corner (reference coordinates, mm) as numbers, how many
// nodes of the uncut tissue lie in it, and Remove; "Add base box" adds the base region of the
// tissue (scenario/scene_defaults.h baseRegion: the bottom few percent of its height); the
// line "anchoredNodes" says how many nodes of the current tissue are anchored.
//
// Every change is a document edit (ScenarioDocument::addFixedRegion, setFixedRegion,
// removeFixedRegion: undoable, one undo step per box while its numbers are typed); the
// editor follows the document on undo, redo and a new document, and the session for the
// counts (the anchors of a derived state, TissueSession::current).
//
// "Place in view" (checkable) asks for the boxes to be drawn and dragged in the 3-D view
// (editInViewToggled: the main window activates FixedRegionTool, which reports back through
// setEditingInView).
//
// objectNames: "addFixedRegion", "editRegionsInView", "anchoredNodes"; per box i: "region<i>", its
// spin boxes "region<i>MinX" .. "region<i>MaxZ", "region<i>Nodes", "region<i>Remove".

#include "scenario/scenario_document.h"

#include <QWidget>

#include <array>
#include <optional>
#include <vector>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QVBoxLayout;

namespace resect {

class ScenarioDocument;
class TissueSession;

class FixedRegionEditor : public QWidget {
    Q_OBJECT

public:
    FixedRegionEditor(ScenarioDocument& document, TissueSession& session,
                      QWidget* parent = nullptr);

    /// Boxes shown.
    int regionCount() const { return static_cast<int>(m_rows.size()); }
    /// The spin box of a corner's coordinate: `max` false for the min corner, axis 0..2.
    QDoubleSpinBox* coordinateBox(int region, bool max, int axis) const;
    /// Anchored nodes of the current tissue (-1 before it is derived).
    int anchoredNodes() const { return m_anchored; }

    /// The base region of the session's uncut tissue (nullopt before it is loaded).
    std::optional<FixedRegion> baseRegionOfTissue() const;

    /// Checks or unchecks "Place in view" (no signal): the view's box tool is (not) active.
    void setEditingInView(bool editing);

signals:
    /// An edit could not be made (no tissue yet): `message` says why.
    void notice(const QString& message);
    /// The author asked to place the boxes in the view (or stopped).
    void editInViewToggled(bool editing);

private:
    struct Row {
        QWidget* widget = nullptr;
        std::array<QDoubleSpinBox*, 6> coordinates{}; ///< min x, y, z, max x, y, z
        QLabel* nodes = nullptr;
    };

    /// Rebuilds the rows if the number of boxes changed, else shows the new numbers in place
    /// (the box being typed in keeps its focus).
    void syncFromDocument();
    void addRow(int index);
    void onCoordinateEdited(int region);
    void addBaseRegion();
    void updateCounts();

    ScenarioDocument& m_document;
    TissueSession& m_session;
    QVBoxLayout* m_rowsLayout = nullptr;
    std::vector<Row> m_rows;
    QPushButton* m_add = nullptr;
    QPushButton* m_inView = nullptr;
    QLabel* m_anchoredLabel = nullptr;
    int m_anchored = -1;
    bool m_syncing = false;
};

} // namespace resect
