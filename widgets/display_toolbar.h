#pragma once
// DisplayToolBar: the controls of TissueDisplay (issue 19, "see the cut") above the 3-D view:
// colour by quality or by piece, cut faces, the last cut's tets, resected pieces shown /
// dimmed / hidden, and an explode slider. The same choices as actions in menu() (the View
// menu's "Display" submenu); toolbar, menu and TissueDisplay stay in step both ways.
//
// objectNames: the toolbar "displayToolBar"; actions "colorByQuality", "colorByPiece",
// "showCutFaces", "highlightLastCut", "resectedShown", "resectedDimmed", "resectedHidden",
// "explodePieces"; widgets "resectedPieces" (combo box, items in TissueDisplay::Resected
// order) and "explodeSlider" (0..kExplodeSteps, factor = value / kExplodeSteps *
// TissueDisplay::kMaxExplode).

#include "widgets/tissue_display.h"

#include <QToolBar>

class QAction;
class QActionGroup;
class QComboBox;
class QMenu;
class QSlider;

namespace resect {

class DisplayToolBar : public QToolBar {
    Q_OBJECT

public:
    explicit DisplayToolBar(TissueDisplay& display, QWidget* parent = nullptr);

    /// The same choices as a menu (owned by the toolbar).
    QMenu* menu() const { return m_menu; }
    QSlider* explodeSlider() const { return m_explode; }
    QComboBox* resectedBox() const { return m_resectedBox; }

    /// Steps of the explode slider.
    static constexpr int kExplodeSteps = 100;
    /// The explode factor "Explode pieces" switches to.
    static constexpr double kDefaultExplode = 0.6;

private:
    /// The controls show the display's settings.
    void sync();

    TissueDisplay& m_display;
    QMenu* m_menu = nullptr;
    QAction* m_byQuality = nullptr;
    QAction* m_byPiece = nullptr;
    QAction* m_cutFaces = nullptr;
    QAction* m_lastCut = nullptr;
    QActionGroup* m_resected = nullptr;
    QAction* m_explodeAction = nullptr;
    QComboBox* m_resectedBox = nullptr;
    QSlider* m_explode = nullptr;
};

} // namespace resect
