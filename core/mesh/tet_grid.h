#pragma once
// Uniform grid over the tets of a mesh (current positions), so that a cut finds the tets
// near its sweep in time proportional to the sweep's area, not to the mesh size.
//
// build() is O(mesh) and belongs where positions change anyway (after loading, after
// simulation steps, alongside collision detection). Between builds, tets appended by a cut
// are added with insert(); a tet replaced in place by a sub-tet stays registered in its old
// cells, which cover it (sub-tets lie inside their parent). Queries are conservative: they
// return every tet whose box overlaps the query and possibly a few more.

#include "core/mesh/renumbering.h"
#include "core/mesh/tet_mesh.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace resect {

class TetGrid {
public:
    /// Cell size 0 chooses twice the mean tet bounding-box extent.
    void build(const TetMesh& mesh, double cellSize = 0);
    /// Registers a tet appended after build() (current positions), or a tet that took another's
    /// index or changed shape (its old registrations stay: queries are conservative).
    void insert(const TetMesh& mesh, int tet);
    /// After a local remeshing that removed tets (the last ones took the freed indices) and
    /// replaced some (`created`): registers the tets that now hold a changed index. Indices at
    /// or past the mesh's new tet count are no longer returned. O(changed tets), not O(mesh).
    void renumber(const TetMesh& mesh, const SparseRenumbering& tets, const std::vector<int>& created);

    /// Undo of insert() calls, for an edit that may be rolled back (a cut): checkpoint()
    /// starts recording inserts, rollback() removes the ones made since, release() keeps them.
    /// Checkpoints nest (LIFO). build() drops every checkpoint.
    struct Checkpoint {
        std::size_t logSize = 0;
        int tetCount = 0;
    };
    Checkpoint checkpoint();
    void rollback(const Checkpoint& checkpoint);
    void release(const Checkpoint& checkpoint);
    bool empty() const { return m_cellSize <= 0; }
    double cellSize() const { return m_cellSize; }

    /// Tets registered in cells overlapping `box`, each once (appended to out, cleared first).
    void query(const Eigen::AlignedBox3d& box, std::vector<int>& out) const;
    /// Tets in cells that the triangle (a, b, c) may cross: cells of its bounding box whose
    /// centre is within half a cell diagonal of the triangle's plane.
    void queryTriangle(const Vec3& a, const Vec3& b, const Vec3& c, std::vector<int>& out) const;

private:
    Eigen::Array3i cellOf(const Vec3& p) const;
    std::int64_t cellIndex(const Eigen::Array3i& c) const {
        return (static_cast<std::int64_t>(c.z()) * m_dims.y() + c.y()) * m_dims.x() + c.x();
    }
    template <class Visit> void forCells(const Eigen::Array3i& lo, const Eigen::Array3i& hi,
                                         const Visit& visit) const;
    void collect(std::int64_t cell, std::vector<int>& out) const;

    double m_cellSize = 0;
    Vec3 m_origin = Vec3::Zero();
    Eigen::Array3i m_dims = Eigen::Array3i::Ones();
    std::vector<int> m_start;   ///< CSR offsets per cell (size cells + 1)
    std::vector<int> m_items;   ///< tets per cell
    std::unordered_map<std::int64_t, std::vector<int>> m_extra;  ///< tets inserted later
    int m_tetCount = 0;         ///< indices at or past it are stale (tets removed since)
    std::vector<std::int64_t> m_insertLog;  ///< cells appended to since the first open checkpoint
    int m_openCheckpoints = 0;
    mutable std::vector<std::uint32_t> m_stamp;
    mutable std::uint32_t m_epoch = 0;
};

} // namespace resect
