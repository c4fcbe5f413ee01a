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

void stepChips(std::vector<Chip>& chips, double h, const Vec3& gravity, double floor) {
    constexpr double kFriction = 0.5;  ///< tangential velocity kept per contact step
    for (Chip& chip : chips) {
        RigidBody& b = chip.body;
        if (!(b.mass > 0) || b.resting)
            continue;
        b.velocity += h * gravity;
        b.centre += h * b.velocity;
        const double w = b.angularVelocity.norm();
        if (w > 0)
            b.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(h * w, b.angularVelocity / w)) * b.orientation;
        b.orientation.normalize();
        // Contact with the floor: the lowest node is put back on it and the body stops falling.
        const Eigen::Matrix3d R = b.orientation.toRotationMatrix();
        double lowest = std::numeric_limits<double>::infinity();
        for (const Vec3& p : b.local)
            lowest = std::min(lowest, (b.centre + R * p).z());
        if (lowest < floor) {
            b.centre.z() += floor - lowest;
            if (b.velocity.z() < 0)
                b.velocity.z() = 0;
            b.velocity.x() *= kFriction;
            b.velocity.y() *= kFriction;
            b.angularVelocity *= kFriction;
            if (b.velocity.norm() < 1e-9 * std::max(1.0, gravity.norm()))
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
