#pragma once
// The scenario document (issue 7): what a curriculum designer authors and the trainer
// receives. A value type mirroring the JSON file one to one; reading and validation are in
// scenario_load.h, writing in scenario_save.h, the strokes as sweep surfaces in
// scenario_sweeps.h, the older layout in scenario_migrate.h.
//
// Units as everywhere in Resect Studio: mm, g, s.
//
// File layout (version 1; every section but "format", "version" and "tissues" is optional
// and takes the defaults below; saving writes every field):
//
//   {"format": "resect-scenario", "version": 1,
//    "metadata": {"title": "...", "author": "...", "description": "...",
//                 "learning_objectives": ["...", ...], "difficulty": 2},
//    "tissues": [{"name": "polyp",
//                 "surface": "sample:polyp",              (or a path, see below; may be
//                                                          left out with "mesh": the tet
//                                                          mesh alone, no embedded surface)
//                 "mesh": "polyp.vtu",                    (either "mesh" ...
//                 "meshing": {"edge_length": 0, "seed": 0},  ... or "meshing")
//                 "material": {"density": 0.001, "stiffness": 1e6, "damping": 0},
//                 "fixed_regions": [{"min": [x, y, z], "max": [x, y, z]}]}],
//    "tool": {"name": "loop electrode", "size": 4,
//             "curve": [[x, y, z], ...]},                 (n + 1 >= 2 points, tool frame)
//    "strokes": [{"name": "...", "poses": [{"t": 0, "position": [x, y, z],
//                                          "orientation": [w, x, y, z]}, ...]}],
//    "sweeps": [{"name": "...", "curves": [[[x, y, z], ...], ...]},    (inline, as in a
//               {"name": "...", "file": "cut.json"}],                   sweep file, or a file)
//    "cut_settings": {"method": "hybrid", "triangulation": "enhanced", "d": 0.2,
//                     "snap": true, "relax_steps": 10, "w_spring": 1, "w_particle": 0.2,
//                     "damping": 10, "rings": 2, "improve": true, "improve_quality": 1,
//                     "improve_short_edge": 0.6, "improve_coarsen": 0.5},
//    "effects": [{"name": "gravity", "parameters": {"acceleration": [0, 0, -9810]}}, ...],
//    "simulation": {"integrator": "implicit", "time_step": 0.001, "duration": 0.5},
//    "expectations": [{"kind": "pieces_at_least", "value": 2}, ...]}
//
// Paths ("surface", "mesh", a sweep's "file") are relative to the scenario file's folder
// (absolute paths are allowed and kept as they are); "sample:polyp" and "sample:myoma" name
// the built-in anatomy (core/mesher/samples.h). Scenario::baseDir is the folder relative
// paths are resolved against; it is not part of the file.
//
// Unknown fields, anywhere, are kept in the `extra` object of the struct for the JSON object
// they were found in, reported as warnings on load and written back on save.
//
// Field meanings and ranges (checked by validation, scenario_load.h):
//  metadata.difficulty      integer 1 (introductory) .. 5 (expert); default 1
//  tissues[].name           non-empty, unique
//  tissues[].meshing        edge_length: mm, 0 = defaultEdgeLength (core/mesher/tetrahedralize.h),
//                           else (0, 1e4]; seed: integer 0 .. 2^32-1 (CGAL's random seed)
//  tissues[].material       density g/mm^3 in (0, 1]; stiffness mm^2/s^2 in (0, 1e15] (the k of
//                           Eq. 4); damping 1/s in [0, 1e6] (core/mesh/material.h)
//  tissues[].fixed_regions  axis-aligned boxes in mm (reference positions), min <= max; the
//                           nodes inside are held by the "fixed" effect
//  tool.curve               the loop electrode as a polyline of n segments in its own frame;
//                           tool.size (mm, (0, 1e3]) scales it: a world point of the tool at a
//                           pose is position + R(orientation) * (size * curve point)
//  strokes[].poses          >= 2 poses with strictly increasing t (s); orientation is a
//                           quaternion [w, x, y, z] of non-zero length (normalised on use)
//  sweeps[]                 exactly one of "curves" (m >= 2 curves of n + 1 >= 2 points) and
//                           "file" (a sweep .json, DESIGN.md "Sweep surface files")
//  cut_settings             maps to CutOptions (toCutOptions; every range is CutLimits'):
//                           method hybrid|subdivision, triangulation enhanced|standard
//                           (enhanced needs hybrid), d in [0, 0.5] (fraction of the mean edge
//                           length), snap, relax_steps [0, 10000], w_spring and w_particle
//                           [0, 1e6], damping (0, 1e6] (the c of Eq. 2), rings [1, 5] (the
//                           relaxation neighbourhood); the mesh improvement after every cut
//                           (step 7 of Tissue::cut, core/cut/improve_mesh.h): improve (bool,
//                           default true, for either method), improve_quality [0, 4] (tets
//                           whose radius ratio is below this times the tissue's worst as
//                           created are improved), improve_short_edge [0, 4] (edges shorter
//                           than this times its shortest as created are collapsed),
//                           improve_coarsen [0, 1] (edges shorter than this times its mean
//                           edge are collapsed where quality allows); 0 turns a criterion off.
//                           Absent: method hybrid gives triangulation enhanced, snap true and
//                           relax_steps 10, subdivision standard, false and 0; every other
//                           field takes CutOptions' default
//  effects[]                names: deformation, gravity, fixed, tool-contact, damping (each at
//                           most once); parameters:
//                             deformation   {"distance": bool, "volume": bool, "area": bool}
//                                           (the terms, all true by default)
//                             gravity       {"acceleration": [x, y, z]} mm/s^2 (default
//                                           [0, 0, -9810])
//                             fixed         {} (uses the tissues' fixed regions)
//                             tool-contact  {"radius": mm in (0, 1e3]} (required: the wire's
//                                           radius; the tool is tool.curve at the current pose)
//                             damping       {"coefficient": 1/s in (0, 1e6]} (default: the
//                                           tissue's material damping, which must then be > 0)
//  simulation               integrator implicit (default; = projective-dynamics, the
//                           product's implicit integrator) | symplectic-euler |
//                           velocity-verlet | backward-euler (linearised, for comparison);
//                           iterations: local-global iterations per implicit step, 1..1000
//                           (default 5; fewer are faster and lag, see README "Real time");
//                           time_step: s in (0, 1] or "stable" (explicit: the stable step,
//                           kept safe as the tissue deforms; implicit: 0.001 s);
//                           duration: s in [0, 1e5] (0: no simulation after the cuts);
//                           resected_pieces rigid (default) | remove | deformable: what
//                           becomes of a piece a cut separates from every fixed region
//  expectations[]           {"kind", "value", "tissue" (optional: one tissue's name; absent:
//                           every tissue must meet it)}; kinds:
//                             pieces_at_least                   integer >= 1: connected pieces
//                                 of the tet mesh after every stroke and sweep is cut
//                             resected_volume_fraction_at_least number in [0, 1]: reference
//                                 volume of the pieces holding no fixed node (no node in a
//                                 fixed region; without fixed regions: every piece but the
//                                 largest) over the tissue's total reference volume
//                             min_radius_ratio_at_least         number in [0, 1]: smallest
//                                 radius ratio 3 r_in / R_circ of any tet after the cuts
//                             stays_finite                      true: every position and
//                                 velocity stays finite and the simulation never diverges
//                             max_inverted_tets                 integer >= 0: tets with
//                                 non-positive volume in the current configuration at the end

#include "core/cut/hybrid_cutter.h"
#include "core/mesh/material.h"
#include "core/mesh/tet_mesh.h"

#include <QJsonObject>

#include <string>
#include <vector>

namespace resect {

inline constexpr const char* kScenarioFormat = "resect-scenario";
/// The version this code reads and writes; older versions migrate (scenario_migrate.h).
inline constexpr int kScenarioVersion = 1;

struct ScenarioMetadata {
    std::string title;
    std::string author;
    std::string description;
    std::vector<std::string> learningObjectives;
    int difficulty = 1; ///< 1 (introductory) .. 5 (expert)
    QJsonObject extra;  ///< unknown fields, kept
    bool operator==(const ScenarioMetadata&) const = default;
};

struct MeshingSpec {
    double edgeLength = 0; ///< mm; 0: defaultEdgeLength of the surface
    unsigned seed = 0;
    QJsonObject extra;
    bool operator==(const MeshingSpec&) const = default;
};

struct MaterialSpec {
    double density = Material{}.density;     ///< g/mm^3
    double stiffness = Material{}.stiffness; ///< mm^2/s^2
    double damping = Material{}.damping;     ///< 1/s
    QJsonObject extra;
    Material toMaterial() const { return {density, stiffness, damping}; }
    bool operator==(const MaterialSpec&) const = default;
};

/// An axis-aligned box, mm, in reference coordinates.
struct FixedRegion {
    Vec3 min = Vec3::Zero();
    Vec3 max = Vec3::Zero();
    QJsonObject extra;
    bool contains(const Vec3& p) const {
        return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
    }
    bool operator==(const FixedRegion&) const = default;
};

struct TissueSpec {
    std::string name;
    std::string surface; ///< "sample:NAME" or a path (relative to Scenario::baseDir)
    std::string mesh;    ///< a .vtu path; empty: mesh `surface` with `meshing`
    MeshingSpec meshing; ///< used when `mesh` is empty
    MaterialSpec material;
    std::vector<FixedRegion> fixedRegions;
    QJsonObject extra;
    bool operator==(const TissueSpec&) const = default;
};

/// The tool (the loop electrode): a polyline in its own frame, scaled by `size` (mm).
struct ToolSpec {
    std::string name = "loop electrode";
    std::vector<Vec3> curve; ///< n + 1 >= 2 points, tool frame (unit: size mm)
    double size = 1;         ///< mm per tool-frame unit
    QJsonObject extra;
    bool operator==(const ToolSpec&) const = default;
};

/// One recorded tool pose.
struct ToolPose {
    double t = 0;                 ///< s
    Vec3 position = Vec3::Zero(); ///< mm, where the tool frame's origin is
    /// Rotation of the tool frame as a quaternion (w, x, y, z), as written (not normalised).
    Eigen::Vector4d orientation{1, 0, 0, 0};
    QJsonObject extra;
    bool operator==(const ToolPose&) const = default;
};

struct Stroke {
    std::string name;
    std::vector<ToolPose> poses; ///< >= 2, strictly increasing t
    QJsonObject extra;
    bool operator==(const Stroke&) const = default;
};

/// An explicit sweep surface: inline curves or a sweep file (exactly one of the two).
struct SweepSpec {
    std::string name;
    std::string file;                      ///< path of a sweep .json, or empty
    std::vector<std::vector<Vec3>> curves; ///< inline curves when `file` is empty
    QJsonObject extra;
    bool operator==(const SweepSpec&) const = default;
};

/// Cut settings; the JSON names are in brackets.
struct CutSettings {
    CutMethod method = CutMethod::Hybrid;                          ///< (method)
    FaceTriangulation triangulation = FaceTriangulation::Enhanced; ///< (triangulation)
    double d = 0.2;         ///< (d) fraction of the mean edge length
    bool snap = true;       ///< (snap)
    int relaxSteps = 10;    ///< (relax_steps)
    double wSpring = 1.0;   ///< (w_spring)
    double wParticle = 0.2; ///< (w_particle)
    double damping = 10.0;  ///< (damping) the c of Eq. 2
    int rings = 2;          ///< (rings)
    /// The mesh improvement after every cut (CutOptions::improve...; defaults are CutOptions').
    bool improve = CutOptions{}.improve;                      ///< (improve)
    double improveQuality = CutOptions{}.improveQuality;     ///< (improve_quality)
    double improveShortEdge = CutOptions{}.improveShortEdge; ///< (improve_short_edge)
    double improveCoarsen = CutOptions{}.improveCoarsen;     ///< (improve_coarsen)
    QJsonObject extra;
    bool operator==(const CutSettings&) const = default;
};

/// The cutter's options for these settings (the density comes from the tissue's material).
CutOptions toCutOptions(const CutSettings& settings, const MaterialSpec& material = {});

/// One effect the scene calls for; only declared effects are simulated. The parameters are
/// kept as written (see the table above for each effect's keys).
struct EffectSpec {
    std::string name;
    QJsonObject parameters;
    QJsonObject extra;
    bool operator==(const EffectSpec&) const = default;

    /// A parameter as a number, or `fallback` when absent.
    double number(const char* key, double fallback) const;
    /// A parameter as a vector [x, y, z], or `fallback` when absent.
    Vec3 vector(const char* key, const Vec3& fallback) const;
    /// A parameter as a boolean, or `fallback` when absent.
    bool flag(const char* key, bool fallback) const;
};

/// Ranges of the effects' parameters (the table above; validation and the studio's editors).
struct EffectLimits {
    static constexpr double kMaxAcceleration = 1e9;   ///< gravity: |component| in mm/s^2
    static constexpr double kMaxToolRadius = 1e3;     ///< tool-contact: radius in (0, this] mm
    static constexpr double kMaxDampingCoefficient = 1e6; ///< damping: coefficient in (0, this] 1/s
};

/// The effect names a scenario may declare, in the order they are listed above.
const std::vector<std::string>& knownEffectNames();

struct SimulationSettings {
    std::string integrator =
        "implicit"; ///< implicit|projective-dynamics|symplectic-euler|velocity-verlet|backward-euler
    int iterations = 5;     ///< local-global iterations per implicit (projective-dynamics) step
    double timeStep = 0;    ///< s; 0 means "stable"
    double duration = 0;    ///< s
    std::string resectedPieces = "rigid";  ///< rigid|remove|deformable: pieces off the fixed regions
    QJsonObject extra;
    bool stableTimeStep() const { return timeStep == 0; }
    bool operator==(const SimulationSettings&) const = default;
};

enum class ExpectationKind {
    PiecesAtLeast,
    ResectedVolumeFractionAtLeast,
    MinRadiusRatioAtLeast,
    StaysFinite,
    MaxInvertedTets,
};
/// The JSON name of a kind ("pieces_at_least", ...).
const char* expectationKindName(ExpectationKind kind);
/// Every kind, in the order of the enum.
const std::vector<ExpectationKind>& allExpectationKinds();

struct Expectation {
    ExpectationKind kind = ExpectationKind::PiecesAtLeast;
    double value = 0;   ///< the bound; 1 or 0 (true or false) for stays_finite
    std::string tissue; ///< empty: every tissue
    QJsonObject extra;
    bool operator==(const Expectation&) const = default;
};

struct Scenario {
    ScenarioMetadata metadata;
    std::vector<TissueSpec> tissues;
    ToolSpec tool;
    std::vector<Stroke> strokes;
    std::vector<SweepSpec> sweeps;
    CutSettings cut;
    std::vector<EffectSpec> effects;
    SimulationSettings simulation;
    std::vector<Expectation> expectations;
    QJsonObject extra; ///< unknown top-level fields

    /// Folder that relative paths are resolved against (absolute, set by loading); not part
    /// of the file and not compared by ==.
    std::string baseDir;

    const EffectSpec* findEffect(const std::string& name) const;
    const TissueSpec* findTissue(const std::string& name) const;

    /// Equal documents: every field and every kept unknown field (baseDir aside).
    bool operator==(const Scenario& other) const;
};

/// The document as JSON (version kScenarioVersion, every field written, unknown fields
/// merged back into their objects). Paths are written as they are stored.
QJsonObject scenarioToJson(const Scenario& scenario);

/// True for "sample:..." sources (no file behind them).
bool isSampleSource(const std::string& source);
/// The path to open for `path` of a document whose relative paths start at `baseDir`:
/// samples and absolute paths unchanged, relative ones joined to baseDir (lexically
/// normalised). An empty baseDir means the current folder.
std::string resolveScenarioPath(const std::string& baseDir, const std::string& path);
/// Rewrites every relative path of the document so that, relative to `newBaseDir`, it names
/// the same file as before relative to scenario.baseDir; then sets baseDir = newBaseDir
/// (made absolute). Absolute paths and samples are unchanged.
void rebaseScenarioPaths(Scenario& scenario, const std::string& newBaseDir);

} // namespace resect
