#include "core/mesh/tet_grid.h"

#include <algorithm>
#include <cmath>

namespace resect {
namespace {

Eigen::AlignedBox3d tetBox(const TetMesh& mesh, int t) {
    Eigen::AlignedBox3d box;
    box.setEmpty();
    for (int v : mesh.tet(t))
        box.extend(mesh.pos(v));
    return box;
}

} // namespace

Eigen::Array3i TetGrid::cellOf(const Vec3& p) const {
    const Eigen::Array3d c = ((p - m_origin) / m_cellSize).array().floor();
    // Clamp in double first: positions far outside the grid must not overflow int.
    const Eigen::Array3d clamped = c.max(0.0).min((m_dims - 1).cast<double>());
    return clamped.cast<int>();
}

template <class Visit>
void TetGrid::forCells(const Eigen::Array3i& lo, const Eigen::Array3i& hi, const Visit& visit) const {
    for (int z = lo.z(); z <= hi.z(); ++z)
        for (int y = lo.y(); y <= hi.y(); ++y)
            for (int x = lo.x(); x <= hi.x(); ++x)
                visit(Eigen::Array3i(x, y, z));
}

void TetGrid::build(const TetMesh& mesh, double cellSize) {
    m_extra.clear();
    m_insertLog.clear();
    m_openCheckpoints = 0;
    m_start.clear();
    m_items.clear();
    if (mesh.empty()) {
        m_cellSize = 0;
        return;
    }
    Eigen::AlignedBox3d all;
    all.setEmpty();
    double extent = 0;
    std::vector<Eigen::AlignedBox3d> boxes(mesh.tetCount());
    for (int t = 0; t < mesh.tetCount(); ++t) {
        boxes[t] = tetBox(mesh, t);
        all.extend(boxes[t]);
        extent += boxes[t].sizes().maxCoeff();
    }
    if (!(cellSize > 0))
        cellSize = 2.0 * extent / mesh.tetCount();
    // At most about four cells per tet (and never fewer than needed to cover the box).
    const Vec3 size = all.sizes().cwiseMax(1e-300);
    const double maxCells = 4.0 * mesh.tetCount() + 64;
    const double cells = (size / cellSize).array().ceil().max(1.0).prod();
    if (cells > maxCells)
        cellSize *= std::cbrt(cells / maxCells);
    m_cellSize = std::max(cellSize, 1e-300);
    m_origin = all.min();
    m_dims = (size / m_cellSize).array().floor().cast<int>().max(0) + 1;

    const std::int64_t cellCount = static_cast<std::int64_t>(m_dims.prod());
    m_start.assign(cellCount + 1, 0);
    std::vector<std::array<Eigen::Array3i, 2>> range(mesh.tetCount());
    for (int t = 0; t < mesh.tetCount(); ++t) {
        range[t] = {cellOf(boxes[t].min()), cellOf(boxes[t].max())};
        forCells(range[t][0], range[t][1], [&](const Eigen::Array3i& c) { ++m_start[cellIndex(c) + 1]; });
    }
    for (std::int64_t i = 0; i < cellCount; ++i)
        m_start[i + 1] += m_start[i];
    m_items.resize(m_start[cellCount]);
    std::vector<int> fill(m_start.begin(), m_start.end() - 1);
    for (int t = 0; t < mesh.tetCount(); ++t)
        forCells(range[t][0], range[t][1],
                 [&](const Eigen::Array3i& c) { m_items[fill[cellIndex(c)]++] = t; });
    m_stamp.assign(mesh.tetCount(), 0);
    m_epoch = 0;
    m_tetCount = mesh.tetCount();
}

void TetGrid::insert(const TetMesh& mesh, int tet) {
    if (empty())
        return;
    m_tetCount = std::max(m_tetCount, tet + 1);
    const Eigen::AlignedBox3d box = tetBox(mesh, tet);
    forCells(cellOf(box.min()), cellOf(box.max()), [&](const Eigen::Array3i& c) {
        const std::int64_t cell = cellIndex(c);
        m_extra[cell].push_back(tet);
        if (m_openCheckpoints > 0)
            m_insertLog.push_back(cell);
    });
}

void TetGrid::renumber(const TetMesh& mesh, const SparseRenumbering& tets, const std::vector<int>& created) {
    if (empty())
        return;
    m_tetCount = mesh.tetCount();
    for (const auto& [old, now] : tets.changed)
        if (now >= 0)
            insert(mesh, now);
    for (int t : created)
        insert(mesh, t);
}

TetGrid::Checkpoint TetGrid::checkpoint() {
    ++m_openCheckpoints;
    return {m_insertLog.size(), m_tetCount};
}

void TetGrid::rollback(const Checkpoint& checkpoint) {
    while (m_insertLog.size() > checkpoint.logSize) {
        const auto it = m_extra.find(m_insertLog.back());
        m_insertLog.pop_back();
        if (it == m_extra.end())
            continue;  // dropped by build()
        it->second.pop_back();
        if (it->second.empty())
            m_extra.erase(it);
    }
    if (m_openCheckpoints > 0)          // (build() since then dropped every checkpoint)
        m_tetCount = checkpoint.tetCount; // stale indices past it stay hidden
    release(checkpoint);
}

void TetGrid::release(const Checkpoint& checkpoint) {
    if (m_openCheckpoints > 0 && --m_openCheckpoints == 0)
        m_insertLog.clear();
}

void TetGrid::collect(std::int64_t cell, std::vector<int>& out) const {
    const auto take = [&](int t) {
        if (t >= m_tetCount)
            return;  // removed since it was registered
        if (t >= static_cast<int>(m_stamp.size()))
            m_stamp.resize(static_cast<std::size_t>(t) + 1 + m_stamp.size() / 2, 0);
        if (m_stamp[t] != m_epoch) {
            m_stamp[t] = m_epoch;
            out.push_back(t);
        }
    };
    for (int k = m_start[cell]; k < m_start[cell + 1]; ++k)
        take(m_items[k]);
    if (!m_extra.empty()) {
        auto it = m_extra.find(cell);
        if (it != m_extra.end())
            for (int t : it->second)
                take(t);
    }
}

void TetGrid::query(const Eigen::AlignedBox3d& box, std::vector<int>& out) const {
    out.clear();
    if (empty() || box.isEmpty())
        return;
    if (++m_epoch == 0) {
        std::fill(m_stamp.begin(), m_stamp.end(), 0);
        m_epoch = 1;
    }
    forCells(cellOf(box.min()), cellOf(box.max()),
             [&](const Eigen::Array3i& c) { collect(cellIndex(c), out); });
}

void TetGrid::queryTriangle(const Vec3& a, const Vec3& b, const Vec3& c, std::vector<int>& out) const {
    out.clear();
    if (empty())
        return;
    if (++m_epoch == 0) {
        std::fill(m_stamp.begin(), m_stamp.end(), 0);
        m_epoch = 1;
    }
    Eigen::AlignedBox3d box;
    box.setEmpty();
    box.extend(a);
    box.extend(b);
    box.extend(c);
    Vec3 n = (b - a).cross(c - a);
    const double len = n.norm();
    const bool flat = len > 0;
    if (flat)
        n /= len;
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * m_cellSize;
    forCells(cellOf(box.min()), cellOf(box.max()), [&](const Eigen::Array3i& cell) {
        if (flat) {
            const Vec3 centre = m_origin + (cell.cast<double>() + 0.5).matrix() * m_cellSize;
            if (std::abs(n.dot(centre - a)) > halfDiagonal)
                return;
        }
        collect(cellIndex(cell), out);
    });
}

} // namespace resect
