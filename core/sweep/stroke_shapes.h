#pragma once
// Shapes of tool strokes as authors make them, for tests, benchmarks and studies: the loop
// electrode's scoops of a resection (the paper's Figure 2 and 10: the loop pulled through the
// tissue again and again, each pass taking a chip where the last ones were) and strokes shaped
// like the studio's mouse-recorded ones (the loop, at one fixed orientation, dragged along a
// wiggly path in a view plane). Each returns the tool curves of a sweep (SweepSurface::
// fromCurves), in the body's units.

#include "core/mesh/tet_mesh.h"

#include <Eigen/Geometry>

#include <random>
#include <vector>

namespace resect {

using Curves = std::vector<std::vector<Vec3>>;

/// The loop electrode in its own frame: a half circle of `points` points (>= 3), its chord
/// 2 * halfWidth along x from +x to -x, its bulge `depth` deep along -z.
std::vector<Vec3> halfLoop(double halfWidth, double depth, int points = 9);

/// A scoop: the loop (arms up) pulled through the top of a body along a horizontal direction.
struct ScoopShape {
    Vec3 centre = Vec3::Zero(); ///< (x, y): where the pull passes the body's axis; z: the body's top
    double angle = 0;           ///< pull direction in the xy plane (rad)
    double halfWidth = 4;       ///< the loop's half width (length)
    double depth = 2;           ///< how far below the top the loop's bottom dips, at its deepest
    double reach = 9;           ///< the stroke starts `reach` before the centre and ends `reach` after it
    double rise = 1.5;          ///< at start and end the loop's bottom is this far above the top
    double armHeight = 4;       ///< the arms reach this far above the top
    int poses = 4;              ///< tool poses (>= 2), evenly along the pull
    int points = 9;             ///< points of the loop (>= 3)
};
/// The curves of a scoop: pose i at s = -reach + 2 reach i / (poses - 1) along the pull; the
/// loop's bottom at top + rise at the ends and top - depth in the middle (a parabola in s).
Curves loopScoop(const ScoopShape& shape);

/// Scoop k (k = 0, 1, ...) of a resection of the body in `bounds` (its top at bounds.max().z()):
/// each pull turned by the golden angle from the last, shifted a little along it and a little
/// deeper (depth = firstDepth + k * depthStep, fractions of the body's height), the loop as wide
/// as `widthFraction` of the body's width.
struct ResectionPlan {
    double firstDepth = 0.11;   ///< of the body's height
    double depthStep = 0.0175;  ///< of the body's height, per scoop
    double widthFraction = 0.4; ///< the loop's half width over the body's width
    double shift = 0.0075;      ///< of the body's width, per scoop, along the pull
    int poses = 4;
    int points = 9;
};
ScoopShape resectionScoop(const Eigen::AlignedBox3d& bounds, const Vec3& axis, int k, const ResectionPlan& plan = {});

/// A stroke shaped like a mouse-recorded one: a view direction drawn at random within
/// `maxTilt` (rad) of straight down, the loop oriented once for the whole stroke (its plane
/// perpendicular to the drag, its chord across the drag in the view plane, its bulge away
/// from the viewer, as StrokeRecorder does), and its centre dragged across the body along a
/// path with random lateral wiggle. With `monotonic` (what a fixed recorder produces) every
/// pose advances along the drag, so the sweep cannot intersect itself; without, the wiggle
/// may also turn back along the drag, as a raw mouse path can.
struct MouseStrokeShape {
    double halfWidth = 3.5;    ///< the loop's half width (length)
    double depthFraction = 0.3;///< the press point's depth below the body's top, of its height
    double wiggle = 0.15;      ///< lateral wiggle amplitude, of the body's width
    double maxTilt = 0.6;      ///< rad
    int poses = 24;
    int points = 9;
    bool monotonic = true;
};
Curves mouseStroke(std::mt19937& rng, const Eigen::AlignedBox3d& bounds, const MouseStrokeShape& shape = {});

} // namespace resect
