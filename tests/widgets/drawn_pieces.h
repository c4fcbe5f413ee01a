#pragma once
// What the viewport's two tet actors (tissue and resected chips) draw, read back from their
// boundary polydata's "piece" and "piece_colour" cell arrays: for the display tests of
// widgets (test_tissue_display) and of the main window (test_studio_display).

#include "widgets/tet_mesh_actor.h"
#include "widgets/vtk_viewport.h"

#include <QtGlobal>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPolyData.h>

#include <array>
#include <cmath>
#include <map>
#include <set>

namespace resect::test {

/// The colours ("piece_colour", as bytes) of the cells of both visible actors, by piece.
inline std::map<int, std::set<std::array<int, 3>>> drawnColoursByPiece(VtkViewport& view) {
    std::map<int, std::set<std::array<int, 3>>> out;
    for (TetMeshActor* actor : {&view.tetMeshActor(), &view.chipsActor()}) {
        vtkPolyData* poly = actor->boundary();
        if (!actor->actor()->GetVisibility() || poly->GetNumberOfCells() == 0)
            continue;
        vtkDataArray* piece = poly->GetCellData()->GetArray(kPieceArray);
        vtkDataArray* colour = poly->GetCellData()->GetArray(kPieceColourArray);
        if (piece == nullptr || colour == nullptr)
            qFatal("no piece arrays");
        for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
            double rgb[3];
            colour->GetTuple(c, rgb);
            out[int(piece->GetTuple1(c))].insert({int(rgb[0]), int(rgb[1]), int(rgb[2])});
        }
    }
    return out;
}

/// Centroid of the points of the drawn cells of `piece` in both actors (display
/// coordinates); NaN if no cell of that piece is drawn.
inline Vec3 drawnCentroid(VtkViewport& view, int piece) {
    Vec3 sum = Vec3::Zero();
    int count = 0;
    for (TetMeshActor* actor : {&view.tetMeshActor(), &view.chipsActor()}) {
        vtkPolyData* poly = actor->boundary();
        if (poly->GetNumberOfCells() == 0)
            continue;
        vtkDataArray* pieces = poly->GetCellData()->GetArray(kPieceArray);
        vtkIdType n = 0;
        const vtkIdType* pts = nullptr;
        for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
            if (int(pieces->GetTuple1(c)) != piece)
                continue;
            poly->GetPolys()->GetCellAtId(c, n, pts);
            for (vtkIdType k = 0; k < n; ++k) {
                double p[3];
                poly->GetPoint(pts[k], p);
                sum += Vec3(p[0], p[1], p[2]);
                ++count;
            }
        }
    }
    return count > 0 ? Vec3(sum / count) : Vec3::Constant(std::nan(""));
}

} // namespace resect::test
