#include "scenario/scene_defaults.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <limits>

namespace resect {

FixedRegion baseRegion(const Vec3& lo, const Vec3& hi, double fraction) {
    const Vec3 extent = (hi - lo).cwiseMax(Vec3::Zero());
    const double margin = kBaseRegionMarginFraction * extent.maxCoeff();
    FixedRegion region;
    region.min = lo - Vec3::Constant(margin);
    region.max = Vec3(hi.x() + margin, hi.y() + margin, lo.z() + fraction * extent.z());
    return region;
}

std::optional<FixedRegion> baseRegion(std::span<const Vec3> points, double fraction) {
    bool any = false;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = -lo;
    for (const Vec3& p : points) {
        if (!p.allFinite())
            continue;
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
        any = true;
    }
    if (!any)
        return std::nullopt;
    return baseRegion(lo, hi, fraction);
}

QJsonObject defaultEffectParameters(const std::string& name) {
    if (name == "deformation")
        return {{"distance", true}, {"volume", true}, {"area", true}};
    if (name == "gravity")
        return {{"acceleration", QJsonArray{0, 0, -kDefaultGravity}}};
    if (name == "tool-contact")
        return {{"radius", kDefaultToolContactRadius}};
    if (name == "damping")
        return {{"coefficient", kDefaultDampingCoefficient}};
    return {};
}

void applySceneDefaults(Scenario& scenario, const FixedRegion& base) {
    if (scenario.tissues.empty())
        return;
    scenario.tissues.front().fixedRegions = {base};
    std::vector<EffectSpec> effects;
    for (const std::string& name : knownEffectNames()) {
        if (const EffectSpec* declared = scenario.findEffect(name)) {
            effects.push_back(*declared);
        } else if (name == "fixed" || name == "damping") {
            EffectSpec e;
            e.name = name;
            e.parameters = defaultEffectParameters(name);
            effects.push_back(std::move(e));
        }
    }
    scenario.effects = std::move(effects);
}

FixedRegion sampleBaseRegion(Sample sample) {
    // The surface the tissue is meshed from (scenario_run.h loadTissue): its nodes lie in it.
    const TriangleSurface surface = sampleSurface(sample);
    return *baseRegion(surface.positions);
}

} // namespace resect
