// Conversions to VTK data sets: the tet grid carries the contract arrays of DESIGN.md, the
// surface its triangles and uvs, and the boundary of a tet mesh is a closed, outward
// surface (its enclosed volume is the mesh volume) with the quality of the owning tets.

#include "scenario/vtk_convert.h"

#include "grid_contract.h"
#include "scenario_test_util.h"

#include "core/mesh/quality.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace resect;
using namespace resect::test;

namespace {

Vec3 point(vtkPoints* points, vtkIdType i) {
    double p[3];
    points->GetPoint(i, p);
    return {p[0], p[1], p[2]};
}

} // namespace

class TestVtkConvert : public QObject {
    Q_OBJECT

private slots:
    void unstructuredGridHasContractArrays();
    void polyDataKeepsTrianglesAndUvs_data();
    void polyDataKeepsTrianglesAndUvs();
    void boundaryIsClosedAndOutward();
};

void TestVtkConvert::unstructuredGridHasContractArrays() {
    const TetMesh mesh = makeSampleMesh();
    vtkSmartPointer<vtkUnstructuredGrid> grid = toUnstructuredGrid(mesh);
    const QString problem = gridContractProblem(grid, mesh, {0, 0, 1});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

void TestVtkConvert::polyDataKeepsTrianglesAndUvs_data() {
    QTest::addColumn<bool>("withUvs");
    QTest::newRow("with uvs") << true;
    QTest::newRow("without uvs") << false;
}

void TestVtkConvert::polyDataKeepsTrianglesAndUvs() {
    QFETCH(bool, withUvs);
    TriangleSurface s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    s.triangles = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    if (withUvs)
        s.uvs = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0.5}};
    vtkSmartPointer<vtkPolyData> poly = toPolyData(s);
    QCOMPARE(poly->GetNumberOfPoints(), vtkIdType(4));
    QCOMPARE(poly->GetNumberOfPolys(), vtkIdType(4));
    auto ids = vtkSmartPointer<vtkIdList>::New();
    for (int f = 0; f < 4; ++f) {
        poly->GetCellPoints(f, ids);
        QCOMPARE(ids->GetNumberOfIds(), vtkIdType(3));
        for (int k = 0; k < 3; ++k)
            QCOMPARE(ids->GetId(k), vtkIdType(s.triangles[f][k]));
    }
    vtkDataArray* tcoords = poly->GetPointData()->GetTCoords();
    QCOMPARE(tcoords != nullptr, withUvs);
    if (withUvs)
        for (int i = 0; i < 4; ++i) {
            QCOMPARE(tcoords->GetComponent(i, 0), s.uvs[i].x());
            QCOMPARE(tcoords->GetComponent(i, 1), s.uvs[i].y());
        }
}

void TestVtkConvert::boundaryIsClosedAndOutward() {
    // Piece 0 (two tets sharing a face) has 6 boundary faces, piece 1 has 4. Their enclosed
    // volume (divergence theorem, current positions) equals the tets' current volume.
    const TetMesh mesh = makeSampleMesh();
    vtkSmartPointer<vtkPolyData> poly = boundaryToPolyData(mesh);
    QCOMPARE(poly->GetNumberOfPolys(), vtkIdType(10));
    QCOMPARE(poly->GetNumberOfPoints(), vtkIdType(mesh.nodeCount())); // point i is node i
    vtkDataArray* quality = poly->GetCellData()->GetArray("quality");
    QVERIFY(quality);
    const std::vector<TetQuality> q = tetQualities(mesh);

    TriangleSurface surface;
    for (int n = 0; n < mesh.nodeCount(); ++n)
        surface.positions.push_back(point(poly->GetPoints(), n));
    auto ids = vtkSmartPointer<vtkIdList>::New();
    for (vtkIdType f = 0; f < poly->GetNumberOfPolys(); ++f) {
        poly->GetCellPoints(f, ids);
        QCOMPARE(ids->GetNumberOfIds(), vtkIdType(3));
        const Tri tri{int(ids->GetId(0)), int(ids->GetId(1)), int(ids->GetId(2))};
        surface.triangles.push_back(tri);
        // The owning tet contains the face; its quality is the face's.
        bool matched = false;
        for (int t = 0; t < mesh.tetCount(); ++t) {
            const Tet& tet = mesh.tet(t);
            const bool owns = std::all_of(tri.begin(), tri.end(), [&](int v) {
                return std::find(tet.begin(), tet.end(), v) != tet.end();
            });
            if (owns && quality->GetComponent(f, 0) == q[t].radiusRatio)
                matched = true;
        }
        QVERIFY(matched);
    }
    double volume = 0;
    for (int t = 0; t < mesh.tetCount(); ++t)
        volume += mesh.currentVolume(t);
    QVERIFY(volume > 0);
    QVERIFY(std::abs(enclosedVolume(surface) - volume) <= 1e-12 * volume);
}

QTEST_GUILESS_MAIN(TestVtkConvert)
#include "test_vtk_convert.moc"
