#pragma once
// Tissue: the one owner of a tissue's state and of applying a cut to it (STYLE.md 13).
//
// A tissue is the coarse tet mesh that is cut and simulated, its spatial index and the unit of
// the threshold d (HybridCutter), the embedded high-resolution surface and its binding
// (section 5), the anchored nodes (the scene's fixed regions), the Figure-4 scheme that
// produced every tet, its pieces, and, when one runs, the simulator with the scene's effects.
// The CLI, replay, the accuracy study, the benchmarks and the studio all cut through cut();
// none of them sequences the steps itself.
//
// cut() applies one sweep, in this order:
//   1. the spatial index is rebuilt if the tets moved since it was built (simulation steps),
//      and the surface follows the tets' current positions (EmbeddedSurface::update);
//   2. the tets are cut (HybridCutter: section 4.1's steps, masses by Eq. 3);
//   3. the embedded surface is cut and closed (section 5.1, 5.2) and its vertices re-bound;
//   4. the simulator's effects follow the change list locally (Simulator::applyCut);
//   5. anchors, schemes, pieces and the cut marks (onCutSurface, tetCuts) follow;
//   6. pieces that no longer touch an anchored node are resected (resect_pieces.h) when the
//      tissue's ResectedPieces says so: they leave the tet mesh and its surface and become
//      chips (removed, or rigid bodies that fall); the simulation is rebuilt on what remains;
//   7. the tets around the cut are improved (CutOptions::improve, core/cut/improve_mesh.h):
//      bad tets and short edges, measured against the tissue as created, are smoothed away or
//      collapsed; the surface is re-bound around them and the simulation follows (locally, or
//      rebuilt when tets were removed).
// Every stage that can fail (2 and 3) runs before the ones that cannot be undone, under a
// backup of the mesh and the spatial index: on failure or cancellation the tissue is exactly
// as it was (the mesh bit-identical, node adjacency order included; the surface, its binding,
// the simulator, anchors and schemes untouched). Cost: in proportion to what the cut touches
// (pieces are counted on demand).

#include "core/cut/hybrid_cutter.h"
#include "core/embed/embedded_surface.h"
#include "core/mesh/body_surface.h"
#include "core/mesh/material.h"
#include "core/mesh/topology.h"
#include "core/sim/anchors.h"
#include "core/sim/simulator.h"
#include "core/status.h"
#include "core/tissue/resect_pieces.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace resect {

struct ImproveResult;

/// What one Tissue::cut did.
struct TissueCut {
    CutStats tets;           ///< the tet cut's counts and stage times (HybridCutter)
    EmbeddedCut surface;     ///< the surface cut's counts and stage times (zeros without one)
    double surfaceMs = 0;    ///< surface update, cut and re-binding together
    double simulationMs = 0; ///< the simulator's effects following the change list
    double resectionMs = 0;  ///< removing resected pieces (0 if none)
    double improveMs = 0;    ///< the improvement step (0 if off)
    int collapsedEdges = 0;  ///< edges the improvement collapsed
    int smoothedNodes = 0;   ///< nodes it moved to raise their worst tet
    int removedTets = 0;     ///< tets the collapses removed, and flips that made fewer than they replaced
    int flips = 0;           ///< 2-3 flips and edge removals the improvement made
    int splits = 0;          ///< edges it split (nodes added)
    /// Tets its flips (2-3, and edge removals of 5 or more tets) and splits added: the tissue's
    /// tets and this cut's chips' together number those before plus tets.addedTets +
    /// improveAddedTets - removedTets.
    int improveAddedTets = 0;
    /// The running simulation was rebuilt (tets were resected or renumbered): pointers to it
    /// or its effects taken before the cut are stale.
    bool simulationRebuilt = false;
    double totalMs = 0;      ///< the whole cut, every stage
    int resectedPieces = 0;  ///< pieces this cut resected (they are chips now)
    double resectedVolume = 0, resectedMass = 0;  ///< their reference volume (mm^3) and mass (g)
    CutChanges changes;      ///< what changed (for views and other followers)
};

/// What a simulation of the tissue runs: the integrator and step, the effects by name (in
/// order, EffectRegistry) and their parameters. The `fixed` effect holds the tissue's anchors:
/// settings.fixed must be left empty.
struct SimulationSetup {
    SimulatorOptions options;
    std::vector<std::string> effects;
    EffectSettings settings;
};

class Tissue {
public:
    Tissue();
    ~Tissue();
    Tissue(Tissue&&) noexcept;
    Tissue& operator=(Tissue&&) noexcept;
    /// A deep copy of everything but the simulation (a copy has none): the copy cuts exactly
    /// as the original would (same spatial index, same unit of d).
    explicit Tissue(const Tissue& other);
    Tissue& operator=(const Tissue&) = delete;

    /// A tissue from a tet mesh (masses by Eq. 3 from material.density if every mass is
    /// zero), the embedded surface (may be empty; positions in the mesh's current
    /// configuration) and the anchored nodes (may be empty). Errors name what is wrong; `out`
    /// is unchanged then.
    static Status create(TetMesh mesh, TriangleSurface surface, const Material& material,
                         const FixedSelection& anchors, Tissue& out);

    bool empty() const { return !m_mesh || m_mesh->empty(); }
    const TetMesh& mesh() const { return *m_mesh; }
    /// The spatial index cuts find their tets in (current positions; up to date after a cut,
    /// and rebuilt before the next one where the simulation moved the tets).
    const TetGrid& spatialIndex() const { return m_cutter->grid(); }
    /// The embedded surface; its positions are those of the last updateSurface() (or cut).
    const EmbeddedSurface& surface() const { return m_surface; }
    const Material& material() const { return m_material; }
    const Anchors& anchors() const { return m_anchors; }
    /// Per tet: the scheme (Figure 4) of the cut that produced it; None for tets of the input.
    const std::vector<Scheme>& schemes() const { return m_schemes; }
    /// Per node: 1 if the node lies on a surface a cut made (CutChanges::cutSurfaceNodes of
    /// every cut so far: cut nodes, split points and their copies), else 0. A boundary face
    /// whose three nodes are marked is a cut face (what the views draw as the cut).
    const std::vector<std::uint8_t>& onCutSurface() const { return m_onCut; }
    /// Per tet: the cut (counted from 1) that last produced or changed it (CutChanges: its
    /// new tets and modified tets), 0 for tets untouched since create(). The last cut's
    /// touched tets are those equal to cutCount().
    const std::vector<int>& tetCuts() const { return m_tetCuts; }
    /// Connected components of the tets (computed on the first call after a cut; safe to call
    /// from several threads on a shared const tissue).
    const Components& pieces() const;
    /// The unit of d: the mean edge length of the tissue as created.
    double meanEdgeLength() const { return m_cutter->meanEdgeLength(); }
    /// Cuts applied since create().
    int cutCount() const { return m_cuts; }
    /// The smallest radius ratio and the shortest edge (reference) of the tissue as created:
    /// the yardsticks of the improvement step.
    double inputWorstRatio() const { return m_inputWorstRatio; }
    double inputShortestEdge() const { return m_inputShortestEdge; }

    /// Replaces the anchored nodes of a tissue that has not been cut and does not simulate (the
    /// scene's fixed regions were edited): the tissue is then exactly what create() makes with
    /// `anchors`. Errors (the tissue unchanged): a cut or simulated tissue, or what
    /// Anchors::create refuses.
    Status setAnchors(const FixedSelection& anchors);

    /// What happens to pieces that no longer touch an anchored node after a cut (Keep by
    /// default; nothing is resected without anchors).
    void setResectedPieces(ResectedPieces policy) { m_resected = policy; }
    ResectedPieces resectedPieces() const { return m_resected; }
    /// The pieces resected so far, in order.
    const std::vector<Chip>& chips() const { return m_chips; }
    /// Reference volume (mm^3) and mass (g) resected so far: with the tissue's, the original's.
    double resectedVolume() const { return m_resectedVolume; }
    double resectedMass() const { return m_resectedMass; }

    /// Applies one sweep to the tissue (see the top of this file). `out` (optional) receives
    /// counts, stage times and the change list; `proceed` is asked before each stage and may
    /// cancel. CutOptions::density is replaced by the material's density.
    Status cut(const SweepSurface& sweep, const CutOptions& options, TissueCut* out = nullptr,
               const CutStageCallback& proceed = {});

    /// Starts a simulation of the tissue (replacing any running one). Errors name the effect.
    Status startSimulation(const SimulationSetup& setup);
    void stopSimulation();
    bool isSimulating() const { return m_sim != nullptr; }
    /// The running simulation, or null. Steps taken through it are noticed by the next cut
    /// (which then rebuilds the spatial index) and by updateSurface().
    Simulator* simulator() { return m_sim.get(); }
    const Simulator* simulator() const { return m_sim.get(); }
    /// One simulation step of h seconds (Simulator::step); rigid chips fall with it (resting on
    /// the plane of the tissue's lowest point as created).
    Status step(double h);

    /// Moves the embedded surface with the tets (call before drawing or saving it).
    void updateSurface();

    /// Gives the mesh away (the tissue is empty afterwards): for callers that continue with
    /// the mesh alone (e.g. a study that perturbs and simulates it).
    TetMesh takeMesh() &&;

private:
    /// Steps the simulator has taken when the index and the surface last followed the tets.
    /// Notes simulation steps taken since the last look (the index and surface are then stale).
    void noticeSteps();
    /// Step 1 of cut(): rebuilds the spatial index and updates the surface where stale.
    void followPositions();
    /// Step 5 of cut(): the scheme of every tet the cut produced or changed.
    void updateSchemes(const CutChanges& changes);
    /// Step 5 of cut(): the cut marks (onCutSurface, tetCuts) of what cut number `cut` made.
    void markCut(const CutChanges& changes, int cut);
    /// Step 6 of cut(): resected pieces leave the tissue; fills the result's counts. `seeds`
    /// (nodes) are renumbered, the ones resected dropped; `rebuild` is set if the simulation
    /// must be rebuilt.
    void resect(TissueCut& result, std::vector<int>& seeds, bool& rebuild);
    /// Step 7 of cut(): one improvement pass around `seeds`. Returns the nodes of the tets it
    /// left below its bound (empty if there are none or it changed nothing), for another.
    /// `tetsBeforeCut`: the tissue's tets before the cut (for the tet budget).
    std::vector<int> improve(TissueCut& result, const std::vector<int>& seeds, const CutOptions& options, int tetsBeforeCut,
                             bool& rebuild);
    /// Anchors, schemes, cut marks, the spatial index and the pieces follow a renumbering of
    /// the tets and nodes (old -> new, -1: gone).
    void renumber(const std::vector<int>& newTet, const std::vector<int>& newNode);
    /// The same after the improvement step's local remeshing, in proportion to what it changed
    /// (ImproveResult::renumbering), not to the mesh.
    void renumberLocally(const ImproveResult& r);
    /// Rebuilds the running simulation on the tissue as it is, its clock going on.
    void rebuildSimulation();

    std::unique_ptr<TetMesh> m_mesh;        // on the heap: the cutter and simulator refer to it
    std::unique_ptr<HybridCutter> m_cutter;
    EmbeddedSurface m_surface;
    Material m_material;
    Anchors m_anchors;
    std::vector<Scheme> m_schemes;
    std::vector<std::uint8_t> m_onCut; ///< per node, onCutSurface()
    std::vector<int> m_tetCuts;        ///< per tet, tetCuts()
    int m_cuts = 0;
    std::unique_ptr<Simulator> m_sim;
    SimulationSetup m_setup;    ///< of the running simulation (rebuilt after a resection)
    ResectedPieces m_resected = ResectedPieces::Keep;
    std::vector<Chip> m_chips;
    double m_resectedVolume = 0, m_resectedMass = 0;
    double m_floor = 0;         ///< z of the tissue's lowest node as created: where chips come to rest
    /// What rigid chips land on: the tissue's boundary triangles (found again after every cut:
    /// m_restingCut is the cut count they were found at, -1 none) at their current positions.
    std::vector<Tri> m_restingTris;
    int m_restingCut = -1;
    RestingSurface m_resting;
    double m_inputWorstRatio = 0, m_inputShortestEdge = 0;  ///< of the tissue as created
    int m_inputTets = 0;  ///< tets of the tissue as created
    /// The body's surface as created (the improvement keeps every node in the body and the
    /// nodes of the body's surface on it); shared by copies: it never changes.
    std::shared_ptr<const BodySurface> m_body;
    /// Every cut's sweep, so that the improvement keeps cracks where their cuts made them
    /// (ImproveOptions::cutDistance); shared by copies: a sweep never changes.
    std::vector<std::shared_ptr<const SweepSurface>> m_sweeps;
    int m_stepsSeen = 0;        ///< simulator steps when the tissue last looked
    bool m_indexStale = false;  ///< the tets moved since the spatial index was built
    bool m_surfaceStale = true; ///< the tets moved since the surface last followed them

    struct PiecesCache {
        std::mutex mutex;
        std::optional<Components> components;
    };
    std::unique_ptr<PiecesCache> m_pieces;
};

} // namespace resect
