#pragma once
// Axis helpers shared by the studio's hand-painted charts (accuracy_chart, quality_curve).

namespace resect {

/// The smallest of 1, 2, 5 times a power of ten that is at least `v` (> 0): a tick step.
double niceStep(double v);

} // namespace resect
