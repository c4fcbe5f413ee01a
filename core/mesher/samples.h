#pragma once
// Built-in procedural anatomy resembling the paper's models (section 6, Figures 9 and 10):
//   polyp: a pedunculated polyp, a lobed head on a narrower stalk (about 20 mm tall)
//   myoma: a roughly spherical, slightly irregular mass (about 20 mm across)
// Each is a closed, manifold, outward-oriented high-resolution surface (tens of thousands
// of triangles) with texture coordinates; the coarse tet mesh is meshed from it.

#include "core/mesh/triangle_surface.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace resect {

enum class Sample { Polyp, Myoma };

/// "polyp" or "myoma"; nullopt for anything else.
std::optional<Sample> sampleFromName(std::string_view name);
std::string sampleName(Sample sample);
std::vector<std::string> sampleNames();

/// The sample's high-resolution surface. `detail` scales the resolution (1 = default,
/// 40 000 triangles; the triangle count is about proportional to `detail`, with a floor
/// of 8 rings x 12 segments; tests may use less). A non-positive or non-finite detail
/// is taken as 1. Deterministic: the same arguments give the same surface.
TriangleSurface sampleSurface(Sample sample, double detail = 1.0);

} // namespace resect
