#include "widgets/display_toolbar.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QSignalBlocker>
#include <QSlider>

#include <cmath>

namespace resect {

namespace {

QAction* checkable(QObject* parent, const QString& text, const char* name, const QString& tip) {
    auto* action = new QAction(text, parent);
    action->setObjectName(QString::fromLatin1(name));
    action->setCheckable(true);
    action->setToolTip(tip);
    action->setStatusTip(tip);
    return action;
}

} // namespace

DisplayToolBar::DisplayToolBar(TissueDisplay& display, QWidget* parent)
    : QToolBar(tr("Display"), parent), m_display(display) {
    setObjectName(QStringLiteral("displayToolBar"));
    m_menu = new QMenu(tr("&Display"), this);

    auto* colours = new QActionGroup(this);
    m_byQuality = checkable(colours, tr("Quality"), "colorByQuality",
                            tr("Colour the tets by the quality overlay (Quality dock)"));
    m_byPiece = checkable(
        colours, tr("Pieces"), "colorByPiece",
        tr("Colour every piece the cuts made, resected chips included, in its own colour"));
    connect(m_byQuality, &QAction::triggered, this,
            [this] { m_display.setColorMode(TetColorMode::Quality); });
    connect(m_byPiece, &QAction::triggered, this,
            [this] { m_display.setColorMode(TetColorMode::Piece); });

    m_cutFaces = checkable(
        this, tr("Cut faces"), "showCutFaces",
        tr("Draw the faces the cuts made in their own colour (and texture on the surface)"));
    connect(m_cutFaces, &QAction::toggled, &m_display, &TissueDisplay::setCutFacesVisible);
    m_lastCut = checkable(this, tr("Last cut"), "highlightLastCut",
                          tr("Outline the tets the last cut produced or changed"));
    connect(m_lastCut, &QAction::toggled, &m_display, &TissueDisplay::setLastCutHighlighted);

    m_resected = new QActionGroup(this);
    const QString resectedTip = tr("How the pieces a cut took off the anchored tissue are drawn");
    const QString names[] = {tr("Show resected pieces"), tr("Dim resected pieces"),
                             tr("Hide resected pieces")};
    const char* objectNames[] = {"resectedShown", "resectedDimmed", "resectedHidden"};
    m_resectedBox = new QComboBox(this);
    m_resectedBox->setObjectName(QStringLiteral("resectedPieces"));
    m_resectedBox->setToolTip(resectedTip);
    m_resectedBox->addItems({tr("Shown"), tr("Dimmed"), tr("Hidden")});
    for (int i = 0; i < 3; ++i) {
        QAction* a = checkable(m_resected, names[i], objectNames[i], resectedTip);
        const auto value = static_cast<TissueDisplay::Resected>(i);
        connect(a, &QAction::triggered, this, [this, value] { m_display.setResected(value); });
    }
    connect(m_resectedBox, &QComboBox::activated, this, [this](int index) {
        m_display.setResected(static_cast<TissueDisplay::Resected>(index));
    });

    m_explode = new QSlider(Qt::Horizontal, this);
    m_explode->setObjectName(QStringLiteral("explodeSlider"));
    m_explode->setRange(0, kExplodeSteps);
    m_explode->setFixedWidth(140);
    m_explode->setToolTip(tr("Move the pieces apart from the tissue's centre (display only: the "
                             "tissue is not changed)"));
    connect(m_explode, &QSlider::valueChanged, this, [this](int value) {
        m_display.setExplode(TissueDisplay::kMaxExplode * value / kExplodeSteps);
    });
    m_explodeAction = checkable(this, tr("Explode pieces"), "explodePieces", m_explode->toolTip());
    connect(m_explodeAction, &QAction::triggered, this, [this](bool on) {
        m_explode->setValue(on ? static_cast<int>(std::lround(
                                     kDefaultExplode / TissueDisplay::kMaxExplode * kExplodeSteps))
                               : 0);
    });

    auto* colourLabel = new QLabel(tr("Colour:"), this);
    addWidget(colourLabel);
    addAction(m_byQuality);
    addAction(m_byPiece);
    addSeparator();
    addAction(m_cutFaces);
    addAction(m_lastCut);
    addSeparator();
    addWidget(new QLabel(tr("Resected:"), this));
    addWidget(m_resectedBox);
    addSeparator();
    addWidget(new QLabel(tr("Explode:"), this));
    addWidget(m_explode);

    m_menu->addAction(m_byQuality);
    m_menu->addAction(m_byPiece);
    m_menu->addSeparator();
    m_menu->addAction(m_cutFaces);
    m_menu->addAction(m_lastCut);
    m_menu->addSeparator();
    m_menu->addActions(m_resected->actions());
    m_menu->addSeparator();
    m_menu->addAction(m_explodeAction);

    connect(&m_display, &TissueDisplay::settingsChanged, this, &DisplayToolBar::sync);
    sync();
}

void DisplayToolBar::sync() {
    const QSignalBlocker b1(m_cutFaces), b2(m_lastCut), b3(m_resectedBox), b4(m_explode);
    (m_display.colorMode() == TetColorMode::Piece ? m_byPiece : m_byQuality)->setChecked(true);
    m_cutFaces->setChecked(m_display.cutFacesVisible());
    m_lastCut->setChecked(m_display.lastCutHighlighted());
    const int resected = static_cast<int>(m_display.resected());
    m_resected->actions().at(resected)->setChecked(true);
    m_resectedBox->setCurrentIndex(resected);
    m_explode->setValue(static_cast<int>(
        std::lround(m_display.explode() / TissueDisplay::kMaxExplode * kExplodeSteps)));
    m_explodeAction->setChecked(m_display.explode() > 0);
}

} // namespace resect
