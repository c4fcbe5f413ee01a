#include "widgets/quality_colors.h"

#include <QCoreApplication>

#include <vtkLookupTable.h>

#include <numbers>

namespace resect {

double qualityMeasureValue(QualityMeasure measure, const TetQuality& quality) {
    switch (measure) {
    case QualityMeasure::MinDihedral:
        return quality.minDihedral * 180.0 / std::numbers::pi;
    case QualityMeasure::None:
    case QualityMeasure::RadiusRatio:
        break;
    }
    return quality.radiusRatio;
}

std::pair<double, double> defaultQualityRange(QualityMeasure measure) {
    if (measure == QualityMeasure::MinDihedral)
        return {0.0, kRegularDihedralDeg};
    return {kQualityScaleMin, kQualityScaleMax};
}

QString qualityMeasureTitle(QualityMeasure measure) {
    switch (measure) {
    case QualityMeasure::None:
        return QCoreApplication::translate("resect::QualityMeasure", "None");
    case QualityMeasure::RadiusRatio:
        return QCoreApplication::translate("resect::QualityMeasure", "Radius ratio");
    case QualityMeasure::MinDihedral:
        return QCoreApplication::translate("resect::QualityMeasure", "Min. dihedral (°)");
    }
    return {};
}

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
