// Seeing the cut in the studio (issue 19, item 1), through the real main window under the
// offscreen platform, driven as a user would: apply a cut through the polyp's stalk, colour by
// piece from the Display toolbar, dim or hide the resected chips, explode the pieces with the
// slider, see the last cut's tets and a tet picked in the Quality dock outlined.

#include "main_window.h"

#include "widgets/camera_ray.h"
#include "widgets/cut_panel.h"
#include "widgets/cut_preview.h"
#include "widgets/display_toolbar.h"
#include "widgets/quality_panel.h"
#include "widgets/scenario_document.h"
#include "widgets/shown_tissue.h"
#include "widgets/tet_inspector.h"
#include "widgets/tet_picker.h"
#include "widgets/tissue_display.h"
#include "widgets/tissue_session.h"
#include "widgets/vtk_viewport.h"

#include "tests/widgets/drawn_pieces.h"
#include "tests/widgets/sweep_fixtures.h"

#include <QAction>
#include <QComboBox>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTest>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPolyData.h>

#include <set>

using namespace resect;

namespace {

constexpr int kWaitMs = 180'000;

/// A window with errors signalled instead of shown.
struct Studio {
    MainWindow window;
    Studio() {
        window.setErrorDialogsEnabled(false);
        window.setUnsavedChangesAnswer(QMessageBox::Discard);
        window.resize(1200, 800);
        window.show();
    }
    bool idle() { return window.cutPreview().waitForIdle(kWaitMs); }
    bool loadSample(Sample sample = Sample::Polyp) {
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        window.openSample(sample);
        return loaded.wait(kWaitMs) && idle();
    }
    bool open(const QString& path) {
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        window.openFile(path);
        if (loaded.count() == 0)
            (void)loaded.wait(kWaitMs);
        return loaded.count() == 1 && idle();
    }
    /// Previews a horizontal cut at the height of the polyp's stalk and applies it with the
    /// cut panel's button.
    bool cutThroughTheStalk() {
        // The stalk is at about 9.5 of the polyp's 20 mm.
        window.cutPreview().setPendingSweep(
            test::planeSweep(window.session().base()->mesh(), 0.47, 0.1));
        if (!idle() || !window.cutPreview().error().isEmpty())
            return false;
        auto* apply = window.cutPanel()->findChild<QPushButton*>(QStringLiteral("applyCut"));
        if (apply == nullptr || !apply->isEnabled())
            return false;
        QTest::mouseClick(apply, Qt::LeftButton);
        return idle() && window.session().current()->cuts() == 1;
    }
    QAction* action(const char* name) {
        return window.findChild<QAction*>(QString::fromLatin1(name));
    }
    DisplayToolBar* toolBar() {
        return window.findChild<DisplayToolBar*>(QStringLiteral("displayToolBar"));
    }
    TissueDisplay& display() { return window.shownTissue().display(); }
    VtkViewport& view() { return *window.viewport(); }
};

} // namespace

class TestStudioDisplay : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void theControlsAreInTheToolBarAndTheViewMenu() {
        Studio s;
        DisplayToolBar* bar = s.toolBar();
        QVERIFY(bar);
        QVERIFY(bar->isVisible());
        QMenu* view = nullptr;
        for (QAction* a : s.window.menuBar()->actions())
            if (a->menu() && a->menu()->title() == MainWindow::tr("&View"))
                view = a->menu();
        QVERIFY(view);
        bool hasDisplay = false;
        for (QAction* a : view->actions())
            hasDisplay = hasDisplay || a->menu() == bar->menu();
        QVERIFY(hasDisplay);
        for (const char* name :
             {"colorByQuality", "colorByPiece", "showCutFaces", "highlightLastCut", "resectedShown",
              "resectedDimmed", "resectedHidden", "explodePieces"}) {
            QAction* a = s.action(name);
            QVERIFY2(a, name);
            QVERIFY2(bar->menu()->actions().contains(a), name);
        }
        // Defaults: quality colours, cut faces and the last cut on, chips dimmed, no explode.
        QVERIFY(s.action("colorByQuality")->isChecked());
        QVERIFY(s.action("showCutFaces")->isChecked());
        QVERIFY(s.action("highlightLastCut")->isChecked());
        QVERIFY(s.action("resectedDimmed")->isChecked());
        QCOMPARE(bar->explodeSlider()->value(), 0);
    }

    void colourByPieceShowsTheHeadApartFromTheStalk() {
        Studio s;
        QVERIFY(s.loadSample());
        QVERIFY(s.cutThroughTheStalk());
        QCOMPARE(s.window.session().current()->pieces, 2);
        s.action("resectedShown")->trigger(); // a resected head undimmed
        s.action("colorByPiece")->trigger();
        QCOMPARE(s.view().tetMeshActor().colorMode(), TetColorMode::Piece);
        QVERIFY(!s.window.qualityPanel()->legend().visible()); // no quality scale for piece colours
        const auto colours = test::drawnColoursByPiece(s.view());
        QCOMPARE(int(colours.size()), 2);
        std::set<std::array<int, 3>> distinct;
        for (const auto& [piece, set] : colours)
            distinct.insert(set.begin(), set.end());
        QCOMPARE(int(distinct.size()), 2);
        // The cut faces are drawn on both pieces.
        int cutFaces = 0;
        for (TetMeshActor* a : {&s.view().tetMeshActor(), &s.view().chipsActor()})
            cutFaces += int(a->cutFaces()->GetNumberOfCells());
        QVERIFY(cutFaces > 0);

        s.action("colorByQuality")->trigger();
        QCOMPARE(s.view().tetMeshActor().colorMode(), TetColorMode::Quality);
        QVERIFY(s.window.qualityPanel()->legend().visible());
        QVERIFY(!s.action("colorByPiece")->isChecked());
    }

    void resectedChipsAreDimmedOrHidden() {
        // The bundled resection: three pulls take the polyp's head off in three chips.
        Studio s;
        QVERIFY(
            s.open(QStringLiteral(RESECT_SOURCE_DIR "/resources/scenarios/polyp-resection.json")));
        QCOMPARE(int(s.window.session().current()->tissue.chips().size()), 3);
        TetMeshActor& chips = s.view().chipsActor();
        QVERIFY(!chips.empty());
        QVERIFY(chips.actor()->GetVisibility());
        QVERIFY(chips.fade() > 0);

        // The combo box, with the keyboard: Dimmed -> Shown.
        QComboBox* box = s.toolBar()->resectedBox();
        QCOMPARE(box->currentIndex(), int(TissueDisplay::Resected::Dimmed));
        box->setFocus();
        QTest::keyClick(box, Qt::Key_Up);
        QCOMPARE(s.display().resected(), TissueDisplay::Resected::Shown);
        QVERIFY(s.action("resectedShown")->isChecked());
        QCOMPARE(chips.fade(), 0.0);
        QVERIFY(chips.actor()->GetVisibility());

        // The menu: hidden.
        s.action("resectedHidden")->trigger();
        QVERIFY(!chips.actor()->GetVisibility());
        QCOMPARE(box->currentIndex(), int(TissueDisplay::Resected::Hidden));
        QVERIFY(s.view().tetMeshActor().actor()->GetVisibility());
        // Four pieces, each in its colour when shown.
        s.action("resectedShown")->trigger();
        s.action("colorByPiece")->trigger();
        QCOMPARE(int(test::drawnColoursByPiece(s.view()).size()), 4);
        QVERIFY(!s.window.document().isModified()); // display only
    }

    void theExplodeSliderMovesThePiecesApart() {
        Studio s;
        QVERIFY(
            s.open(QStringLiteral(RESECT_SOURCE_DIR "/resources/scenarios/polyp-resection.json")));
        const TetMesh& mesh = s.window.session().current()->mesh();
        const std::vector<Vec3> positions(mesh.positions().begin(), mesh.positions().end());
        const int pieces = s.display().pieceCount();
        QCOMPARE(pieces, 4);
        const auto spread = [&] {
            // The mean distance of the pieces' drawn centroids from the stump's.
            double d = 0;
            for (int p = 1; p < pieces; ++p)
                d += (test::drawnCentroid(s.view(), p) - test::drawnCentroid(s.view(), 0)).norm();
            return d / (pieces - 1);
        };
        const double before = spread();
        QSlider* slider = s.toolBar()->explodeSlider();
        slider->setFocus();
        QTest::keyClick(slider, Qt::Key_PageUp);
        QTest::keyClick(slider, Qt::Key_PageUp);
        QTest::keyClick(slider, Qt::Key_PageUp);
        QVERIFY(slider->value() > 0);
        QVERIFY(s.display().explode() > 0);
        QVERIFY(s.action("explodePieces")->isChecked());
        const double after = spread();
        QVERIFY2(after > 1.2 * before, qPrintable(QString("%1 -> %2").arg(before).arg(after)));
        // The tissue and the document did not change.
        QVERIFY(std::equal(positions.begin(), positions.end(),
                           s.window.session().current()->mesh().positions().begin()));
        QVERIFY(!s.window.document().isModified());
        // The menu's toggle puts them back.
        s.action("explodePieces")->trigger();
        QCOMPARE(slider->value(), 0);
        QVERIFY(std::abs(spread() - before) < 1e-9 * before);
    }

    void theLastCutAndAPickedTetAreOutlined() {
        Studio s;
        QVERIFY(s.loadSample());
        TetMeshActor& actor = s.view().tetMeshActor();
        QCOMPARE(actor.touchedEdges()->GetNumberOfLines(), vtkIdType(0)); // nothing cut yet
        QVERIFY(s.cutThroughTheStalk());
        QVERIFY(actor.touchedEdges()->GetNumberOfLines() > 0);
        QVERIFY(actor.touchedActor()->GetVisibility());
        s.action("highlightLastCut")->trigger();
        QVERIFY(!actor.touchedActor()->GetVisibility());
        s.action("highlightLastCut")->trigger();
        QVERIFY(actor.touchedActor()->GetVisibility());

        // Pick a tet with the Quality dock's picker: click on the middle of the view.
        auto* pick =
            s.window.qualityPanel()->findChild<QPushButton*>(QStringLiteral("pickEnabled"));
        QVERIFY(pick);
        pick->click();
        QVERIFY(pick->isChecked());
        QPoint pixel;
        int expected = -1;
        for (int dy = 0; dy < 200 && expected < 0; dy += 10) {
            pixel = QPoint(s.view().width() / 2, s.view().height() / 2 + dy);
            expected = TetPicker::pickTet(s.view(), pixel);
        }
        QVERIFY(expected >= 0);
        QTest::mouseClick(&s.view(), Qt::LeftButton, {}, pixel);
        QCOMPARE(s.window.qualityPanel()->inspector()->tet(), expected);
        QCOMPARE(s.display().pickedTet(), expected);
        QCOMPARE(actor.pickedOutline()->GetNumberOfLines(), vtkIdType(6));
        QVERIFY(actor.pickedActor()->GetVisibility());
        const Tet& q = s.window.shownTissue().mesh()->tet(expected);
        double p[3];
        actor.pickedOutline()->GetPoint(0, p);
        QCOMPARE(Vec3(p[0], p[1], p[2]), s.window.shownTissue().mesh()->pos(q[0]));

        // Another document: no pick left over.
        QVERIFY(s.loadSample(Sample::Myoma));
        QCOMPARE(s.display().pickedTet(), -1);
        QVERIFY(!actor.pickedActor()->GetVisibility());
    }
};

QTEST_MAIN(TestStudioDisplay)
#include "test_studio_display.moc"
