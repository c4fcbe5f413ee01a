#pragma once
// DeformationModel: the terms of the tissue model (forces.h) as structure-of-arrays data,
// built from a TetMesh and updated after a cut in time proportional to the change.
//
// Terms and stiffnesses (Teschner et al. 2004, the paper's ref. [19]; Eq. 3 and 4):
//   distance, one per mesh edge (a, b):   k_s = k (m_a + m_b) / l0^2          (Eq. 4)
//   volume, one per tet t:                k_v = k (m_1 + m_2 + m_3 + m_4) / V0^2  (Eq. 4)
//   area, one per boundary triangle:      k_a = k (m_a + m_b + m_c) / A0^2
// k is Material::stiffness (mm^2/s^2), m the lumped masses of Eq. 3 read from the mesh, and
// l0, V0, A0 the reference geometry. The paper gives Eq. 4 for edges and tets only; the area
// stiffness follows the same rule (the term's masses over its squared rest measure), so that
// every term contributes a frequency sqrt(k) / L of the same order and the stable time step
// (stable_time_step.h with areaTerm) keeps its form. Boundary triangles are the faces in
// exactly one tet, oriented outward; their area term resists stretching of the surface.
//
// Layout: volume terms are indexed like the mesh's tets (their node indices are read from
// the mesh). Edges and triangles live in slots; the initial ones are sorted by their smallest
// node, for locality. A cut kills the slots of terms that disappeared (they become inert:
// zero stiffness, zero rest value, and are reused by later additions) and appends new ones.

#include "core/cut/cut_types.h"
#include "core/mesh/material.h"
#include "core/sim/forces.h"

#include <unordered_map>
#include <vector>

namespace resect {

struct DeformationTerms {
    bool distance = true; ///< distance preservation on every edge
    bool volume = true;   ///< volume preservation on every tet
    bool area = true;     ///< surface-area preservation on every boundary triangle
};

/// Which slots a cut changed (created, re-used, re-computed or killed), for the caller's
/// per-slot bookkeeping (DeformationEffect's thread windows).
struct DeformationChanges {
    std::vector<int> edgeSlots;
    std::vector<int> triangleSlots;
    std::vector<int> tets;
};

class DeformationModel {
public:
    DeformationModel() = default;
    /// Builds every enabled term from the mesh (O(mesh)). Needs masses (Eq. 3).
    DeformationModel(const TetMesh& mesh, const Material& material, const DeformationTerms& terms);

    /// After a cut (HybridCutter, which has already updated masses): re-computes the terms
    /// around the nodes the cut touched, kills the ones that disappeared, adds the new ones.
    /// Cost O(sum of the valences of the touched nodes). Assumes, as CutChanges guarantees,
    /// that every node of every tet that changed (before and after) is in touchedNodes or is
    /// an original or copy in duplicatedNodes. Returns the slots it changed.
    DeformationChanges applyCut(const TetMesh& mesh, const CutChanges& changes);

    const DeformationTerms& terms() const { return m_terms; }

    // --- distance terms (#edge slots) ---
    std::span<const Edge> edges() const { return m_edges; }
    std::span<const double> edgeRestLength() const { return m_edgeRest; }
    std::span<const double> edgeStiffness() const { return m_edgeK; }
    // --- volume terms (#tets, indexed like mesh.tets()), scaled as forces.h says ---
    std::span<const double> tetRestVolume6() const { return m_tetRest; } ///< 6 V0
    std::span<const double> tetStiffness36() const { return m_tetK; }    ///< k_v / 36
    // --- area terms (#triangle slots) ---
    std::span<const Tri> triangles() const { return m_tris; }
    std::span<const double> triangleRestArea() const { return m_triRest; }
    std::span<const double> triangleStiffness() const { return m_triK; }

    int liveEdgeCount() const { return static_cast<int>(m_edges.size() - m_freeEdges.size()); }
    int liveTriangleCount() const { return static_cast<int>(m_tris.size() - m_freeTris.size()); }
    /// Live terms, each with its nodes sorted, as keys (for tests comparing two models).
    std::vector<Edge> liveEdges() const;
    std::vector<Tri> liveTriangles() const;

private:
    /// Slots grouped by their term's smallest node: the initial slots in a CSR layout, slots
    /// filled later in a per-node overflow list.
    struct SlotIndex {
        std::vector<int> begin; ///< #initial nodes + 1
        std::unordered_map<int, std::vector<int>> extra;
        template <class F> void forEach(int owner, F&& f) const;
        bool inInitialRange(int owner, int slot) const;
        void add(int owner, int slot);
        void remove(int owner, int slot);
    };

    void setTet(const TetMesh& mesh, int t);
    void setEdge(const TetMesh& mesh, int slot, int a, int b);
    void setTriangle(const TetMesh& mesh, int slot, const Tri& nodes);
    int findEdge(int a, int b) const;               ///< a < b; -1 if absent
    int findTriangle(const Tri& sortedNodes) const; ///< -1 if absent
    int allocateEdge(int owner);
    int allocateTriangle(int owner);
    void killEdge(int slot);
    void killTriangle(int slot);

    Material m_material;
    DeformationTerms m_terms;
    std::vector<Edge> m_edges;
    std::vector<double> m_edgeRest, m_edgeK;
    std::vector<double> m_tetRest, m_tetK;
    std::vector<Tri> m_tris;
    std::vector<double> m_triRest, m_triK;
    SlotIndex m_edgeIndex, m_triIndex;
    std::vector<int> m_freeEdges, m_freeTris;
};

} // namespace resect
