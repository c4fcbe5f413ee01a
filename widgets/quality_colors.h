#pragma once
// Colour scale for element quality (radius ratio 3 r_in / R_circ, DESIGN.md "Tet mesh
// files"): red for degenerate tets (0), through yellow, to green for regular ones (1).

#include <vtkSmartPointer.h>

class vtkLookupTable;

namespace resect {

/// Range of the quality scale; values outside are clamped (inverted tets, whose radius
/// ratio is negative, show as the 0 colour).
inline constexpr double kQualityScaleMin = 0.0;
inline constexpr double kQualityScaleMax = 1.0;

/// A 256-entry lookup table over [kQualityScaleMin, kQualityScaleMax].
vtkSmartPointer<vtkLookupTable> makeQualityLookupTable();

} // namespace resect
