#pragma once
// Colour scale and measures for element quality overlays: the radius ratio 3 r_in / R_circ
// (DESIGN.md "Tet mesh files", 1 for a regular tet) and the minimum dihedral angle in
// degrees (70.53 for a regular tet). Both are "higher is better": the scale runs from red
// (degenerate) through yellow to green (regular).

#include "core/mesh/quality.h"

#include <QString>

#include <vtkSmartPointer.h>

#include <utility>

class vtkLookupTable;

namespace resect {

/// Range of the radius-ratio scale; values outside are clamped (inverted tets, whose radius
/// ratio is negative, show as the 0 colour).
inline constexpr double kQualityScaleMin = 0.0;
inline constexpr double kQualityScaleMax = 1.0;
/// Dihedral angle of the regular tet, arccos(1/3), in degrees: the top of the min-dihedral
/// scale.
inline constexpr double kRegularDihedralDeg = 70.528779365509308;

/// What a quality overlay shows per tet (reference configuration, core/mesh/quality.h).
enum class QualityMeasure {
    None,        ///< no overlay: uniform tissue colour
    RadiusRatio, ///< 3 r_in / R_circ, in [0, 1] for valid tets
    MinDihedral, ///< smallest of the six dihedral angles, degrees
};

/// The measure's value for one tet (radius ratio for None, so that filters and histograms
/// always have a value).
double qualityMeasureValue(QualityMeasure measure, const TetQuality& quality);
/// Default colour range of the measure: [0, 1] for the radius ratio, [0, 70.53] degrees for
/// the minimum dihedral angle (None: the radius ratio's).
std::pair<double, double> defaultQualityRange(QualityMeasure measure);
/// Translated, user-visible name of the measure ("Radius ratio", "Min. dihedral (°)",
/// "None").
QString qualityMeasureTitle(QualityMeasure measure);

/// A 256-entry lookup table over [kQualityScaleMin, kQualityScaleMax]; its range is set to
/// the overlay's colour range by TetMeshActor.
vtkSmartPointer<vtkLookupTable> makeQualityLookupTable();

} // namespace resect
