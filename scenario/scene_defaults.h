#pragma once
// Defaults of a new scene (issue 19): what a scenario started from a sample gets, and what an
// effect switched on for the first time starts with, so that a scene behaves when it is
// simulated before the author has set anything.
//  - The base is anchored: one fixed region, a box around the bottom kBaseRegionFraction of the
//    body's height (z is up, as in the samples and the default gravity), reaching
//    kBaseRegionMarginFraction of the body's largest extent beyond its sides and below it, so
//    that the nodes on its bounds are inside. The bundled polyp example anchors its stalk the
//    same way (the bottom 1 mm of 20, `resect simulate --fix-box`).
//  - Damping is on: the effect needs a positive coefficient, and materials have none by
//    default (core/mesh/material.h).
// The parameters an effect starts with (defaultEffectParameters) are valid as they are
// (scenario_document.h's table), so switching an effect on never makes a scene that fails.

#include "core/mesher/samples.h"
#include "scenario/scenario_document.h"

#include <QJsonObject>

#include <optional>
#include <span>
#include <string>

namespace resect {

/// Height of the base region as a fraction of the body's height (z extent).
inline constexpr double kBaseRegionFraction = 0.05;
/// How far the base region reaches beyond the body's sides and below it, as a fraction of
/// the body's largest extent.
inline constexpr double kBaseRegionMarginFraction = 0.01;
/// 1/s: kinetic energy decays with the time constant 1 / (2 c) = 25 ms, as in the bundled
/// examples; a sagging tissue settles in a fraction of a second.
inline constexpr double kDefaultDampingCoefficient = 20.0;
/// mm: the radius of the tool-contact effect (required): the wire of a resectoscope loop is
/// about 0.3 mm thick; 0.5 leaves a small margin.
inline constexpr double kDefaultToolContactRadius = 0.5;
/// mm/s^2: gravity's default acceleration, down the z axis (as GravityEffect's).
inline constexpr double kDefaultGravity = 9810.0;

/// The base region of a body with bounds [lo, hi] (mm; see the top of this file).
FixedRegion baseRegion(const Vec3& lo, const Vec3& hi, double fraction = kBaseRegionFraction);
/// The base region of the bounds of `points` (a mesh's reference positions, a surface's
/// vertices); nullopt when there is no finite point.
std::optional<FixedRegion> baseRegion(std::span<const Vec3> points,
                                      double fraction = kBaseRegionFraction);

/// The parameters a known effect starts with when it is switched on (every key of its row in
/// scenario_document.h's table, with the defaults above); an empty object for other names.
QJsonObject defaultEffectParameters(const std::string& name);

/// A new scene's defaults on a scenario whose first tissue has bounds with base region
/// `base`: `base` becomes its fixed region (replacing any), and the fixed and damping effects
/// are switched on (with defaultEffectParameters) next to the effects it declares.
void applySceneDefaults(Scenario& scenario, const FixedRegion& base);

/// The base region of a built-in sample (from its high-resolution surface, which the meshed
/// tissue fills).
FixedRegion sampleBaseRegion(Sample sample);

} // namespace resect
