#pragma once
// The `deformation` effect: the internal forces of the tissue model (forces.h) over the terms
// of a DeformationModel, run on several threads.
//
// Threading: each term array (edges, tets, triangles) is split into one contiguous chunk per
// thread when the effect is built. Thread 0 adds its chunks' forces straight into the
// output; every other thread accumulates into a private window covering the node range its
// terms touch (for a mesh numbered with locality, as box meshes and sorted edges are, the
// windows barely overlap), then the windows are added to the output in thread order. So there
// are no scatter races, no atomics, and the result is bit-identical for a given thread count
// (different thread counts sum in a different order, which changes rounding only).
// Terms a cut adds go to the last chunk, whose window grows to cover them.

#include "core/mesh/material.h"
#include "core/sim/deformation_model.h"
#include "core/sim/effect.h"

#include <cstdint>
#include <memory>

namespace resect {

struct DeformationOptions {
    DeformationTerms terms;
    int threads = 0;  ///< 0: resolveThreadCount's default
    int grain = 4096; ///< fewer threads if one would get fewer terms (threadsFor)
};

class DeformationEffect : public Effect {
public:
    /// Keeps a reference to the mesh (for its tets); builds the model (O(mesh)).
    DeformationEffect(const TetMesh& mesh, const Material& material,
                      const DeformationOptions& options = {});

    std::string name() const override { return "deformation"; }
    double addForces(const SimState& s, std::span<Vec3> f) override;
    void addForceDifferential(const SimState& s, std::span<const Vec3> dx,
                              std::span<Vec3> df) override;
    void addSystemDiagonal(const SimState& s, double h, std::span<Vec3> diag) override;
    /// stableTimeStep (stable_time_step.h) of this model, with the area term if enabled;
    /// computed once and again only after a cut.
    double stableTimeStep(const TetMesh& mesh) override;
    void applyCut(const TetMesh& mesh, const CutChanges& changes) override;

    /// Potential energy of the model at positions x (no forces written).
    double energy(std::span<const Vec3> x);
    const DeformationModel& model() const { return m_model; }
    int threads() const { return m_threads; }

private:
    struct Range {
        std::int64_t begin = 0, end = 0;
    };
    struct Chunk {
        Range edges, tets, triangles;
    };
    /// Node window [lo, hi) of thread t >= 1 and its private buffer.
    struct Window {
        int lo = 0, hi = 0;
        std::vector<Vec3> buffer;
    };
    Chunk chunk(int t) const;
    int chunkOf(std::int64_t slot, const std::vector<std::int64_t>& splits) const;
    void extendWindow(int t, int node);
    /// Runs kernel(window, chunk) on every thread and reduces into out; returns the summed
    /// results of kernel in thread order.
    template <class Kernel> double run(std::span<Vec3> out, Kernel&& kernel);

    const TetMesh& m_mesh;
    Material m_material;
    DeformationModel m_model;
    int m_threads = 1;
    std::vector<std::int64_t> m_edgeSplit, m_tetSplit, m_triSplit; ///< #threads + 1
    std::vector<Window> m_windows;                                 ///< #threads (0 unused)
    double m_stableDt = 0;                                         ///< 0: not computed yet or stale
};

} // namespace resect
