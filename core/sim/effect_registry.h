#pragma once
// Effects by name, for callers that declare a scene (the CLI, later the scenario document):
//   deformation   the tissue model's internal forces (deformation_effect.h)
//   gravity       f = m g (gravity_effect.h)
//   fixed         anchored nodes (fixed_nodes_effect.h)
//   tool-contact  a tool pushing the surface out of its capsules (tool_contact_effect.h)
//   damping       f = -c m v (damping_effect.h)
// New effects are added with EffectRegistry::add; their parameters come from
// EffectSettings::extra or from whatever the factory captures.

#include "core/mesh/material.h"
#include "core/sim/deformation_model.h"
#include "core/sim/effect.h"
#include "core/sim/fixed_nodes_effect.h"
#include "core/sim/tool_contact_effect.h"
#include "core/status.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace resect {

/// Parameters of the built-in effects; each is read only if its effect is requested.
struct EffectSettings {
    DeformationTerms deformation;        ///< deformation: which terms
    Vec3 gravity{0, 0, -9810};           ///< gravity: mm/s^2
    FixedSelection fixed;                ///< fixed: nodes and/or a box (anchors.h; not empty)
    Tool tool;                           ///< tool-contact: polyline and radius (required)
    std::optional<double> damping;       ///< damping: 1/s (default Material::damping, > 0)
    std::map<std::string, double> extra; ///< parameters of registered effects
    int threads = 0;                     ///< 0: resolveThreadCount's default
    int grain = 4096;                    ///< minimum work per thread (parallel.h)
};

class EffectRegistry {
public:
    using Factory =
        std::function<Status(const TetMesh& mesh, const Material& material,
                             const EffectSettings& settings, std::unique_ptr<Effect>& out)>;

    /// A registry holding the built-in effects listed above.
    static EffectRegistry withBuiltins();

    /// Registers (or replaces) an effect.
    void add(const std::string& name, Factory factory);
    bool contains(const std::string& name) const { return m_factories.count(name) > 0; }
    /// Registered names, sorted.
    std::vector<std::string> names() const;

    /// Builds the named effect; an unknown name or bad parameters give an error naming them.
    Status create(const std::string& name, const TetMesh& mesh, const Material& material,
                  const EffectSettings& settings, std::unique_ptr<Effect>& out) const;

    /// Splits a comma-separated list ("deformation,gravity"); unknown, empty or repeated
    /// names are an error naming them.
    Status parseList(const std::string& text, std::vector<std::string>& names) const;

private:
    std::map<std::string, Factory> m_factories;
};

} // namespace resect
