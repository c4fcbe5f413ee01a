#pragma once
// The scenario's cuts as sweep surfaces, for replay: every recorded stroke swept by the tool,
// then the explicit sweep surfaces.
//
// A stroke with poses P_0 .. P_{m-1} gives the multi-pose sweep of section 4.2 with one tool
// curve per pose (in time order): point j of curve i is
//     position_i + R(q_i) * (size * curve_j),
// R(q) the rotation of the normalised quaternion q = (w, x, y, z), `size` the tool's scale
// (mm per tool-frame unit). A pose equal to the one before it (the tool held still) adds no
// curve; a stroke must keep at least two distinct poses.

#include "core/status.h"
#include "core/sweep/sweep_surface.h"
#include "scenario/scenario_document.h"

#include <string>
#include <vector>

namespace resect {

/// The tool's polyline in world coordinates (mm) at `pose`. The quaternion must have a
/// non-zero length (validation guarantees it; a zero one is taken as the identity).
std::vector<Vec3> toolCurveAt(const ToolSpec& tool, const ToolPose& pose);

/// The tool pose at time t within the stroke: positions interpolated linearly, orientations
/// by spherical linear interpolation, clamped to the first and last pose.
ToolPose poseAt(const Stroke& stroke, double t);

/// The sweep of one stroke. Errors name the stroke ("strokes[1] 'second pass': ...").
Status strokeSweep(const Scenario& scenario, int stroke, SweepSurface& out);

/// One sweep per stroke, in the order of the strokes.
Status strokeSweeps(const Scenario& scenario, std::vector<SweepSurface>& out);

/// The explicit sweep surfaces, in order: inline curves, or files read with readSweep
/// (resolved against scenario.baseDir). Errors name the sweep.
Status explicitSweeps(const Scenario& scenario, std::vector<SweepSurface>& out);

/// A sweep to cut with and where it comes from ("strokes[0] 'first pass'", "sweeps[1]").
struct ScenarioCut {
    std::string label;
    SweepSurface sweep;
};
/// Every cut of the scenario in replay order: the strokes, then the explicit sweeps.
Status scenarioCuts(const Scenario& scenario, std::vector<ScenarioCut>& out);

/// "strokes[i]" or "strokes[i] 'name'"; likewise for sweeps.
std::string strokeLabel(const Scenario& scenario, int stroke);
std::string sweepLabel(const Scenario& scenario, int sweep);

} // namespace resect
