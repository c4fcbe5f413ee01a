#pragma once
// QualityLegend: the colour bar of a TetMeshActor's quality overlay (a vtkScalarBarActor in
// the viewport's lower right), sharing the actor's lookup table and titled with the
// measure's name. Hidden when the overlay is None.
//
// Usage: viewport.addProp(legend.actor()); call legend.update(actor) after changing the
// actor's overlay measure or colour range (QualityPanel does this).

#include "widgets/quality_colors.h"

#include <QString>

#include <vtkSmartPointer.h>

class vtkScalarBarActor;

namespace resect {

class TetMeshActor;

class QualityLegend {
public:
    QualityLegend();

    /// Takes the actor's lookup table (and so its colour range) and measure name; shown
    /// unless the overlay is None or the actor colours by piece.
    void update(const TetMeshActor& actor);

    vtkScalarBarActor* actor() const;
    /// The title shown (qualityMeasureTitle of the overlay measure).
    QString title() const;
    bool visible() const;

private:
    vtkSmartPointer<vtkScalarBarActor> m_bar;
};

} // namespace resect
