#include "core/sim/effect_registry.h"

#include "core/sim/damping_effect.h"
#include "core/sim/deformation_effect.h"
#include "core/sim/gravity_effect.h"
#include "core/sim/parallel.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace resect {

EffectRegistry EffectRegistry::withBuiltins() {
    EffectRegistry r;
    r.add("deformation", [](const TetMesh& mesh, const Material& material, const EffectSettings& s,
                            std::unique_ptr<Effect>& out) {
        if (!s.deformation.distance && !s.deformation.volume && !s.deformation.area)
            return Status::error("deformation: no term enabled");
        if (!std::isfinite(material.stiffness) || !(material.stiffness > 0))
            return Status::error("deformation: the stiffness must be finite and positive");
        DeformationOptions options;
        options.terms = s.deformation;
        options.threads = s.threads;
        options.grain = s.grain;
        out = std::make_unique<DeformationEffect>(mesh, material, options);
        return Status::success();
    });
    r.add("gravity", [](const TetMesh&, const Material&, const EffectSettings& s,
                        std::unique_ptr<Effect>& out) {
        if (!s.gravity.allFinite())
            return Status::error("gravity: the acceleration must be finite");
        out = std::make_unique<GravityEffect>(s.gravity, resolveThreadCount(s.threads), s.grain);
        return Status::success();
    });
    r.add("damping", [](const TetMesh&, const Material& material, const EffectSettings& s,
                        std::unique_ptr<Effect>& out) {
        const double c = s.damping.value_or(material.damping);
        if (!std::isfinite(c) || !(c > 0))
            return Status::error(
                "damping: the coefficient must be finite and positive (1/s), got " +
                std::to_string(c));
        out = std::make_unique<DampingEffect>(c, resolveThreadCount(s.threads), s.grain);
        return Status::success();
    });
    r.add("fixed", [](const TetMesh& mesh, const Material&, const EffectSettings& s,
                      std::unique_ptr<Effect>& out) {
        if (s.fixed.box) {
            const auto& [lo, hi] = *s.fixed.box;
            if (!lo.allFinite() || !hi.allFinite() || (lo.array() > hi.array()).any())
                return Status::error("fixed: the box must be finite with lo <= hi");
        }
        if (s.fixed.empty()) {
            return Status::error("fixed: give anchored nodes or a box");
        }
        for (int n : s.fixed.nodes)
            if (n < 0 || n >= mesh.nodeCount())
                return Status::error("fixed: node " + std::to_string(n) + " is not in the mesh");
        Anchors anchors;
        if (Status st = Anchors::create(mesh, s.fixed, anchors); !st.ok())
            return Status::error("fixed: " + st.message());
        out = std::make_unique<FixedNodesEffect>(mesh, std::move(anchors));
        return Status::success();
    });
    r.add("tool-contact", [](const TetMesh& mesh, const Material&, const EffectSettings& s,
                             std::unique_ptr<Effect>& out) {
        if (Status st = checkTool(s.tool); !st.ok())
            return Status::error("tool-contact: " + st.message());
        out = std::make_unique<ToolContactEffect>(mesh, s.tool);
        return Status::success();
    });
    return r;
}

void EffectRegistry::add(const std::string& name, Factory factory) {
    m_factories[name] = std::move(factory);
}

std::vector<std::string> EffectRegistry::names() const {
    std::vector<std::string> result;
    for (const auto& [name, factory] : m_factories)
        result.push_back(name);
    return result;
}

Status EffectRegistry::create(const std::string& name, const TetMesh& mesh,
                              const Material& material, const EffectSettings& settings,
                              std::unique_ptr<Effect>& out) const {
    const auto it = m_factories.find(name);
    if (it == m_factories.end()) {
        std::string known;
        for (const auto& n : names())
            known += (known.empty() ? "" : ", ") + n;
        return Status::error("unknown effect '" + name + "' (known: " + known + ")");
    }
    return it->second(mesh, material, settings, out);
}

Status EffectRegistry::parseList(const std::string& text, std::vector<std::string>& names) const {
    names.clear();
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        if (item.empty())
            return Status::error("empty effect name in '" + text + "'");
        if (!contains(item)) {
            std::string known;
            for (const auto& n : this->names())
                known += (known.empty() ? "" : ", ") + n;
            return Status::error("unknown effect '" + item + "' (known: " + known + ")");
        }
        if (std::find(names.begin(), names.end(), item) != names.end())
            return Status::error("effect '" + item + "' given twice");
        names.push_back(item);
    }
    if (names.empty() || (!text.empty() && text.back() == ','))
        return Status::error("empty effect list '" + text + "'");
    return Status::success();
}

} // namespace resect
