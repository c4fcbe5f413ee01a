#pragma once
// The `tool-contact` effect: a rigid tool (the loop electrode) pushes the tissue.
//
// The tool is a polyline with a radius: the union of the capsules around its segments (a
// single point is a sphere). Its pose (the polyline's points) can be set before every step.
// Contact is resolved by projection, not by a penalty force: after the integrator moved the
// nodes, every surface node (a node of a boundary face) inside the tool is moved to the
// nearest point of the tool's surface, and the normal component of its velocity relative to
// the tool is clamped so that it no longer approaches the tool (inelastic contact, no
// friction; the tool's velocity comes from its last two poses). Projection needs no contact
// stiffness, so it does not lower the stable time step, it never lets a surface node stay
// inside the tool whatever the tool's speed, and a deep initial overlap is resolved without
// turning the position jump into velocity. Interior nodes are not tested: the tissue is only
// reached through its surface. Cost per step: O(surface nodes within the tool's bounding box x
// segments).

#include "core/sim/effect.h"
#include "core/status.h"

#include <vector>

namespace resect {

struct Tool {
    std::vector<Vec3> points; ///< the polyline (mm), at least one point
    double radius = 0;        ///< mm, > 0
};

/// Empty message if the tool is usable: >= 1 finite point, finite radius > 0.
Status checkTool(const Tool& tool);

class ToolContactEffect : public Effect {
public:
    /// The tool must pass checkTool. Finds the surface nodes (O(mesh)).
    ToolContactEffect(const TetMesh& mesh, Tool tool);

    std::string name() const override { return "tool-contact"; }
    int phase() const override { return kContact; }
    bool afterStep(const SimState& s) override;
    void applyCut(const TetMesh& mesh, const CutChanges& changes) override;

    /// Moves the tool: the same number of points as before, all finite.
    Status setPose(std::span<const Vec3> points);
    const Tool& tool() const { return m_tool; }
    /// Surface nodes pushed out in the last step.
    int lastContacts() const { return m_lastContacts; }
    /// Nodes tested for contact (the surface nodes), in no particular order.
    const std::vector<int>& surfaceNodes() const { return m_surface; }

    /// Closest point of the tool's axis (the polyline) to p.
    Vec3 closestPoint(const Vec3& p) const;

private:
    void setSurface(int node, bool surface);

    Tool m_tool;
    std::vector<Vec3> m_previous; ///< the pose at the end of the last step (tool velocity)
    std::vector<int> m_surface;   ///< surface nodes
    std::vector<int> m_position;  ///< #nodes: index in m_surface, or -1
    int m_lastContacts = 0;
};

} // namespace resect
