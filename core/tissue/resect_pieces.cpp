#include "core/tissue/resect_pieces.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace resect {

const char* resectedPiecesName(ResectedPieces policy) {
    switch (policy) {
    case ResectedPieces::Keep: return "keep";
    case ResectedPieces::Remove: return "remove";
    case ResectedPieces::Rigid: return "rigid";
    }
    return "?";
}

bool parseResectedPieces(const std::string& name, ResectedPieces& out) {
    if (name == "keep" || name == "deformable")
        out = ResectedPieces::Keep;
    else if (name == "remove")
        out = ResectedPieces::Remove;
    else if (name == "rigid")
        out = ResectedPieces::Rigid;
    else
        return false;
    return true;
}

Resection resectPieces(TetMesh& mesh, const Components& pieces, const Anchors& anchors, int cut,
                       std::vector<Chip>& chips) {
    Resection r;
    r.firstChip = static_cast<int>(chips.size());
    r.newNode.resize(mesh.nodeCount());
    r.newTet.resize(mesh.tetCount());
    r.pieceOfTet.assign(mesh.tetCount(), -1);
    for (int n = 0; n < mesh.nodeCount(); ++n)
        r.newNode[n] = n;
    for (int t = 0; t < mesh.tetCount(); ++t)
        r.newTet[t] = t;
    if (anchors.empty() || pieces.count <= 1)
        return r;
    std::vector<bool> anchored(pieces.count, false);
    for (int n : anchors.nodes())
        if (pieces.nodeComponent[n] >= 0)
            anchored[pieces.nodeComponent[n]] = true;
    std::vector<int> chipOf(pieces.count, -1);
    for (int c = 0; c < pieces.count; ++c)
        if (!anchored[c])
            chipOf[c] = r.chips++;
    if (r.chips == 0)
        return r;

    // Renumber the kept nodes and tets in order; gather each chip's.
    std::vector<std::vector<int>> chipNodes(r.chips), chipTets(r.chips);
    std::vector<int> indexInChip(mesh.nodeCount(), -1);
    int keptNodes = 0, keptTets = 0;
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const int c = pieces.nodeComponent[n];
        const int chip = c >= 0 ? chipOf[c] : -1;
        if (chip < 0) {
            r.newNode[n] = keptNodes++;
        } else {
            r.newNode[n] = -1;
            indexInChip[n] = static_cast<int>(chipNodes[chip].size());
            chipNodes[chip].push_back(n);
        }
    }
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const int chip = chipOf[pieces.tetComponent[t]];
        r.pieceOfTet[t] = chip;
        if (chip < 0) {
            r.newTet[t] = keptTets++;
        } else {
            r.newTet[t] = -1;
            chipTets[chip].push_back(t);
        }
    }
    // The chips.
    for (int chip = 0; chip < r.chips; ++chip) {
        std::vector<Vec3> ref;
        for (int n : chipNodes[chip])
            ref.push_back(mesh.ref(n));
        std::vector<Tet> tets;
        for (int t : chipTets[chip]) {
            Tet q = mesh.tet(t);
            for (int& v : q)
                v = indexInChip[v];
            tets.push_back(q);
        }
        Chip c;
        c.mesh = TetMesh::fromArrays(std::move(ref), std::move(tets));
        for (std::size_t i = 0; i < chipNodes[chip].size(); ++i) {
            const int n = chipNodes[chip][i];
            c.mesh.positions()[i] = mesh.pos(n);
            c.mesh.velocities()[i] = mesh.velocities()[n];
            c.mesh.masses()[i] = mesh.masses()[n];
            c.mass += mesh.masses()[n];
        }
        c.volume = c.mesh.totalReferenceVolume();
        c.cut = cut;
        r.volume += c.volume;
        r.mass += c.mass;
        chips.push_back(std::move(c));
    }
    // The tissue without them.
    std::vector<Vec3> ref, pos, vel;
    std::vector<double> mass;
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (r.newNode[n] >= 0) {
            ref.push_back(mesh.ref(n));
            pos.push_back(mesh.pos(n));
            vel.push_back(mesh.velocities()[n]);
            mass.push_back(mesh.masses()[n]);
        }
    std::vector<Tet> tets;
    for (int t = 0; t < mesh.tetCount(); ++t)
        if (r.newTet[t] >= 0) {
            Tet q = mesh.tet(t);
            for (int& v : q)
                v = r.newNode[v];
            tets.push_back(q);
        }
    TetMesh kept = TetMesh::fromArrays(std::move(ref), std::move(tets));
    std::copy(pos.begin(), pos.end(), kept.positions().begin());
    std::copy(vel.begin(), vel.end(), kept.velocities().begin());
    std::copy(mass.begin(), mass.end(), kept.masses().begin());
    mesh = std::move(kept);
    return r;
}

void makeRigidBody(Chip& chip) {
    RigidBody& b = chip.body;
    const TetMesh& m = chip.mesh;
    b.mass = 0;
    Vec3 centre = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    for (int n = 0; n < m.nodeCount(); ++n) {
        b.mass += m.masses()[n];
        centre += m.masses()[n] * m.pos(n);
        velocity += m.masses()[n] * m.velocities()[n];
    }
    if (!(b.mass > 0))
        return;
    b.centre = centre / b.mass;
    b.velocity = velocity / b.mass;
    b.orientation = Eigen::Quaterniond::Identity();
    b.angularVelocity = Vec3::Zero();
    // Inertia about the centre from the nodes' lumped masses (Eq. 3 masses are a quarter of
    // each tet's mass per node: a point-mass approximation of the chip).
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (int n = 0; n < m.nodeCount(); ++n) {
        const Vec3 r = m.pos(n) - b.centre;
        inertia += m.masses()[n] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    }
    // A chip whose nodes are (nearly) on a line has a (nearly) singular inertia: regularised.
    inertia += 1e-9 * std::max(inertia.trace(), 1e-30) * Eigen::Matrix3d::Identity();
    b.inertia = inertia;
    b.local.clear();
    for (int n = 0; n < m.nodeCount(); ++n)
        b.local.push_back(m.pos(n) - b.centre);
    chip.surfaceLocal.clear();
    for (const Vec3& p : chip.surface.positions)
        chip.surfaceLocal.push_back(p - b.centre);
}

void RestingSurface::build(std::span<const Tri> triangles, std::span<const Vec3> positions) {
    m_triangles.clear();
    double edges = 0;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Tri& t : triangles) {
        const std::array<Vec3, 3> p{positions[t[0]], positions[t[1]], positions[t[2]]};
        if (!((p[1] - p[0]).cross(p[2] - p[0]).z() > 0))
            continue; // only surfaces facing up carry a chip
        m_triangles.push_back(p);
        for (int k = 0; k < 3; ++k) {
            lo = lo.cwiseMin(p[k]);
            hi = hi.cwiseMax(p[k]);
            edges += (p[(k + 1) % 3] - p[k]).head<2>().norm();
        }
    }
    m_begin.clear();
    m_items.clear();
    if (m_triangles.empty())
        return;
    m_lo = lo;
    m_cell = std::max(edges / (3.0 * m_triangles.size()), 1e-9);
    m_nx = std::min(4096, static_cast<int>((hi.x() - lo.x()) / m_cell) + 1);
    m_ny = std::min(4096, static_cast<int>((hi.y() - lo.y()) / m_cell) + 1);
    m_cell = std::max({m_cell, (hi.x() - lo.x()) / m_nx, (hi.y() - lo.y()) / m_ny}) * (1 + 1e-9);
    const auto range = [&](const std::array<Vec3, 3>& p, int& x0, int& x1, int& y0, int& y1) {
        const double ax = std::min({p[0].x(), p[1].x(), p[2].x()}), bx = std::max({p[0].x(), p[1].x(), p[2].x()});
        const double ay = std::min({p[0].y(), p[1].y(), p[2].y()}), by = std::max({p[0].y(), p[1].y(), p[2].y()});
        x0 = std::clamp(static_cast<int>((ax - m_lo.x()) / m_cell), 0, m_nx - 1);
        x1 = std::clamp(static_cast<int>((bx - m_lo.x()) / m_cell), 0, m_nx - 1);
        y0 = std::clamp(static_cast<int>((ay - m_lo.y()) / m_cell), 0, m_ny - 1);
        y1 = std::clamp(static_cast<int>((by - m_lo.y()) / m_cell), 0, m_ny - 1);
    };
    m_begin.assign(static_cast<std::size_t>(m_nx) * m_ny + 1, 0);
    for (const auto& p : m_triangles) {
        int x0, x1, y0, y1;
        range(p, x0, x1, y0, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                ++m_begin[static_cast<std::size_t>(y) * m_nx + x + 1];
    }
    for (std::size_t c = 1; c < m_begin.size(); ++c)
        m_begin[c] += m_begin[c - 1];
    m_items.resize(m_begin.back());
    std::vector<int> fill(m_begin.begin(), m_begin.end() - 1);
    for (int i = 0; i < static_cast<int>(m_triangles.size()); ++i) {
        int x0, x1, y0, y1;
        range(m_triangles[i], x0, x1, y0, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                m_items[fill[static_cast<std::size_t>(y) * m_nx + x]++] = i;
    }
}

double RestingSurface::heightBelow(double x, double y, double z) const {
    double best = -std::numeric_limits<double>::infinity();
    if (m_triangles.empty())
        return best;
    const int cx = static_cast<int>(std::floor((x - m_lo.x()) / m_cell));
    const int cy = static_cast<int>(std::floor((y - m_lo.y()) / m_cell));
    if (cx < 0 || cy < 0 || cx >= m_nx || cy >= m_ny)
        return best;
    const std::size_t c = static_cast<std::size_t>(cy) * m_nx + cx;
    for (int k = m_begin[c]; k < m_begin[c + 1]; ++k) {
        const auto& p = m_triangles[m_items[k]];
        // Barycentric coordinates of (x, y) in the triangle's projection (counter-clockwise:
        // it faces up).
        const double d = (p[1].x() - p[0].x()) * (p[2].y() - p[0].y()) - (p[2].x() - p[0].x()) * (p[1].y() - p[0].y());
        if (!(d > 0))
            continue;
        const double b1 = ((x - p[0].x()) * (p[2].y() - p[0].y()) - (p[2].x() - p[0].x()) * (y - p[0].y())) / d;
        const double b2 = ((p[1].x() - p[0].x()) * (y - p[0].y()) - (x - p[0].x()) * (p[1].y() - p[0].y())) / d;
        if (b1 < 0 || b2 < 0 || b1 + b2 > 1)
            continue;  // (edges included: a chip's node on a vertex of the cut stays on it)
        const double h = p[0].z() + b1 * (p[1].z() - p[0].z()) + b2 * (p[2].z() - p[0].z());
        if (h <= z && h > best)
            best = h;
    }
    return best;
}

void stepChips(std::vector<Chip>& chips, double h, const Vec3& gravity, double floor, const RestingSurface* tissue) {
    constexpr double kFriction = 0.5;  ///< tangential velocity kept per contact step
    for (Chip& chip : chips) {
        RigidBody& b = chip.body;
        if (!(b.mass > 0) || b.resting)
            continue;
        const Eigen::Matrix3d before = b.orientation.toRotationMatrix();
        const Vec3 centreBefore = b.centre;
        b.velocity += h * gravity;
        b.centre += h * b.velocity;
        const double w = b.angularVelocity.norm();
        if (w > 0)
            b.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(h * w, b.angularVelocity / w)) * b.orientation;
        b.orientation.normalize();
        // Contact with the support (the floor, or the tissue's surface under where the node
        // was before the step): the deepest node is put back on it and the body stops falling.
        const Eigen::Matrix3d R = b.orientation.toRotationMatrix();
        double lift = 0;
        bool onTissue = false;  // the deepest contact is with the tissue, not the floor
        for (const Vec3& q : b.local) {
            const Vec3 p = b.centre + R * q;
            double support = floor;
            bool tissueHere = false;
            if (tissue) {
                const Vec3 was = centreBefore + before * q;
                const double top = tissue->heightBelow(p.x(), p.y(), std::max(was.z(), p.z()));
                tissueHere = top > floor;
                support = std::max(support, top);
            }
            if (support - p.z() > lift) {
                lift = support - p.z();
                onTissue = tissueHere;
            }
        }
        if (lift > 0) {
            b.centre.z() += lift;
            if (b.velocity.z() < 0)
                b.velocity.z() = 0;
            b.velocity.x() *= kFriction;
            b.velocity.y() *= kFriction;
            b.angularVelocity *= kFriction;
            // At rest on the floor it stays; on the tissue it keeps following the surface.
            if (!onTissue && b.velocity.norm() < 1e-9 * std::max(1.0, gravity.norm()))
                b.resting = true;
        }
        for (int n = 0; n < chip.mesh.nodeCount(); ++n) {
            chip.mesh.positions()[n] = b.centre + R * b.local[n];
            chip.mesh.velocities()[n] = b.velocity + b.angularVelocity.cross(R * b.local[n]);
        }
        for (std::size_t v = 0; v < chip.surface.positions.size(); ++v)
            chip.surface.positions[v] = b.centre + R * chip.surfaceLocal[v];
    }
}

} // namespace resect
