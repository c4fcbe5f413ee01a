#include "widgets/quality_colors.h"

#include <vtkLookupTable.h>

namespace resect {

vtkSmartPointer<vtkLookupTable> makeQualityLookupTable() {
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetNumberOfTableValues(256);
    table->SetTableRange(kQualityScaleMin, kQualityScaleMax);
    // Hue 0 (red) to 1/3 (green) in HSV; slightly muted so that lighting stays readable.
    table->SetHueRange(0.0, 1.0 / 3.0);
    table->SetSaturationRange(0.7, 0.7);
    table->SetValueRange(0.95, 0.95);
    table->SetAlphaRange(1.0, 1.0);
    table->Build();
    return table;
}

} // namespace resect
