#pragma once
// TetMesh: the coarse tetrahedral mesh that is simulated and cut.
//
// Nodes are stored as a structure of arrays (reference positions, current positions,
// velocities, masses: one array each, indexed by node). Tets are four node indices,
// positively oriented in the reference configuration: det[p1-p0, p2-p0, p3-p0] > 0.
//
// Only node->tets adjacency is stored; it is updated incrementally by every topology edit
// (addNode, addTet, replaceTet), so edits cost O(valence), never O(mesh). Edge->tets and
// face->tets are answered locally from it. Global derived structures (the edge list,
// boundary faces, connected components) are built on demand by the functions in
// topology.h, for reporting and for setting up a simulation, not per edit.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products on Vec3 everywhere

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace resect {

class TetMeshBackup;

using Vec3 = Eigen::Vector3d;
using Tet = std::array<int, 4>;
using Tri = std::array<int, 3>;

/// Local numbering of a tet's six edges: edge e joins local nodes kTetEdges[e][0] and
/// kTetEdges[e][1]. Bit e of a six-bit cut-edge code refers to this edge.
inline constexpr std::array<std::array<int, 2>, 6> kTetEdges{
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

/// Local numbering of a tet's four faces: face f is opposite local node f, listed so that
/// its right-hand normal points out of a positively oriented tet.
inline constexpr std::array<std::array<int, 3>, 4> kTetFaces{
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

class TetMesh {
public:
    TetMesh() = default;

    /// Builds a mesh whose current positions equal the reference positions; velocities and
    /// masses are zero. Indices must be valid (see checkTetIndices for untrusted input).
    static TetMesh fromArrays(std::vector<Vec3> referencePositions, std::vector<Tet> tets);

    int nodeCount() const { return static_cast<int>(m_ref.size()); }
    int tetCount() const { return static_cast<int>(m_tets.size()); }
    bool empty() const { return m_tets.empty(); }

    // --- node arrays (structure of arrays); sizes are kept equal by addNode ---
    std::span<const Vec3> referencePositions() const { return m_ref; }
    std::span<Vec3> referencePositions() { return m_ref; }
    std::span<const Vec3> positions() const { return m_pos; }
    std::span<Vec3> positions() { return m_pos; }
    std::span<const Vec3> velocities() const { return m_vel; }
    std::span<Vec3> velocities() { return m_vel; }
    std::span<const double> masses() const { return m_mass; }
    std::span<double> masses() { return m_mass; }

    const Vec3& ref(int n) const { return m_ref[n]; }
    const Vec3& pos(int n) const { return m_pos[n]; }

    // --- tets ---
    const std::vector<Tet>& tets() const { return m_tets; }
    const Tet& tet(int t) const { return m_tets[t]; }

    // --- incremental topology edits, O(valence) each ---
    /// Appends a node; returns its index. Velocity and mass start at zero.
    int addNode(const Vec3& referencePosition, const Vec3& currentPosition);
    /// Appends a tet; returns its index.
    int addTet(const Tet& t);
    /// Replaces the nodes of tet t (used when a tet is decomposed in place or re-attached
    /// to a duplicated node).
    void replaceTet(int t, const Tet& nodes);
    /// Removes tet t: the last tet takes its slot (so tet indices above t may change: the last
    /// one becomes t). O(valence). Recorded by open backups.
    void removeTet(int t);
    /// Removes node n, which no tet may use: the last node takes its index (the tets of the
    /// last node are relabelled). O(valence of the last node). Recorded by open backups.
    void removeNode(int n);
    void reserve(int nodes, int tets);
    /// Removes the trailing tets and nodes beyond the given counts. The remaining tets must
    /// not refer to removed nodes. (To undo an edit exactly, use a TetMeshBackup.)
    void truncate(int nodes, int tets);

    // --- node edits that an open TetMeshBackup records (tet_mesh_backup.h) ---
    /// Moves node n in both configurations.
    void setNodePosition(int n, const Vec3& referencePosition, const Vec3& currentPosition);
    void setMass(int n, double mass);

    // --- local adjacency ---
    /// Tets incident to node n, in no particular order.
    std::span<const int> nodeTets(int n) const { return m_nodeTets[n]; }
    /// Tets containing both nodes a and b (appended to out after clearing it).
    void edgeTets(int a, int b, std::vector<int>& out) const;
    /// Tets containing nodes a, b and c (appended to out after clearing it).
    void faceTets(int a, int b, int c, std::vector<int>& out) const;
    /// Nodes sharing an edge with n, sorted, without duplicates.
    std::vector<int> nodeNeighbours(int n) const;

    // --- geometry of one tet ---
    /// Signed volume det[p1-p0, p2-p0, p3-p0] / 6 in the reference configuration.
    double referenceVolume(int t) const;
    /// Signed volume in the current configuration.
    double currentVolume(int t) const;
    /// Sum of signed reference volumes.
    double totalReferenceVolume() const;

private:
    friend class TetMeshBackup;
    void attach(int t);
    void detach(int t);
    /// Tells every open backup that tet t / node n is about to change.
    void willChangeTet(int t);
    void willChangeNode(int n);
    void willChangeNodesOf(const Tet& t);

    /// Open backups, innermost last. Not copied with the mesh: a copy has none.
    struct Backups {
        std::vector<TetMeshBackup*> open;
        Backups() = default;
        Backups(const Backups&) {}
        Backups(Backups&&) noexcept {}
        Backups& operator=(const Backups&) { return *this; }
        Backups& operator=(Backups&&) noexcept { return *this; }
    };

    std::vector<Vec3> m_ref;
    std::vector<Vec3> m_pos;
    std::vector<Vec3> m_vel;
    std::vector<double> m_mass;
    std::vector<Tet> m_tets;
    std::vector<std::vector<int>> m_nodeTets;
    Backups m_backups;
};

/// Signed volume of the tet (a, b, c, d): det[b-a, c-a, d-a] / 6.
double signedVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Barycentric coordinates of p in the tet (a, b, c, d) (closed form: w_i is the volume of the
/// tet with corner i replaced by p over the tet's volume); they sum to 1.
std::array<double, 4> barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& p);

/// For untrusted input: returns an empty string if every tet has four distinct indices in
/// [0, nodeCount), else a message naming the first bad tet.
std::string checkTetIndices(int nodeCount, std::span<const Tet> tets);

} // namespace resect
