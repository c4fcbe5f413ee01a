#include "widgets/quality_legend.h"

#include "widgets/tet_mesh_actor.h"

#include <vtkCoordinate.h>
#include <vtkLookupTable.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

namespace resect {

QualityLegend::QualityLegend() : m_bar(vtkSmartPointer<vtkScalarBarActor>::New()) {
    m_bar->SetOrientationToVertical();
    m_bar->SetNumberOfLabels(5);
    m_bar->SetLabelFormat("%.3g");
    m_bar->SetMaximumWidthInPixels(90);
    m_bar->SetMaximumHeightInPixels(320);
    // Lower right corner, in normalised viewport coordinates.
    m_bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    m_bar->GetPositionCoordinate()->SetValue(0.8, 0.08);
    m_bar->SetWidth(0.12);
    m_bar->SetHeight(0.5);
    // Fixed font sizes: by default the bar scales its text to its width, which leaves the
    // title of the narrow vertical bar unreadably small.
    m_bar->UnconstrainedFontSizeOn();
    m_bar->GetTitleTextProperty()->SetFontSize(13);
    m_bar->GetTitleTextProperty()->SetJustificationToRight();
    m_bar->GetLabelTextProperty()->SetFontSize(12);
    m_bar->SetVisibility(false);
}

void QualityLegend::update(const TetMeshActor& actor) {
    m_bar->SetLookupTable(actor.lookupTable());
    m_bar->SetTitle(qualityMeasureTitle(actor.overlayMeasure()).toUtf8().constData());
    m_bar->SetVisibility(actor.overlayMeasure() != QualityMeasure::None &&
                         actor.colorMode() == TetColorMode::Quality);
    m_bar->Modified();
}

vtkScalarBarActor* QualityLegend::actor() const {
    return m_bar;
}

QString QualityLegend::title() const {
    const char* title = m_bar->GetTitle();
    return title != nullptr ? QString::fromUtf8(title) : QString();
}

bool QualityLegend::visible() const {
    return m_bar->GetVisibility() != 0;
}

} // namespace resect
