#pragma once
// After a cut: the pieces that no longer touch an anchored node (a fixed region) are resected
// (the paper's Figure 10: each pass of the loop takes a chip off). They leave the tissue's tet
// mesh, so later cuts never cut them again, and become Chips, which either leave the scene
// (Remove) or fall as one rigid body each (Rigid: a chip never limits the tissue's time step).
// Keep leaves them in the tissue, deformable, as before.

#include "core/mesh/topology.h"
#include "core/mesh/triangle_surface.h"
#include "core/sim/anchors.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <span>
#include <vector>

namespace resect {

enum class ResectedPieces { Keep, Remove, Rigid };
/// "keep", "remove", "rigid".
const char* resectedPiecesName(ResectedPieces policy);
/// Parses the names above (also "deformable" for Keep); false for anything else.
bool parseResectedPieces(const std::string& name, ResectedPieces& out);

/// One rigid body: centre of mass and orientation, velocities, and its mass properties.
struct RigidBody {
    Vec3 centre = Vec3::Zero();                               ///< mm, current centre of mass
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    Vec3 velocity = Vec3::Zero();                             ///< mm/s
    Vec3 angularVelocity = Vec3::Zero();                      ///< rad/s, world frame
    double mass = 0;                                          ///< g
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();    ///< g mm^2, body frame, about the centre
    std::vector<Vec3> local;                                  ///< the chip's nodes in the body frame
    bool resting = false;                                     ///< lying on the floor (for good)
};

/// A piece that left the tissue.
struct Chip {
    TetMesh mesh;             ///< its tets and nodes, renumbered; positions follow the body
    TriangleSurface surface;  ///< its part of the embedded surface (may be empty)
    std::vector<Vec3> surfaceLocal;  ///< the surface's vertices in the body frame
    double volume = 0;        ///< reference volume, mm^3
    double mass = 0;          ///< g
    int cut = 0;              ///< the cut (counted from 1) that resected it
    /// The tissue's cut marks of its nodes and tets (Tissue::onCutSurface, Tissue::tetCuts),
    /// carried over by Tissue when it resected the piece; empty when made by resectPieces alone.
    std::vector<std::uint8_t> onCutSurface;
    std::vector<int> tetCuts;
    RigidBody body;
};

/// What resectPieces did: the renumbering of the tissue (old -> new index, -1 removed) and
/// the chip each removed tet went to (-1 for kept tets).
struct Resection {
    std::vector<int> newNode, newTet, pieceOfTet;
    int firstChip = 0;  ///< index in `chips` of the first chip made now
    int chips = 0;      ///< chips made now
    double volume = 0, mass = 0;
};

/// Splits the pieces of `mesh` (its components `pieces`) holding no anchored node off it:
/// `mesh` keeps the rest, renumbered in order; each removed piece is appended to `chips` (with
/// its rigid body at rest). With no anchors nothing is removed. O(mesh).
Resection resectPieces(TetMesh& mesh, const Components& pieces, const Anchors& anchors, int cut,
                       std::vector<Chip>& chips);

/// The rigid body of a chip from its tets (mass from its nodes' masses, inertia from its tets
/// with their mass spread evenly); its nodes and surface in the body frame.
void makeRigidBody(Chip& chip);

/// The tissue's upward-facing boundary triangles at their current positions, in a grid over
/// (x, y): what a falling chip lands on. Building it is O(triangles); a query looks at one
/// cell.
class RestingSurface {
public:
    /// triangles: the tissue's boundary triangles (outward oriented), positions: current.
    void build(std::span<const Tri> triangles, std::span<const Vec3> positions);
    /// The highest point of the surface on the vertical through (x, y) that is not above z;
    /// -infinity if there is none.
    double heightBelow(double x, double y, double z) const;
    bool empty() const { return m_triangles.empty(); }

private:
    std::vector<std::array<Vec3, 3>> m_triangles;
    Vec3 m_lo = Vec3::Zero();
    double m_cell = 1;
    int m_nx = 0, m_ny = 0;
    std::vector<int> m_begin, m_items; ///< per cell (CSR): the triangles over it
};

/// One step of h seconds of every chip's rigid body under gravity (mm/s^2), resting on the
/// plane z = floor and, if given, on the tissue's surface (a chip lands on the tissue and stays
/// there; the tissue does not feel it): semi-implicit Euler, with the chip's nodes kept above
/// the support by a position correction of the body and friction that stops it. Moves the
/// chips' nodes and surfaces. O(chip nodes).
void stepChips(std::vector<Chip>& chips, double h, const Vec3& gravity, double floor,
               const RestingSurface* tissue = nullptr);

} // namespace resect
