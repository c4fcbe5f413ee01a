#include "scenario/scenario_sweeps.h"

#include "scenario/sweep_io.h"

#include <algorithm>
#include <cmath>

namespace resect {

namespace {

Eigen::Quaterniond rotationOf(const Eigen::Vector4d& wxyz) {
    const double length = wxyz.norm();
    if (!(length > 0) || !std::isfinite(length))
        return Eigen::Quaterniond::Identity();
    return Eigen::Quaterniond(wxyz[0] / length, wxyz[1] / length, wxyz[2] / length,
                              wxyz[3] / length);
}

Status withLabel(const std::string& label, const Status& s) {
    return s.ok() ? s : Status::error(label + ": " + s.message());
}

} // namespace

std::vector<Vec3> toolCurveAt(const ToolSpec& tool, const ToolPose& pose) {
    const Eigen::Matrix3d r = rotationOf(pose.orientation).toRotationMatrix();
    std::vector<Vec3> out;
    out.reserve(tool.curve.size());
    for (const Vec3& p : tool.curve)
        out.push_back(pose.position + r * (tool.size * p));
    return out;
}

ToolPose poseAt(const Stroke& stroke, double t) {
    const auto& poses = stroke.poses;
    if (poses.empty())
        return {};
    if (!(t > poses.front().t))
        return poses.front();
    if (t >= poses.back().t)
        return poses.back();
    // First pose with a time stamp above t; poses[i - 1].t <= t < poses[i].t.
    const auto it = std::upper_bound(poses.begin(), poses.end(), t,
                                     [](double value, const ToolPose& p) { return value < p.t; });
    const ToolPose& a = *(it - 1);
    const ToolPose& b = *it;
    const double w = (t - a.t) / (b.t - a.t);
    ToolPose out;
    out.t = t;
    out.position = (1 - w) * a.position + w * b.position;
    const Eigen::Quaterniond q = rotationOf(a.orientation).slerp(w, rotationOf(b.orientation));
    out.orientation = Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
    return out;
}

std::string strokeLabel(const Scenario& scenario, int stroke) {
    std::string label = "strokes[" + std::to_string(stroke) + "]";
    if (stroke >= 0 && stroke < static_cast<int>(scenario.strokes.size()) &&
        !scenario.strokes[stroke].name.empty())
        label += " '" + scenario.strokes[stroke].name + "'";
    return label;
}

std::string sweepLabel(const Scenario& scenario, int sweep) {
    std::string label = "sweeps[" + std::to_string(sweep) + "]";
    if (sweep >= 0 && sweep < static_cast<int>(scenario.sweeps.size()) &&
        !scenario.sweeps[sweep].name.empty())
        label += " '" + scenario.sweeps[sweep].name + "'";
    return label;
}

Status strokeSweep(const Scenario& scenario, int stroke, SweepSurface& out) {
    const std::string label = strokeLabel(scenario, stroke);
    if (stroke < 0 || stroke >= static_cast<int>(scenario.strokes.size()))
        return Status::error(label + ": no such stroke");
    if (scenario.tool.curve.size() < 2)
        return Status::error(label + ": the tool curve needs at least two points");
    const auto& poses = scenario.strokes[stroke].poses;
    std::vector<std::vector<Vec3>> curves;
    const ToolPose* previous = nullptr;
    for (const ToolPose& p : poses) {
        if (previous && previous->position == p.position && previous->orientation == p.orientation)
            continue; // the tool held still: no new curve
        curves.push_back(toolCurveAt(scenario.tool, p));
        previous = &p;
    }
    if (curves.size() < 2)
        return Status::error(label + ": the tool does not move (fewer than two distinct poses)");
    return withLabel(label, SweepSurface::fromCurves(curves, out));
}

Status strokeSweeps(const Scenario& scenario, std::vector<SweepSurface>& out) {
    std::vector<SweepSurface> sweeps(scenario.strokes.size());
    for (std::size_t i = 0; i < sweeps.size(); ++i)
        if (Status s = strokeSweep(scenario, static_cast<int>(i), sweeps[i]); !s.ok())
            return s;
    out = std::move(sweeps);
    return Status::success();
}

Status explicitSweeps(const Scenario& scenario, std::vector<SweepSurface>& out) {
    std::vector<SweepSurface> sweeps(scenario.sweeps.size());
    for (std::size_t i = 0; i < sweeps.size(); ++i) {
        const SweepSpec& spec = scenario.sweeps[i];
        const std::string label = sweepLabel(scenario, static_cast<int>(i));
        const Status s =
            spec.file.empty()
                ? SweepSurface::fromCurves(spec.curves, sweeps[i])
                : readSweep(resolveScenarioPath(scenario.baseDir, spec.file), sweeps[i]);
        if (!s.ok())
            return withLabel(label, s);
    }
    out = std::move(sweeps);
    return Status::success();
}

Status scenarioCuts(const Scenario& scenario, std::vector<ScenarioCut>& out) {
    std::vector<SweepSurface> strokes, explicitOnes;
    if (Status s = strokeSweeps(scenario, strokes); !s.ok())
        return s;
    if (Status s = explicitSweeps(scenario, explicitOnes); !s.ok())
        return s;
    std::vector<ScenarioCut> cuts;
    for (std::size_t i = 0; i < strokes.size(); ++i)
        cuts.push_back({strokeLabel(scenario, static_cast<int>(i)), std::move(strokes[i])});
    for (std::size_t i = 0; i < explicitOnes.size(); ++i)
        cuts.push_back({sweepLabel(scenario, static_cast<int>(i)), std::move(explicitOnes[i])});
    out = std::move(cuts);
    return Status::success();
}

} // namespace resect
