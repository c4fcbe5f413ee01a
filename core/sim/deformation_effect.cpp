#include "core/sim/deformation_effect.h"

#include "core/mesh/stable_time_step.h"
#include "core/sim/parallel.h"

#include <algorithm>

namespace resect {
namespace {

std::vector<std::int64_t> splits(std::int64_t count, int threads) {
    std::vector<std::int64_t> s(static_cast<std::size_t>(threads) + 1);
    for (int t = 0; t <= threads; ++t)
        s[t] = chunkBegin(count, threads, t);
    return s;
}

} // namespace

DeformationEffect::DeformationEffect(const TetMesh& mesh, const Material& material,
                                     const DeformationOptions& options)
    : m_mesh(mesh), m_material(material), m_model(mesh, material, options.terms), m_threads(1) {
    const auto& terms = m_model.terms();
    const std::int64_t work = static_cast<std::int64_t>(m_model.edges().size()) +
                              static_cast<std::int64_t>(m_model.tetRestVolume6().size()) +
                              static_cast<std::int64_t>(m_model.triangles().size());
    m_threads = threadsFor(resolveThreadCount(options.threads), work, options.grain);
    m_edgeSplit = splits(static_cast<std::int64_t>(m_model.edges().size()), m_threads);
    m_tetSplit = splits(terms.volume ? mesh.tetCount() : 0, m_threads);
    m_triSplit = splits(static_cast<std::int64_t>(m_model.triangles().size()), m_threads);
    m_windows.resize(m_threads);
    for (int t = 1; t < m_threads; ++t) {
        const Chunk c = chunk(t);
        for (auto s = c.edges.begin; s < c.edges.end; ++s)
            for (int v : m_model.edges()[s])
                extendWindow(t, v);
        for (auto s = c.tets.begin; s < c.tets.end; ++s)
            for (int v : mesh.tet(static_cast<int>(s)))
                extendWindow(t, v);
        for (auto s = c.triangles.begin; s < c.triangles.end; ++s)
            for (int v : m_model.triangles()[s])
                extendWindow(t, v);
    }
}

DeformationEffect::Chunk DeformationEffect::chunk(int t) const {
    const bool last = t == m_threads - 1;
    const auto range = [&](const std::vector<std::int64_t>& split, std::int64_t size) {
        return Range{split[t], last ? size : split[t + 1]};
    };
    Chunk c;
    c.edges = range(m_edgeSplit, static_cast<std::int64_t>(m_model.edges().size()));
    c.tets = range(m_tetSplit, static_cast<std::int64_t>(m_model.tetRestVolume6().size()));
    c.triangles = range(m_triSplit, static_cast<std::int64_t>(m_model.triangles().size()));
    return c;
}

int DeformationEffect::chunkOf(std::int64_t slot, const std::vector<std::int64_t>& split) const {
    int t = 0;
    while (t + 1 < m_threads && split[t + 1] <= slot)
        ++t;
    return t;
}

void DeformationEffect::extendWindow(int t, int node) {
    Window& w = m_windows[t];
    if (w.lo == w.hi) {
        w.lo = node;
        w.hi = node + 1;
    } else {
        w.lo = std::min(w.lo, node);
        w.hi = std::max(w.hi, node + 1);
    }
}

template <class Kernel> double DeformationEffect::run(std::span<Vec3> out, Kernel&& kernel) {
    if (m_threads == 1)
        return kernel(ForceWindow{out, 0}, chunk(0));
    std::vector<double> partial(static_cast<std::size_t>(m_threads), 0.0);
    const auto nodes = static_cast<std::int64_t>(out.size());
    parallelRun(m_threads, [&](int t) {
        ForceWindow w{out, 0};
        if (t > 0) {
            Window& own = m_windows[t];
            own.buffer.resize(static_cast<std::size_t>(own.hi - own.lo));
            std::fill(own.buffer.begin(), own.buffer.end(), Vec3::Zero());
            w = ForceWindow{own.buffer, own.lo};
        }
        partial[t] = kernel(w, chunk(t));
    });
    // Then chunk t of the nodes adds the windows of threads 1.. into the output, in order.
    parallelRun(m_threads, [&](int t) {
        const std::int64_t begin = chunkBegin(nodes, m_threads, t);
        const std::int64_t end = chunkBegin(nodes, m_threads, t + 1);
        for (int u = 1; u < m_threads; ++u) {
            const Window& other = m_windows[u];
            const std::int64_t lo = std::max<std::int64_t>(begin, other.lo);
            const std::int64_t hi = std::min<std::int64_t>(end, other.hi);
            for (std::int64_t i = lo; i < hi; ++i)
                out[i] += other.buffer[i - other.lo];
        }
    });
    double sum = 0;
    for (double p : partial)
        sum += p;
    return sum;
}

double DeformationEffect::addForces(const SimState& s, std::span<Vec3> f) {
    const auto tets = std::span<const Tet>(m_mesh.tets());
    return run(f, [&](ForceWindow w, const Chunk& c) {
        double e = 0;
        const auto& m = m_model;
        if (c.edges.end > c.edges.begin) {
            const auto n = static_cast<std::size_t>(c.edges.end - c.edges.begin);
            e += addEdgeForces(m.edges().subspan(c.edges.begin, n),
                               m.edgeRestLength().subspan(c.edges.begin, n),
                               m.edgeStiffness().subspan(c.edges.begin, n), s.x, w);
        }
        if (c.tets.end > c.tets.begin) {
            const auto n = static_cast<std::size_t>(c.tets.end - c.tets.begin);
            e += addVolumeForces(tets.subspan(c.tets.begin, n),
                                 m.tetRestVolume6().subspan(c.tets.begin, n),
                                 m.tetStiffness36().subspan(c.tets.begin, n), s.x, w);
        }
        if (c.triangles.end > c.triangles.begin) {
            const auto n = static_cast<std::size_t>(c.triangles.end - c.triangles.begin);
            e += addAreaForces(m.triangles().subspan(c.triangles.begin, n),
                               m.triangleRestArea().subspan(c.triangles.begin, n),
                               m.triangleStiffness().subspan(c.triangles.begin, n), s.x, w);
        }
        return e;
    });
}

void DeformationEffect::addForceDifferential(const SimState& s, std::span<const Vec3> dx,
                                             std::span<Vec3> df) {
    const auto tets = std::span<const Tet>(m_mesh.tets());
    run(df, [&](ForceWindow w, const Chunk& c) {
        const auto& m = m_model;
        if (c.edges.end > c.edges.begin) {
            const auto n = static_cast<std::size_t>(c.edges.end - c.edges.begin);
            addEdgeForceDifferential(m.edges().subspan(c.edges.begin, n),
                                     m.edgeRestLength().subspan(c.edges.begin, n),
                                     m.edgeStiffness().subspan(c.edges.begin, n), s.x, dx, w);
        }
        if (c.tets.end > c.tets.begin) {
            const auto n = static_cast<std::size_t>(c.tets.end - c.tets.begin);
            addVolumeForceDifferential(tets.subspan(c.tets.begin, n),
                                       m.tetStiffness36().subspan(c.tets.begin, n), s.x, dx, w);
        }
        if (c.triangles.end > c.triangles.begin) {
            const auto n = static_cast<std::size_t>(c.triangles.end - c.triangles.begin);
            addAreaForceDifferential(m.triangles().subspan(c.triangles.begin, n),
                                     m.triangleStiffness().subspan(c.triangles.begin, n), s.x, dx,
                                     w);
        }
        return 0.0;
    });
}

void DeformationEffect::addSystemDiagonal(const SimState& s, double h, std::span<Vec3> diag) {
    // diag of -h^2 df/dx = h^2 (diagonal of the stiffness); accumulate, then scale once.
    std::vector<Vec3> k(diag.size(), Vec3::Zero());
    const auto tets = std::span<const Tet>(m_mesh.tets());
    run(k, [&](ForceWindow w, const Chunk& c) {
        const auto& m = m_model;
        if (c.edges.end > c.edges.begin) {
            const auto n = static_cast<std::size_t>(c.edges.end - c.edges.begin);
            addEdgeStiffnessDiagonal(m.edges().subspan(c.edges.begin, n),
                                     m.edgeRestLength().subspan(c.edges.begin, n),
                                     m.edgeStiffness().subspan(c.edges.begin, n), s.x, w);
        }
        if (c.tets.end > c.tets.begin) {
            const auto n = static_cast<std::size_t>(c.tets.end - c.tets.begin);
            addVolumeStiffnessDiagonal(tets.subspan(c.tets.begin, n),
                                       m.tetStiffness36().subspan(c.tets.begin, n), s.x, w);
        }
        if (c.triangles.end > c.triangles.begin) {
            const auto n = static_cast<std::size_t>(c.triangles.end - c.triangles.begin);
            addAreaStiffnessDiagonal(m.triangles().subspan(c.triangles.begin, n),
                                     m.triangleStiffness().subspan(c.triangles.begin, n), s.x, w);
        }
        return 0.0;
    });
    for (std::size_t i = 0; i < diag.size(); ++i)
        diag[i] += h * h * k[i];
}

double DeformationEffect::energy(std::span<const Vec3> x) {
    std::vector<Vec3> f(x.size(), Vec3::Zero());
    std::vector<Vec3> copy(x.begin(), x.end());
    SimState s;
    s.x = copy;
    return addForces(s, f);
}

double DeformationEffect::stableTimeStep(const TetMesh& mesh) {
    if (!(m_stableDt > 0)) {
        StableTimeStepOptions options;
        options.areaTerm = m_model.terms().area;
        m_stableDt = resect::stableTimeStep(mesh, m_material, options).dt;
    }
    return m_stableDt;
}

void DeformationEffect::applyCut(const TetMesh& mesh, const CutChanges& changes) {
    const DeformationChanges changed = m_model.applyCut(mesh, changes);
    for (int s : changed.edgeSlots)
        if (const int t = chunkOf(s, m_edgeSplit); t > 0)
            for (int v : m_model.edges()[s])
                extendWindow(t, v);
    for (int s : changed.tets)
        if (const int t = chunkOf(s, m_tetSplit); t > 0)
            for (int v : mesh.tet(s))
                extendWindow(t, v);
    for (int s : changed.triangleSlots)
        if (const int t = chunkOf(s, m_triSplit); t > 0)
            for (int v : m_model.triangles()[s])
                extendWindow(t, v);
    m_stableDt = 0;
}

} // namespace resect
