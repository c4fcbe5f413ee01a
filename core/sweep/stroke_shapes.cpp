#include "core/sweep/stroke_shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace resect {

std::vector<Vec3> halfLoop(double halfWidth, double depth, int points) {
    points = std::max(points, 3);
    std::vector<Vec3> out;
    for (int i = 0; i < points; ++i) {
        const double a = std::numbers::pi * i / (points - 1);
        out.emplace_back(halfWidth * std::cos(a), 0.0, -depth * std::sin(a));
    }
    return out;
}

Curves loopScoop(const ScoopShape& s) {
    const Vec3 along(std::cos(s.angle), std::sin(s.angle), 0);
    const Vec3 across(-along.y(), along.x(), 0);
    const int poses = std::max(s.poses, 2);
    // The loop in the plane spanned by `across` and z: chord across the pull, arms up.
    const double loopDepth = s.depth + s.armHeight;
    const std::vector<Vec3> loop = halfLoop(s.halfWidth, loopDepth, s.points);
    Curves curves;
    for (int i = 0; i < poses; ++i) {
        const double f = -1.0 + 2.0 * i / (poses - 1);  // -1 .. 1 along the pull
        const double bottom = s.centre.z() + s.rise - (s.depth + s.rise) * (1 - f * f);
        const Vec3 base = Vec3(s.centre.x(), s.centre.y(), 0) + f * s.reach * along;
        std::vector<Vec3> curve;
        for (const Vec3& p : loop)
            curve.push_back(base + p.x() * across + Vec3(0, 0, bottom + loopDepth + p.z()));
        curves.push_back(std::move(curve));
    }
    return curves;
}

ScoopShape resectionScoop(const Eigen::AlignedBox3d& bounds, const Vec3& axis, int k, const ResectionPlan& plan) {
    const Vec3 size = bounds.sizes();
    const double width = std::max(size.x(), size.y()), height = size.z();
    constexpr double kGoldenAngle = 2.399963229728653;  // rad
    ScoopShape s;
    s.angle = k * kGoldenAngle;
    const Vec3 along(std::cos(s.angle), std::sin(s.angle), 0);
    s.centre = Vec3(axis.x(), axis.y(), bounds.max().z()) + k * plan.shift * width * along;
    s.halfWidth = plan.widthFraction * width;
    s.depth = (plan.firstDepth + k * plan.depthStep) * height;
    s.reach = 0.9 * width;
    s.rise = 0.075 * height;
    s.armHeight = 0.2 * height;
    s.poses = plan.poses;
    s.points = plan.points;
    return s;
}

Curves mouseStroke(std::mt19937& rng, const Eigen::AlignedBox3d& bounds, const MouseStrokeShape& shape) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Vec3 size = bounds.sizes(), centre = bounds.center();
    const double width = std::max(size.x(), size.y()), height = size.z();
    // View direction: down, tilted by up to maxTilt towards a random azimuth.
    const double tilt = shape.maxTilt * unit(rng), azimuth = 2 * std::numbers::pi * unit(rng);
    const Vec3 view = Vec3(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), -std::cos(tilt));
    // Drag direction in the view plane, at a random angle.
    const Vec3 e1 = view.unitOrthogonal(), e2 = view.cross(e1);
    const double heading = 2 * std::numbers::pi * unit(rng);
    const Vec3 drag = std::cos(heading) * e1 + std::sin(heading) * e2;
    const Vec3 side = drag.cross(view);  // across the drag, in the view plane
    // The press point: on the body's axis at a depth below its top (the recorder's depth
    // reference), offset a little sideways; the path runs through it in the view plane.
    const Vec3 press = Vec3(centre.x(), centre.y(), bounds.max().z() - shape.depthFraction * height) +
                       (unit(rng) - 0.5) * 0.3 * width * side;
    const double reach = 0.8 * width;
    // Loop frame: chord along `side`, bulge along `view` (away from the viewer), plane normal `drag`.
    const std::vector<Vec3> loop = halfLoop(shape.halfWidth, shape.halfWidth, shape.points);
    // Wiggle: a sum of two random sines across the drag (and, without `monotonic`, along it).
    const double phase1 = 2 * std::numbers::pi * unit(rng), phase2 = 2 * std::numbers::pi * unit(rng);
    const double f1 = 1 + 2 * unit(rng), f2 = 3 + 3 * unit(rng);
    const double amplitude = shape.wiggle * width;
    const int poses = std::max(shape.poses, 2);
    Curves curves;
    for (int i = 0; i < poses; ++i) {
        const double s = static_cast<double>(i) / (poses - 1);
        const double w1 = std::sin(2 * std::numbers::pi * f1 * s + phase1);
        const double w2 = std::sin(2 * std::numbers::pi * f2 * s + phase2);
        double forward = (2 * s - 1) * reach;
        if (!shape.monotonic)
            forward += 0.5 * amplitude * w2 * f2;  // can exceed the forward step: turns back
        const Vec3 position = press + forward * drag + amplitude * (0.7 * w1 + 0.3 * w2) * side;
        std::vector<Vec3> curve;
        // Chord across the drag; the loop's -z (its bulge) points along the view.
        for (const Vec3& p : loop)
            curve.push_back(position + p.x() * side - p.z() * view);
        curves.push_back(std::move(curve));
    }
    return curves;
}

} // namespace resect
