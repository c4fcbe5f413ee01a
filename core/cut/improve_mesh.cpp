#include "core/cut/improve_mesh.h"

#include "core/mesh/index_marks.h"

#include "core/cut/update_rest_state.h"
#include "core/mesh/body_surface.h"
#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"
#include "core/mesh/tet_grid.h"
#include "core/mesh/topology.h"
#include "core/mesh/uniform_cells.h"
#include "core/mesh/validity.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <span>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace resect {

double pointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    return (p - closestPointOnTriangle(p, a, b, c)).norm();
}

Vec3 nearestToZeroInHull(const std::vector<Vec3>& g) {
    // Over every subset, the point of its affine hull nearest to zero, kept where its weights
    // are all non-negative; the nearest of those.
    if (g.empty() || g.size() > 4)
        return Vec3::Zero();
    const int k = static_cast<int>(g.size());
    Vec3 best = g.front();
    for (int mask = 1; mask < (1 << k); ++mask) {
        int set[4] = {0, 0, 0, 0}, size = 0;
        for (int i = 0; i < k; ++i)
            if (mask & (1 << i))
                set[size++] = i;
        Vec3 candidate = g[set[0]];
        if (size > 1) {
            const int n = size - 1;
            Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> a(3, n);
            for (int j = 0; j < n; ++j)
                a.col(j) = g[set[j + 1]] - g[set[0]];
            const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1> t =
                (a.transpose() * a).ldlt().solve(-a.transpose() * g[set[0]]);
            if (!t.allFinite() || (t.array() < -1e-12).any() || t.sum() > 1 + 1e-12)
                continue;
            candidate = g[set[0]] + a * t;
        }
        if (candidate.squaredNorm() < best.squaredNorm())
            best = candidate;
    }
    return best;
}

ImproveRegion improveRegion(const TetMesh& mesh, const std::vector<int>& seeds, const std::vector<int>& fixedNodes,
                            int rings) {
    ImproveRegion region;
    std::unordered_set<int> inside;
    std::vector<int> frontier;
    for (int n : seeds)
        if (n >= 0 && n < mesh.nodeCount() && !mesh.nodeTets(n).empty() && inside.insert(n).second)
            frontier.push_back(n);
    for (int ring = 0; ring < rings; ++ring) {
        std::vector<int> next;
        for (int n : frontier)
            for (int t : mesh.nodeTets(n))
                for (int v : mesh.tet(t))
                    if (inside.insert(v).second)
                        next.push_back(v);
        frontier = std::move(next);
    }
    const std::unordered_set<int> fixed(fixedNodes.begin(), fixedNodes.end());
    for (int n : inside)
        (fixed.count(n) ? region.fixed : region.nodes).push_back(n);
    std::sort(region.nodes.begin(), region.nodes.end());
    std::sort(region.fixed.begin(), region.fixed.end());
    for (const auto* list : {&region.nodes, &region.fixed})
        for (int n : *list)
            region.tets.insert(region.tets.end(), mesh.nodeTets(n).begin(), mesh.nodeTets(n).end());
    std::sort(region.tets.begin(), region.tets.end());
    region.tets.erase(std::unique(region.tets.begin(), region.tets.end()), region.tets.end());
    return region;
}

namespace {

constexpr int kOmega = -1;  // the virtual vertex that closes the boundary (link condition)
constexpr int kSmoothingIterations = 40;  // ascent steps per node and sweep
// Smoothing raises together the tets within this of the worst radius ratio (at most kMaxActive).
constexpr double kActiveRatio = 0.02;
constexpr std::size_t kMaxActive = 4;
// An edge split must raise the worst tet around the edge by this much; the two longest edges
// of a bad tet are tried.
constexpr double kSplitGain = 0.01;
constexpr int kSplitEdges = 2;
// How far (in local edge lengths) a boundary node may be placed outside the body, or off it for
// a node of the body's surface alone, when ImproveOptions::body is given: rounding. The bound is
// absolute (against the body as created), so it does not add up over passes.
constexpr double kBodyTolerance = 1e-9;
// A node within this many local edge lengths of the body's surface is on it (held to it if no
// cut marks it): placements on the old boundary that keep the volume exactly can land off a
// plane by about kBodyTolerance near the body's sharp edges, and such a node stays held.
constexpr double kOnBodyTolerance = 1e-6;

/// Signed volume of a tet by its nodes (reference positions).
double tetVolume(const TetMesh& m, const Tet& q) {
    return (m.ref(q[1]) - m.ref(q[0])).dot((m.ref(q[2]) - m.ref(q[0])).cross(m.ref(q[3]) - m.ref(q[0]))) / 6.0;
}

/// The tet q with node v placed at p (reference positions otherwise).
std::array<Vec3, 4> cornersWith(const TetMesh& m, const Tet& q, int v, const Vec3& p, bool current) {
    std::array<Vec3, 4> c;
    for (int i = 0; i < 4; ++i)
        c[i] = q[i] == v ? p : (current ? m.pos(q[i]) : m.ref(q[i]));
    return c;
}

double ratioWith(const TetMesh& m, const Tet& q, int v, const Vec3& p) {
    const auto c = cornersWith(m, q, v, p, false);
    return radiusRatio(c[0], c[1], c[2], c[3]);
}

bool positiveWith(const TetMesh& m, const Tet& q, int v, const Vec3& p, bool current) {
    const auto c = cornersWith(m, q, v, p, current);
    return orient3d(c[0], c[1], c[2], c[3]) > 0;
}

/// Volume of tet q with v at p, and its gradient with respect to p (q must contain v).
double volumeAndGradient(const TetMesh& m, const Tet& q, int v, const Vec3& p, Vec3& gradient) {
    // Rotate v to the front by an even permutation (orientation kept).
    static constexpr int kEven[4][4] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}};
    int i = 0;
    while (q[i] != v)
        ++i;
    const Vec3& x1 = m.ref(q[kEven[i][1]]);
    const Vec3& x2 = m.ref(q[kEven[i][2]]);
    const Vec3& x3 = m.ref(q[kEven[i][3]]);
    gradient = -(x2 - x1).cross(x3 - x1) / 6.0;
    return signedVolume(p, x1, x2, x3);
}

/// Barycentric coordinates of p in tet q (reference positions).
std::array<double, 4> referenceBarycentric(const TetMesh& m, const Tet& q, const Vec3& p) {
    return barycentric(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3]), p);
}

/// Where the element in each slot of a TetMesh array (tets or nodes) came from, recorded only
/// for the slots that changed: a slot absent from the map holds what it held at the start (a
/// slot past the start's count: a new element). Removal moves the last element into the freed
/// slot (TetMesh::removeTet / removeNode), so the map holds about two entries per removal and
/// costs nothing in the size of the mesh.
class SlotOrigins {
public:
    explicit SlotOrigins(int countAtStart) : m_start(countAtStart) {}

    bool changed() const { return m_changed; }
    /// The index at the start of the element in `slot`, or -1 for a new one.
    int originOf(int slot) const {
        const auto it = m_map.find(slot);
        return it != m_map.end() ? it->second : defaultOf(slot);
    }
    /// `slot` now holds the element that had index `origin` at the start (-1: a new one).
    void set(int slot, int origin) {
        m_changed = true;
        if (origin == defaultOf(slot))
            m_map.erase(slot);
        else
            m_map[slot] = origin;
    }
    /// The element in `slot` was removed from `count` elements: the last one took its slot.
    void remove(int slot, int count) {
        const int last = count - 1;
        set(slot, originOf(last));
        if (last != slot)
            m_map.erase(last);
    }
    /// Old index -> new index for the elements whose index changed (-1: gone), sorted.
    SparseRenumbering renumbering(int finalCount) const {
        SparseRenumbering r;
        r.oldCount = m_start;
        r.newCount = finalCount;
        if (!m_changed)
            return r;
        std::unordered_map<int, int> newOf;  // old index -> slot, for the elements that moved
        std::vector<int> candidates;
        for (const auto& [slot, origin] : m_map) {
            if (origin >= 0 && slot < finalCount) {
                newOf[origin] = slot;
                candidates.push_back(origin);
            }
            if (slot < m_start)
                candidates.push_back(slot);  // its old element moved away or is gone
        }
        for (int i = finalCount; i < m_start; ++i)
            candidates.push_back(i);  // slots cut off at the end
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        for (int old : candidates) {
            const auto it = newOf.find(old);
            const int now = it != newOf.end() ? it->second : (old < finalCount && !m_map.count(old) ? old : -1);
            if (now != old)
                r.changed.emplace_back(old, now);
        }
        return r;
    }
    /// Calls f for every slot below `count` whose element is not the one it held at the start.
    template <class F>
    void forEachChangedSlot(int count, F f) const {
        for (const auto& [slot, origin] : m_map)
            if (slot < count)
                f(slot);
        for (int i = m_start; i < count; ++i)
            if (!m_map.count(i))
                f(i);
    }
    /// The slots (below finalCount) that hold new elements, sorted.
    std::vector<int> newSlots(int finalCount) const {
        std::vector<int> out;
        for (const auto& [slot, origin] : m_map)
            if (origin < 0 && slot < finalCount)
                out.push_back(slot);
        for (int i = m_start; i < finalCount; ++i)
            if (!m_map.count(i))
                out.push_back(i);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }

private:
    int defaultOf(int slot) const { return slot < m_start ? slot : -1; }

    int m_start;
    bool m_changed = false;
    std::unordered_map<int, int> m_map;
};

struct Face {
    Tri nodes;  ///< outward
    bool crack = false;  ///< a glued crack face (Pass::glue), not the mesh boundary
};

/// An unoriented triangle, by its sorted nodes.
struct TriKey {
    int a, b, c;
    static TriKey of(int x, int y, int z) {
        if (x > y)
            std::swap(x, y);
        if (y > z)
            std::swap(y, z);
        if (x > y)
            std::swap(x, y);
        return {x, y, z};
    }
    static TriKey of(const Tri& t) { return of(t[0], t[1], t[2]); }
    bool operator==(const TriKey&) const = default;
};
struct TriKeyHash {
    std::size_t operator()(const TriKey& k) const {
        std::uint64_t h = static_cast<std::uint32_t>(k.a);
        h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.b);
        h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.c);
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

class Pass {
public:
    Pass(TetMesh& mesh, const ImproveRegion& region, const ImproveOptions& options, ImproveResult& result)
        : m(mesh), o(options), r(result), editable(region.nodes.begin(), region.nodes.end()),
          nodes(region.nodes), tetOrigin(mesh.tetCount()), nodeOrigin(mesh.nodeCount()), startNodes(mesh.nodeCount()) {
        flippable = editable;
        flippable.insert(region.fixed.begin(), region.fixed.end());
        for (int n : region.fixed) {
            if (o.moveAnchored && keptOut(m.ref(n))) {  // (ImproveOptions::moveAnchored)
                anchored.insert(n);
                editable.insert(n);
                nodes.push_back(n);
            } else {
                fixedInRegion.push_back(n);
            }
        }
        std::sort(nodes.begin(), nodes.end());
    }

    void run() {
        if (o.glueCracks)
            glue();
        r.worstBefore = worstInRegion();
        sweeps();
        if (!crack.empty() || !spares.empty())
            unglue();
        // Where the glued walls could not be made good enough (tissue between two walls thinner
        // than the elements, a flap), the sweeps again with the walls on their own.
        if (r.gluedNodes > 0 && weak()) {
            ++r.ungluedPasses;
            sweeps();
        }
        r.worstAfter = worstInRegion();
        finish();
    }

private:
    TetMesh& m;
    const ImproveOptions& o;
    ImproveResult& r;
    std::unordered_set<int> editable;   ///< nodes that may move or merge
    std::unordered_set<int> flippable;  ///< nodes whose tets may be flipped (also the fixed ones: flips move no node)
    std::vector<int> nodes;                      ///< the region's nodes (original indices)
    std::vector<int> fixedInRegion;
    std::unordered_set<int> anchored;  ///< fixed nodes that may move within keepOut (moveAnchored)
    std::unordered_map<int, int> mergedInto;     ///< collapsed node -> node it merged into
    std::unordered_set<int> moved, touched;
    SlotOrigins tetOrigin, nodeOrigin;           ///< what each changed slot held at the start
    mutable std::unordered_map<int, double> ratioOf;  ///< tetRatio() of tets not changed since
    int startNodes;                              ///< node count at the start (added nodes come after)
    std::unordered_map<int, bool> cutMarkOf;     ///< onCut() of merged and added nodes
    /// Glued cracks (glue()): the crack faces, by their nodes as they are now, and the copies
    /// glued into each node (out of every tet until unglue() gives them a side again).
    std::unordered_set<TriKey, TriKeyHash> crack;
    std::unordered_map<int, std::vector<int>> spares;

    bool alive(int n) const { return !mergedInto.count(n); }
    /// Whether a glued crack node moved from `from` to `to` drifts from the cuts: farther from
    /// their sweeps than ImproveOptions::maxCrackDrift and than it was.
    bool drifts(const Vec3& from, const Vec3& to) const {
        if (!o.cutDistance || crack.empty())
            return false;
        return o.cutDistance(to) > std::max(o.maxCrackDrift, o.cutDistance(from)) * (1 + 1e-12);
    }
    /// The number of sectors of the star `tets` of x: tets joined across faces at x that are not
    /// crack faces (isCrack with from/to: the tets after a collapse of `from` into `to`).
    int sectorsOf(const std::vector<Tet>& tets, int x, int from = -1, int to = -1) const {
        std::vector<int> parent(tets.size());
        std::iota(parent.begin(), parent.end(), 0);
        const auto root = [&](int i) {
            while (parent[i] != i)
                i = parent[i] = parent[parent[i]];
            return i;
        };
        std::unordered_map<std::uint64_t, int> firstWith;
        for (int i = 0; i < static_cast<int>(tets.size()); ++i) {
            const Tet& q = tets[i];
            for (const auto& lf : kTetFaces) {
                const Tri f{q[lf[0]], q[lf[1]], q[lf[2]]};
                const int k = f[0] == x ? 0 : f[1] == x ? 1 : f[2] == x ? 2 : -1;
                if (k < 0 || isCrack(f, from, to))
                    continue;
                const auto [it, inserted] = firstWith.emplace(linkEdge(f[(k + 1) % 3], f[(k + 2) % 3]), i);
                if (!inserted)
                    parent[root(i)] = root(it->second);
            }
        }
        int count = 0;
        for (int i = 0; i < static_cast<int>(tets.size()); ++i)
            count += root(i) == i;
        return count;
    }
    int sectorCount(int x) const { return sectorsOf(starOf(x), x); }
    /// Per tet of `tets` (around nodes a and b), its side of the glued crack: tets joined across
    /// faces that are not crack faces; the label of the first tet's side is 0, the others 1
    /// (the sides are found across every face, not only those at a node).
    std::vector<int> sidesOf(const std::vector<Tet>& tets, int& count) const {
        std::vector<int> parent(tets.size());
        std::iota(parent.begin(), parent.end(), 0);
        const auto root = [&](int i) {
            while (parent[i] != i)
                i = parent[i] = parent[parent[i]];
            return i;
        };
        std::unordered_map<TriKey, int, TriKeyHash> firstWith;
        for (int i = 0; i < static_cast<int>(tets.size()); ++i)
            for (const auto& lf : kTetFaces) {
                const Tri f{tets[i][lf[0]], tets[i][lf[1]], tets[i][lf[2]]};
                if (isCrack(f))
                    continue;
                const auto [it, inserted] = firstWith.emplace(TriKey::of(f), i);
                if (!inserted)
                    parent[root(i)] = root(it->second);
            }
        count = 0;
        std::vector<int> side(tets.size());
        for (int i = 0; i < static_cast<int>(tets.size()); ++i) {
            count += root(i) == i;
            side[i] = root(i) == root(0) ? 0 : 1;
        }
        return side;
    }

    bool keptOut(const Vec3& p) const {
        if (!o.keepOut)
            return false;
        const auto& [lo, hi] = *o.keepOut;
        return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
    }
    /// Whether the nodes `ns`, merged or moved to p, may not go there: free nodes stay out of
    /// keepOut, anchored ones (moveAnchored) in it; a free node merged with an anchored one
    /// goes into it where ImproveOptions::mergeFreeIntoAnchored allows that (the merged node
    /// is anchored then), else the two kinds are not merged.
    bool misplaced(std::initializer_list<int> ns, const Vec3& p) const {
        const auto isAnchored = [&](int n) { return anchored.count(n) > 0; };
        if (std::none_of(ns.begin(), ns.end(), isAnchored))
            return keptOut(p);
        return (!o.mergeFreeIntoAnchored && !std::all_of(ns.begin(), ns.end(), isAnchored)) || !keptOut(p);
    }

    // --- the body's surface (ImproveOptions::body, cutSurfaceNodes) ---
    /// Whether node n lies on a cut's surface (ImproveOptions::cutSurfaceNodes; a merged node
    /// if either end did, a split point if both ends of its edge did).
    bool onCut(int n) const {
        if (const auto it = cutMarkOf.find(n); it != cutMarkOf.end())
            return it->second;
        return n < static_cast<int>(o.cutSurfaceNodes.size()) && o.cutSurfaceNodes[n] != 0;
    }
    /// Whether a boundary node (a merged node: its boundary ends `nodesOf`) is a node of the
    /// body's surface alone: on no cut's surface by its marks, and on the body's surface (a node
    /// the marks miss, off the body, is not; it does not free a merged node from the body).
    bool bodyOnly(const std::vector<int>& nodesOf, double scale) const {
        if (!o.body || std::any_of(nodesOf.begin(), nodesOf.end(), [&](int n) { return onCut(n); }))
            return false;
        const double eps = kOnBodyTolerance * scale;
        return std::any_of(nodesOf.begin(), nodesOf.end(), [&](int n) {
            const BodySurface::Side s = o.body->side(m.ref(n), 2 * eps);
            return std::abs(s.distance) <= s.slack + eps;
        });
    }
    /// Whether a boundary node moved from `from` to p leaves the body: p is outside it, or the
    /// node is of the body's surface alone (`pure`) and p is off that surface. Both up to the
    /// surface's slack (BodySurface::side) and rounding; `scale`: a local edge length. The
    /// surface is searched within |p - from| plus that length of p (from may itself lie
    /// outside by up to the slack of another patch).
    bool leavesBody(const Vec3& from, const Vec3& p, bool pure, double scale) const {
        if (!o.body)
            return false;
        const double eps = kBodyTolerance * scale;
        const BodySurface::Side s = o.body->side(p, (p - from).norm() + scale);
        return s.distance > s.slack + eps || (pure && s.distance < -s.slack - eps);
    }

    /// Collapses, flips, smoothing and splits over the region, until a sweep changes nothing.
    void sweeps() {
        for (int sweep = 0; sweep < o.sweeps; ++sweep) {
            const int before = r.collapses + r.smoothed + r.flips + r.splits;
            collapseSweep();
            flipSweep();
            smoothSweep();
            if (o.split)
                splitSweep();
            if (r.collapses + r.smoothed + r.flips + r.splits == before)
                break;
        }
    }

    /// Whether a tet of the region is below ImproveOptions::weakRatio or an edge below weakEdge.
    bool weak() const {
        for (int n : nodes)
            if (alive(n))
                for (int t : m.nodeTets(n)) {
                    if (tetRatio(t) < o.weakRatio)
                        return true;
                    const Tet& q = m.tet(t);
                    for (const auto& e : kTetEdges)
                        if ((m.ref(q[e[0]]) - m.ref(q[e[1]])).norm() < o.weakEdge)
                            return true;
                }
        return false;
    }

    double worstInRegion() const {
        double worst = 1;
        for (int n : nodes)
            if (alive(n))
                for (int t : m.nodeTets(n))
                    worst = std::min(worst, tetRatio(t));
        return worst;
    }

    /// Radius ratio of tet t as it is (reference positions). Each tet is measured once until
    /// it changes (forget()): the sweeps look at the same tets again and again.
    double tetRatio(int t) const {
        if (const auto it = ratioOf.find(t); it != ratioOf.end())
            return it->second;
        const Tet& q = m.tet(t);
        const double ratio = radiusRatio(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3]));
        ratioOf.emplace(t, ratio);
        return ratio;
    }
    void forget(int t) { ratioOf.erase(t); }

    /// Whether face f is a glued crack face; with from >= 0, also where f names node `to` for
    /// node `from` (the tets after a collapse of `from` into `to`).
    bool isCrack(const Tri& f, int from = -1, int to = -1) const {
        if (crack.empty())
            return false;
        if (crack.count(TriKey::of(f)))
            return true;
        if (from < 0)
            return false;
        Tri g = f;
        bool renamed = false;
        for (int& v : g)
            if (v == to) {
                v = from;
                renamed = true;
            }
        return renamed && crack.count(TriKey::of(g));
    }

    /// Faces of the given tets that contain node x and occur once among them (the boundary of
    /// x's star when `tets` are all of x's tets), oriented outward, and the glued crack faces
    /// at x (twice among them: once, as one of the tets has it; `crack` set). With from >= 0
    /// the tets are those after a collapse of `from` into `to` (isCrack).
    std::vector<Face> boundaryFacesAt(const std::vector<Tet>& tets, int x, int from = -1, int to = -1) const {
        // Every face here contains x, so its other two nodes (u < v) identify it: faces are
        // matched on one 64-bit key. The few that occur once are then put in the order of their
        // sorted node triples (what callers iterate in; sums over them depend on the order).
        struct Entry {
            std::uint64_t key;
            Tri face;
            bool operator<(const Entry& e) const { return key < e.key; }
        };
        thread_local std::vector<Entry> all;
        all.clear();
        for (const Tet& q : tets)
            for (const auto& lf : kTetFaces) {
                const Tri f{q[lf[0]], q[lf[1]], q[lf[2]]};
                const int i = f[0] == x ? 0 : f[1] == x ? 1 : f[2] == x ? 2 : -1;
                if (i < 0)
                    continue;
                const int u = f[(i + 1) % 3], v = f[(i + 2) % 3];
                all.push_back({linkEdge(u, v), f});
            }
        std::sort(all.begin(), all.end());
        std::vector<Face> faces;
        for (std::size_t i = 0; i < all.size();) {
            std::size_t j = i + 1;
            while (j < all.size() && all[j].key == all[i].key)
                ++j;
            if (j == i + 1)
                faces.push_back({all[i].face});
            else if (j == i + 2 && isCrack(all[i].face, from, to))
                faces.push_back({all[i].face, true});
            i = j;
        }
        const auto sorted = [](const Face& f) {
            Tri t = f.nodes;
            std::sort(t.begin(), t.end());
            return t;
        };
        std::sort(faces.begin(), faces.end(), [&](const Face& p, const Face& q) { return sorted(p) < sorted(q); });
        return faces;
    }
    static bool anyOuter(const std::vector<Face>& faces) {
        return std::any_of(faces.begin(), faces.end(), [](const Face& f) { return !f.crack; });
    }

    std::vector<Tet> starOf(int x) const {
        std::vector<Tet> star;
        for (int t : m.nodeTets(x))
            star.push_back(m.tet(t));
        return star;
    }

    double meanEdgeOf(const std::vector<Face>& faces) const {
        double sum = 0;
        int count = 0;
        for (const Face& f : faces)
            for (int i = 0; i < 3; ++i) {
                sum += (m.ref(f.nodes[i]) - m.ref(f.nodes[(i + 1) % 3])).norm();
                ++count;
            }
        return count ? sum / count : 0;
    }

    /// Largest distance of p from the triangles `faces` (reference positions, node x at px).
    double distanceTo(const Vec3& p, const std::vector<Face>& faces, int x, const Vec3& px) const {
        double best = std::numeric_limits<double>::infinity();
        const auto at = [&](int n) -> const Vec3& { return n == x ? px : m.ref(n); };
        for (const Face& f : faces)
            best = std::min(best, pointTriangleDistance(p, at(f.nodes[0]), at(f.nodes[1]), at(f.nodes[2])));
        return best;
    }

    /// The point of the triangles `faces` (reference positions) nearest to p.
    Vec3 nearestOn(const std::vector<Face>& faces, const Vec3& p) const {
        Vec3 best = p;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (const Face& f : faces) {
            const Vec3 c = closestPointOnTriangle(p, m.ref(f.nodes[0]), m.ref(f.nodes[1]), m.ref(f.nodes[2]));
            if (const double d = (c - p).squaredNorm(); d < bestDistance) {
                bestDistance = d;
                best = c;
            }
        }
        return best;
    }

    /// Current position and velocity at reference point p, from the tet of `star` (reference
    /// positions as they are now) that contains it best.
    void mapToCurrent(const std::vector<Tet>& star, const Vec3& p, Vec3& pos, Vec3& vel) const {
        double best = -std::numeric_limits<double>::infinity();
        for (const Tet& q : star) {
            const auto w = referenceBarycentric(m, q, p);
            const double s = std::min({w[0], w[1], w[2], w[3]});
            if (!(s > best))
                continue;
            best = s;
            pos = Vec3::Zero();
            vel = Vec3::Zero();
            for (int i = 0; i < 4; ++i) {
                pos += w[i] * m.pos(q[i]);
                vel += w[i] * m.velocities()[q[i]];
            }
        }
    }

    void moveNode(int v, const Vec3& ref, const Vec3& pos, const Vec3& vel) {
        for (int t : m.nodeTets(v))
            forget(t);
        m.setNodePosition(v, ref, pos);
        m.velocities()[v] = vel;  // velocities are not recorded by backups: none is open here
        moved.insert(v);
        for (int t : m.nodeTets(v))
            touched.insert(m.tet(t).begin(), m.tet(t).end());
    }

    // --- link condition (Dey, Edelsbrunner, Guha, Nekhayev), boundary closed by kOmega ---
    struct Link {
        std::vector<int> verts;
        std::vector<std::uint64_t> edges;
        void finish() {
            std::sort(verts.begin(), verts.end());
            verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
            std::sort(edges.begin(), edges.end());
            edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
        }
    };
    static std::uint64_t linkEdge(int a, int b) {
        if (a > b)
            std::swap(a, b);
        return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a + 1)) << 32) |
               static_cast<std::uint32_t>(b + 1);
    }
    /// The link of x; its star and the star's boundary faces at x go to `star` and `faces`.
    Link linkOfNode(int x, std::vector<Tet>& star, std::vector<Face>& faces) const {
        Link l;
        star = starOf(x);
        for (const Tet& q : star) {
            int o3[3], k = 0;
            for (int v : q)
                if (v != x)
                    o3[k++] = v;
            l.verts.insert(l.verts.end(), o3, o3 + 3);
            l.edges.push_back(linkEdge(o3[0], o3[1]));
            l.edges.push_back(linkEdge(o3[0], o3[2]));
            l.edges.push_back(linkEdge(o3[1], o3[2]));
        }
        faces = boundaryFacesAt(star, x);
        for (const Face& f : faces) {
            l.verts.push_back(kOmega);
            for (int v : f.nodes)
                if (v != x)
                    l.edges.push_back(linkEdge(kOmega, v));
        }
        l.finish();
        return l;
    }
    bool linkCondition(int a, int b) const {
        std::vector<Tet> starA, starB;
        std::vector<Face> facesA, facesB;
        const Link la = linkOfNode(a, starA, facesA), lb = linkOfNode(b, starB, facesB);
        Link lab;
        for (const Tet& q : starA) {
            if (std::find(q.begin(), q.end(), b) == q.end())
                continue;
            int o2[2], k = 0;
            for (int v : q)
                if (v != a && v != b)
                    o2[k++] = v;
            lab.verts.insert(lab.verts.end(), o2, o2 + 2);
            lab.edges.push_back(linkEdge(o2[0], o2[1]));
        }
        for (const Face& f : facesA) {
            const bool hasB = f.nodes[0] == b || f.nodes[1] == b || f.nodes[2] == b;
            if (!hasB)
                continue;
            lab.verts.push_back(kOmega);
            for (int v : f.nodes)
                if (v != a && v != b)
                    lab.edges.push_back(linkEdge(kOmega, v));
        }
        lab.finish();
        std::vector<int> commonVerts;
        std::set_intersection(la.verts.begin(), la.verts.end(), lb.verts.begin(), lb.verts.end(),
                              std::back_inserter(commonVerts));
        if (commonVerts != lab.verts)
            return false;
        std::vector<std::uint64_t> commonEdges;
        std::set_intersection(la.edges.begin(), la.edges.end(), lb.edges.begin(), lb.edges.end(),
                              std::back_inserter(commonEdges));
        return commonEdges == lab.edges;
    }

    /// Whether the glued crack through node x ends inside the tissue somewhere (a border edge of
    /// its crack faces, reached across crack edges, that lies on no boundary face: a front).
    /// Such a crack does not separate its two sides, so joining its walls at a node cannot
    /// join two pieces; a crack without one may separate them (or run on beyond the region).
    bool crackHasFront(int x) const {
        const auto facesAt = [&](int y) {
            std::vector<TriKey> out;
            for (int t : m.nodeTets(y)) {
                const Tet& q = m.tet(t);
                for (const auto& lf : kTetFaces) {
                    const Tri f{q[lf[0]], q[lf[1]], q[lf[2]]};
                    if (std::find(f.begin(), f.end(), y) == f.end())
                        continue;
                    const TriKey k = TriKey::of(f);
                    if (crack.count(k) && std::find(out.begin(), out.end(), k) == out.end())
                        out.push_back(k);
                }
            }
            return out;
        };
        std::vector<TriKey> queue = facesAt(x);
        std::unordered_set<TriKey, TriKeyHash> seen(queue.begin(), queue.end());
        std::vector<int> tets;
        for (std::size_t i = 0; i < queue.size() && i < 20000; ++i) {
            const TriKey k = queue[i];
            const int v[3] = {k.a, k.b, k.c};
            for (int e = 0; e < 3; ++e) {
                const int p = v[e], q = v[(e + 1) % 3];
                int across = 0;
                for (const TriKey& g : facesAt(p)) {
                    if (!(g.a == q || g.b == q || g.c == q) || g == k)
                        continue;
                    ++across;
                    if (seen.insert(g).second)
                        queue.push_back(g);
                }
                if (across > 0)
                    continue;
                // A border edge: a front where no boundary face holds it.
                m.edgeTets(p, q, tets);
                bool onBoundary = false;
                std::vector<int> ft;
                for (int t : tets) {
                    const Tet& qq = m.tet(t);
                    for (int r : qq) {
                        if (r == p || r == q)
                            continue;
                        m.faceTets(p, q, r, ft);
                        if (ft.size() == 1)
                            onBoundary = true;
                    }
                }
                if (!onBoundary)
                    return true;
            }
        }
        return false;
    }

    // --- edge collapse ---

    /// The point of the triangles `faces` (reference positions) nearest to p0 where
    /// g . (p - p0) = delta; none if no face reaches that level.
    std::optional<Vec3> onBoundaryWithVolume(const std::vector<Face>& faces, const Vec3& g, const Vec3& p0,
                                             double delta) const {
        std::optional<Vec3> best;
        double bestDistance = std::numeric_limits<double>::infinity();
        const double level = g.dot(p0) + delta;
        const auto consider = [&](const Vec3& p) {
            const double dist = (p - p0).squaredNorm();
            if (dist < bestDistance) {
                bestDistance = dist;
                best = p;
            }
        };
        for (const Face& f : faces) {
            const Vec3 c[3] = {m.ref(f.nodes[0]), m.ref(f.nodes[1]), m.ref(f.nodes[2])};
            const double h[3] = {g.dot(c[0]) - level, g.dot(c[1]) - level, g.dot(c[2]) - level};
            // The level line crosses the triangle where h changes sign: a segment between two
            // edge points (or a corner on the level).
            Vec3 ends[3];
            int count = 0;
            for (int i = 0; i < 3; ++i) {
                const int j = (i + 1) % 3;
                if (h[i] == 0)
                    ends[count++] = c[i];
                else if ((h[i] < 0) != (h[j] < 0) && h[j] != 0)
                    ends[count++] = c[i] + (c[j] - c[i]) * (h[i] / (h[i] - h[j]));
                if (count == 2)
                    break;
            }
            if (count == 1)
                consider(ends[0]);
            else if (count == 2) {
                // Nearest point to p0 on the segment.
                const Vec3 d = ends[1] - ends[0];
                const double len2 = d.squaredNorm();
                const double t = len2 > 0 ? std::clamp((p0 - ends[0]).dot(d) / len2, 0.0, 1.0) : 0.0;
                consider(ends[0] + t * d);
            }
        }
        return best;
    }

    struct Placement {
        Vec3 ref = Vec3::Zero(), pos = Vec3::Zero(), vel = Vec3::Zero();
        double worst = -1;
    };

    /// Where the link condition refuses a short edge (a, b) of the boundary because of a pit at
    /// it (ImproveOptions::fillPits), the pit is filled and the edge collapsed keeping the
    /// volume the mesh had; if that fails, the filling tet goes again. False where there is no
    /// such pit.
    bool collapseThroughPit(int a, int b, bool coarsen) {
        const std::optional<Tet> pit = pitAt(a, b);
        if (!pit || !keepsTetsWithout(*pit, a, b))
            return false;
        replaceTets({}, {*pit});
        const int slot = m.tetCount() - 1;
        if (linkCondition(a, b) && tryCollapse(a, b, true, coarsen, slot)) {
            ++r.pitsFilled;
            return true;
        }
        replaceTets({slot}, {});
        return false;
    }

    /// A pit at edge (a, b): nodes x and c with boundary faces (a, b, x), (a, x, c) and
    /// (b, x, c) (none a glued crack face) where no tet has a, b and c: a void the shape of the
    /// tet (x, a, b, c), which is returned oriented if it is positive in both configurations.
    std::optional<Tet> pitAt(int a, int b) const {
        const std::vector<Face> fa = boundaryFacesAt(starOf(a), a);
        const std::vector<Face> fb = boundaryFacesAt(starOf(b), b);
        const auto has = [](const Face& f, int v) { return std::find(f.nodes.begin(), f.nodes.end(), v) != f.nodes.end(); };
        const auto third = [](const Face& f, int u, int v) {
            for (int w : f.nodes)
                if (w != u && w != v)
                    return w;
            return -1;
        };
        for (const Face& f : fa) {
            if (f.crack || !has(f, b))
                continue;
            const int x = third(f, a, b);
            for (const Face& g : fa) {
                if (g.crack || !has(g, x) || has(g, b))
                    continue;
                const int c = third(g, a, x);
                const bool closed = std::any_of(fb.begin(), fb.end(), [&](const Face& h) { return !h.crack && has(h, x) && has(h, c); });
                const bool mouthIsFace = std::any_of(m.nodeTets(a).begin(), m.nodeTets(a).end(),
                                                     [&](int t) { return contains(m.tet(t), b) && contains(m.tet(t), c); });
                if (!closed || mouthIsFace)
                    continue;
                Tet v{x, a, b, c};
                if (orient3d(m.ref(v[0]), m.ref(v[1]), m.ref(v[2]), m.ref(v[3])) < 0)
                    std::swap(v[2], v[3]);
                if (orient3d(m.ref(v[0]), m.ref(v[1]), m.ref(v[2]), m.ref(v[3])) > 0 &&
                    orient3d(m.pos(v[0]), m.pos(v[1]), m.pos(v[2]), m.pos(v[3])) > 0)
                    return v;
            }
        }
        return std::nullopt;
    }

    /// Whether each node of q other than a and b is in a tet without edge (a, b): the collapse
    /// removes the edge's tets, and a node with no other would be left in none.
    bool keepsTetsWithout(const Tet& q, int a, int b) const {
        return std::all_of(q.begin(), q.end(), [&](int c) {
            return c == a || c == b || std::any_of(m.nodeTets(c).begin(), m.nodeTets(c).end(), [&](int u) {
                       return !(contains(m.tet(u), a) && contains(m.tet(u), b));
                   });
        });
    }

    /// Collapses edge (a, b) into a (b disappears) if a placement is allowed (see the header).
    /// With `pit` >= 0, the slot of the tet that fills a pit at the edge (collapseThroughPit):
    /// the volume kept is the mesh's without it.
    bool tryCollapse(int a, int b, bool isShort, bool coarsen = false, int pit = -1) {
        if (!editable.count(a) || !editable.count(b) || !alive(a) || !alive(b))
            return false;
        if (o.fillPits && isShort && pit < 0 && !linkCondition(a, b))
            return collapseThroughPit(a, b, coarsen);
        std::vector<int> tetsA(m.nodeTets(a).begin(), m.nodeTets(a).end());
        std::vector<int> tetsB(m.nodeTets(b).begin(), m.nodeTets(b).end());
        std::vector<int> shell;
        for (int t : tetsA)
            if (std::find(tetsB.begin(), tetsB.end(), t) != tetsB.end())
                shell.push_back(t);
        if (shell.empty())
            return false;
        // The union of both stars before, and the tets that remain, with b -> a.
        std::vector<Tet> before, after;
        double volumeBefore = 0, worstBefore = 1;
        for (int t : tetsA) {
            before.push_back(m.tet(t));
            if (t != pit) {  // (a pit's filling tet is no part of the mesh's volume)
                volumeBefore += m.referenceVolume(t);
                worstBefore = std::min(worstBefore, tetRatio(t));
            }
            if (std::find(shell.begin(), shell.end(), t) == shell.end())
                after.push_back(m.tet(t));
        }
        for (int t : tetsB)
            if (std::find(shell.begin(), shell.end(), t) == shell.end()) {
                before.push_back(m.tet(t));
                volumeBefore += m.referenceVolume(t);
                worstBefore = std::min(worstBefore, tetRatio(t));
                Tet q = m.tet(t);
                for (int& v : q)
                    if (v == b)
                        v = a;
                after.push_back(q);
            }
        // The sides of a glued crack through the stars: the placement keeps the volume of each
        // (else the crack would move tissue from one side to the other). Tets of `after` keep
        // the side of the tet they come from (`before` holds tetsA, then tetsB outside the
        // shell, in the order `after` takes them).
        int sideCount = 1;
        std::vector<int> afterSide;
        double sideBefore = 0;
        if (!crack.empty()) {
            const std::vector<int> side = sidesOf(before, sideCount);
            for (std::size_t i = 0; i < before.size(); ++i) {
                if (side[i] == 0)
                    sideBefore += tetVolume(m, before[i]);
                const bool inShell = i < tetsA.size() && std::find(shell.begin(), shell.end(), tetsA[i]) != shell.end();
                if (!inShell)
                    afterSide.push_back(side[i]);
            }
        }
        // Old boundary around a and b (for the deviation checks).
        std::vector<Face> oldBoundary = boundaryFacesAt(before, a);
        const bool boundaryA = !oldBoundary.empty();
        const std::vector<Face> facesB = boundaryFacesAt(before, b);
        const bool boundaryB = !facesB.empty();
        oldBoundary.insert(oldBoundary.end(), facesB.begin(), facesB.end());
        const bool boundary = boundaryA || boundaryB;
        // A glued crack's end nearer to the cuts: the merged node goes no farther from them.
        std::optional<Vec3> crackEnd;
        for (const Face& f : oldBoundary)
            if (f.crack && o.cutDistance)
                for (int x : {a, b})
                    if (std::find(f.nodes.begin(), f.nodes.end(), x) != f.nodes.end() &&
                        (!crackEnd || o.cutDistance(m.ref(x)) < o.cutDistance(*crackEnd)))
                        crackEnd = m.ref(x);
        // Only on the mesh's boundary does the merged node's place change the volume (around
        // a glued crack the tets on both sides fill the same space wherever it goes).
        const bool outer = anyOuter(oldBoundary);
        const double edgeScale = meanEdgeOf(oldBoundary);
        const double tolerance = o.maxDeviation * edgeScale;
        std::vector<int> boundaryEnds;
        if (boundaryA)
            boundaryEnds.push_back(a);
        if (boundaryB)
            boundaryEnds.push_back(b);
        const bool pure = bodyOnly(boundaryEnds, edgeScale);

        // The overlap guard (boundary collapses): b's tets are replaced, b is gone.
        const GuardEdge guardScope(*this, b, -1);
        // (Only on the mesh's boundary: a star closed all round, glued crack faces included,
        // fills the same space wherever its node goes.)
        std::vector<Tet> beforeWithoutPit;
        if (pit >= 0) {
            beforeWithoutPit = before;
            beforeWithoutPit.erase(std::find(beforeWithoutPit.begin(), beforeWithoutPit.end(), m.tet(pit)));
        }
        OverlapGuard guard(*this, pit >= 0 ? beforeWithoutPit : before, after, a, outer && o.overlapGuard);
        Placement best;
        std::vector<Placement> candidates;
        const Vec3 pa = m.ref(a), pb = m.ref(b);
        // Candidates: either end or the midpoint; on the boundary only those on the old
        // boundary (an end on it, the midpoint of a boundary edge).
        bool edgeOnBoundary = false;
        for (const Face& f : oldBoundary) {
            const bool hasA = std::find(f.nodes.begin(), f.nodes.end(), a) != f.nodes.end();
            const bool hasB = std::find(f.nodes.begin(), f.nodes.end(), b) != f.nodes.end();
            edgeOnBoundary = edgeOnBoundary || (hasA && hasB);
        }
        std::vector<Vec3> starts;
        if (!boundary || boundaryA)
            starts.push_back(pa);
        if (!boundary || boundaryB)
            starts.push_back(pb);
        if (!boundary || edgeOnBoundary)
            starts.push_back(0.5 * (pa + pb));
        for (const Vec3& p0 : starts) {
            // The volume of `after` is affine in the merged node's position, with gradient g.
            // On the boundary, the node goes to the point of the old boundary nearest to p0
            // where the volume is what it was: it stays on the body's surface (or the cut
            // surface) and the volume is kept. Inside the mesh the stars fill the same space
            // wherever the node is: nothing to correct.
            double volume = 0;
            Vec3 gradient = Vec3::Zero();
            for (const Tet& q : after) {
                Vec3 g;
                volume += volumeAndGradient(m, q, a, p0, g);
                gradient += g;
            }
            Vec3 p = p0;
            const double scale = std::abs(volumeBefore) + 1e-300;
            bool offSurface = false;
            // The volume of side 0 of a glued crack, with a at x, and its gradient.
            const auto sideVolume = [&](const Vec3& x, Vec3* grad) {
                double v = 0;
                Vec3 g = Vec3::Zero();
                for (std::size_t i = 0; i < after.size(); ++i)
                    if (afterSide[i] == 0) {
                        Vec3 gi;
                        v += volumeAndGradient(m, after[i], a, x, gi);
                        g += gi;
                    }
                if (grad)
                    *grad = g;
                return v;
            };
            if (sideCount > 2)
                continue;  // three sides or more (cracks meeting): no placement keeps them all
            if (sideCount == 2 && outer) {
                // A rim (the crack meets the body's surface): the body's volume and each
                // side's, both affine in the position: the nearest point to p0 keeping both.
                Vec3 gs;
                const double v = sideVolume(p0, &gs);
                const double r1 = volumeBefore - volume, r2 = sideBefore - v;
                const double a11 = gradient.dot(gradient), a12 = gradient.dot(gs), a22 = gs.dot(gs);
                const double det = a11 * a22 - a12 * a12;
                if (!(det > 1e-12 * a11 * a22))
                    continue;
                const double l1 = (a22 * r1 - a12 * r2) / det, l2 = (a11 * r2 - a12 * r1) / det;
                p = p0 + l1 * gradient + l2 * gs;
                offSurface = true;  // (within maxDeviation of the old boundary: checked below)
            } else if (sideCount == 2 && !outer) {
                Vec3 g;
                const double v = sideVolume(p0, &g);
                if (std::abs(sideBefore - v) > 1e-15 * scale) {
                    const std::optional<Vec3> q = onBoundaryWithVolume(oldBoundary, g, p0, sideBefore - v);
                    if (!q)
                        continue;
                    p = *q;
                }
            }
            if (outer && sideCount != 2 && std::abs(volumeBefore - volume) > 1e-15 * scale) {
                const std::optional<Vec3> q = onBoundaryWithVolume(oldBoundary, gradient, p0, volumeBefore - volume);
                if (q) {
                    p = *q;
                } else if (!o.offSurface || (coarsen && !isShort) || pure) {
                    continue;  // (coarsening, being optional, and the body's surface keep to the old boundary)
                } else {
                    // No point of the old boundary has the volume: along the gradient, within
                    // maxDeviation of the old boundary (checked below).
                    p = p0 + gradient * ((volumeBefore - volume) / gradient.squaredNorm());
                    offSurface = true;
                }
            }
            if (!p.allFinite() || misplaced({a, b}, p) || (boundary && leavesBody(p0, p, pure, edgeScale)))
                continue;
            if (sideCount == 2 && std::abs(sideVolume(p, nullptr) - sideBefore) > 1e-12 * scale)
                continue;
            if (crackEnd && drifts(*crackEnd, p))
                continue;
            if (o.maxEdge > 0 && !isShort) {
                // Coarsening stops where edges would grow too long.
                double longest = 0;
                for (const Tet& q : after)
                    for (int v : q)
                        if (v != a)
                            longest = std::max(longest, (m.ref(v) - p).norm());
                if (longest > o.maxEdge)
                    continue;
            }
            bool ok = true;
            double worst = 1;
            for (const Tet& q : after) {
                if (!positiveWith(m, q, a, p, false)) {
                    ok = false;
                    break;
                }
                worst = std::min(worst, ratioWith(m, q, a, p));
            }
            if (!ok)
                continue;
            if (boundary) {
                // The nodes that were on the boundary stay near the new one.
                const std::vector<Face> newBoundary = boundaryFacesAt(after, a, b, a);
                if ((offSurface && distanceTo(p, oldBoundary, -2, Vec3::Zero()) > tolerance) || (boundaryA && distanceTo(pa, newBoundary, a, p) > tolerance) ||
                    (boundaryB && distanceTo(pb, newBoundary, a, p) > tolerance))
                    continue;
            }
            Placement cand;
            cand.ref = p;
            mapToCurrent(before, p, cand.pos, cand.vel);
            if (!allPositive(after, a, cand.pos, true))
                continue;
            cand.worst = worst;
            candidates.push_back(cand);
        }
        // The best candidate the overlap guard allows (the guard last: it costs the most, and
        // most collapses of bad tets' edges end here, their best placement not good enough).
        std::stable_sort(candidates.begin(), candidates.end(), [](const Placement& x, const Placement& y) { return x.worst > y.worst; });
        if (candidates.empty() || (!isShort && !(coarsen ? candidates.front().worst >= std::min(o.badRatio, worstBefore)
                                                         : candidates.front().worst > worstBefore)))
            return false;  // (as below: no placement is acceptable)
        for (const Placement& cand : candidates)
            if (!guard.refuses(cand.ref)) {
                best = cand;
                break;
            }
        if (best.worst < 0)
            return false;
        // An edge below floorEdge goes even if the tets around it get worse, down to floorRatio.
        const bool critical = isShort && (pa - pb).norm() < o.floorEdge && best.worst >= o.floorRatio;
        const auto acceptable = [&](double worst) {
            return isShort || coarsen ? worst >= std::min(o.badRatio, worstBefore) || critical : worst > worstBefore;
        };
        bool accept = acceptable(best.worst);
        if (!accept && isShort) {
            // The merged node smoothed among the tets that remain, from the best placement.
            const Vec3 keepRef = m.ref(a), keepPos = m.pos(a);
            m.setNodePosition(a, best.ref, best.pos);
            // (b's crack faces as a's for the while: the merged node's sides are those of
            // `after`, else smoothing would take a crack node for an inner one and bend it.)
            std::vector<std::pair<TriKey, TriKey>> renamed;
            if (!crack.empty()) {
                for (int t : tetsB)
                    for (const auto& lf : kTetFaces) {
                        const Tet& q = m.tet(t);
                        const Tri f{q[lf[0]], q[lf[1]], q[lf[2]]};
                        if (std::find(f.begin(), f.end(), b) == f.end() || std::find(f.begin(), f.end(), a) != f.end() ||
                            !crack.count(TriKey::of(f)))
                            continue;
                        const TriKey to = TriKey::of(f[0] == b ? a : f[0], f[1] == b ? a : f[1], f[2] == b ? a : f[2]);
                        if (std::none_of(renamed.begin(), renamed.end(), [&](const auto& r) { return r.first == TriKey::of(f); }))
                            renamed.emplace_back(TriKey::of(f), to);
                    }
                for (const auto& [from, to] : renamed) {
                    crack.erase(from);
                    crack.insert(to);
                }
            }
            const std::optional<Vec3> x = bestPosition(a, after, best.worst);
            for (const auto& [from, to] : renamed) {
                crack.erase(to);
                crack.insert(from);
            }
            m.setNodePosition(a, keepRef, keepPos);
            if (x) {
                Placement cand;
                cand.ref = *x;
                cand.worst = worstAround(after, a, *x);
                mapToCurrent(before, *x, cand.pos, cand.vel);
                bool ok = acceptable(cand.worst) && !misplaced({a, b}, *x) && allPositive(after, a, *x) && allPositive(after, a, cand.pos, true);
                if (ok && boundary) {
                    const std::vector<Face> newBoundary = boundaryFacesAt(after, a, b, a);
                    ok = !(boundaryA && distanceTo(pa, newBoundary, a, *x) > tolerance) &&
                         !(boundaryB && distanceTo(pb, newBoundary, a, *x) > tolerance);
                }
                if (ok) {
                    best = cand;
                    accept = true;
                }
            }
        }
        // The link condition last: it holds for most edges, and most placements are refused.
        if (!accept || !linkCondition(a, b))
            return false;
        // A glued crack keeps separating what it separated: the merged node has as many sides
        // as the more of its ends had, except on a crack that ends inside the tissue somewhere
        // (crackHasFront). There the walls may meet at the node (the crack's border moves to
        // it), which cannot join two pieces; a crack without a front may be all that separates
        // them.
        if (!crack.empty() && (boundaryA || boundaryB)) {
            const int sa = sectorCount(a), sb = sectorCount(b);
            if (sectorsOf(after, a, b, a) < std::max(sa, sb) && !crackHasFront(a) && !crackHasFront(b))
                return false;
        }
        applyCollapse(a, b, shell, tetsB, best);
        return true;
    }

    void removeTet(int t) {
        tetOrigin.remove(t, m.tetCount());
        forget(t);
        forget(m.tetCount() - 1);  // the last tet takes slot t
        m.removeTet(t);
        ++r.removedTets;
    }

    void applyCollapse(int a, int b, std::vector<int> shell, const std::vector<int>& tetsB, const Placement& at) {
        if (!crack.empty()) {
            // b's crack faces become a's; those with both vanish with the shell.
            std::vector<TriKey> renamed;
            for (int t : tetsB)
                for (const auto& lf : kTetFaces) {
                    const Tet& q = m.tet(t);
                    const Tri f{q[lf[0]], q[lf[1]], q[lf[2]]};
                    if (std::find(f.begin(), f.end(), b) == f.end() || !crack.erase(TriKey::of(f)))
                        continue;
                    if (std::find(f.begin(), f.end(), a) == f.end())
                        renamed.push_back(TriKey::of(f[0] == b ? a : f[0], f[1] == b ? a : f[1], f[2] == b ? a : f[2]));
                }
            crack.insert(renamed.begin(), renamed.end());
        }
        if (const auto it = spares.find(b); it != spares.end()) {
            std::vector<int> moving = std::move(it->second);
            spares.erase(it);
            spares[a].insert(spares[a].end(), moving.begin(), moving.end());
        }
        for (int t : tetsB)
            if (std::find(shell.begin(), shell.end(), t) == shell.end()) {
                Tet q = m.tet(t);
                for (int& v : q)
                    if (v == b)
                        v = a;
                forget(t);
                m.replaceTet(t, q);
            }
        // Highest first: the last tet, which takes a freed slot, is then never in the shell.
        std::sort(shell.rbegin(), shell.rend());
        for (int t : shell)
            touched.insert(m.tet(t).begin(), m.tet(t).end());
        for (int t : shell)
            removeTet(t);
        mergedInto[b] = a;
        if (anchored.count(b))
            anchored.insert(a);  // (a free node merged with an anchored one, in keepOut)
        cutMarkOf[a] = onCut(a) || onCut(b);
        moved.erase(b);
        touched.erase(b);
        moveNode(a, at.ref, at.pos, at.vel);
        ++r.collapses;
    }

    void collapseSweep() {
        struct Candidate {
            double length;
            int a, b;
            bool isShort, coarsen;
        };
        std::vector<Candidate> candidates;
        std::unordered_set<std::uint64_t> seen;
        for (int n : nodes) {
            if (!alive(n))
                continue;
            for (int t : m.nodeTets(n)) {
                const Tet& q = m.tet(t);
                const bool bad = tetRatio(t) < o.badRatio;
                for (const auto& e : kTetEdges) {
                    const int a = q[e[0]], b = q[e[1]];
                    if (!editable.count(a) || !editable.count(b))
                        continue;
                    const double length = (m.ref(a) - m.ref(b)).norm();
                    const bool isShort = length < o.shortEdge;
                    const bool coarsen = length < o.coarsenEdge;
                    if ((isShort || coarsen || bad) && seen.insert(linkEdge(a, b)).second)
                        candidates.push_back({length, std::min(a, b), std::max(a, b), isShort, coarsen});
                }
            }
        }
        std::sort(candidates.begin(), candidates.end(),
                  [](const Candidate& x, const Candidate& y) { return x.length < y.length; });
        for (const Candidate& c : candidates) {
            if (!alive(c.a) || !alive(c.b))
                continue;
            tryCollapse(c.a, c.b, c.isShort, c.coarsen);
        }
    }

    // --- flips (2-3 and 3-2): the tets change, the nodes stay; the union of the tets, and so
    // the boundary and the volume, is the same before and after ---

    /// The tet with these nodes (any order), or -1.
    int findTet(const Tet& nodes) const {
        for (int t : m.nodeTets(nodes[0])) {
            const Tet& q = m.tet(t);
            bool all = true;
            for (int v : nodes)
                all = all && std::find(q.begin(), q.end(), v) != q.end();
            if (all)
                return t;
        }
        return -1;
    }

    bool flippableTet(const Tet& q) const {
        for (int v : q)
            if (!flippable.count(v) || !alive(v))
                return false;
        return true;
    }

    /// q with node `from` replaced by `to`.
    static Tet replaced(Tet q, int from, int to) {
        for (int& v : q)
            if (v == from)
                v = to;
        return q;
    }

    /// The new tets are allowed: positive in both configurations (exact), and better than the
    /// old ones' worst.
    bool better(const std::vector<Tet>& created, double worstOld) const {
        double worst = 1;
        for (const Tet& q : created) {
            if (orient3d(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3])) <= 0 ||
                orient3d(m.pos(q[0]), m.pos(q[1]), m.pos(q[2]), m.pos(q[3])) <= 0)
                return false;
            worst = std::min(worst, radiusRatio(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3])));
        }
        return worst > worstOld * (1 + 1e-9) + 1e-12;
    }

    void replaceTets(const std::vector<int>& old, const std::vector<Tet>& created) {
        for (const Tet& q : created)
            touched.insert(q.begin(), q.end());
        std::vector<int> slots = old;
        std::sort(slots.rbegin(), slots.rend());  // highest first (removal moves the last tet)
        const std::size_t common = std::min(slots.size(), created.size());
        for (std::size_t i = 0; i < common; ++i) {
            forget(slots[i]);
            m.replaceTet(slots[i], created[i]);
            tetOrigin.set(slots[i], -1);
        }
        for (std::size_t i = common; i < created.size(); ++i) {
            tetOrigin.set(m.tetCount(), -1);
            forget(m.tetCount());
            m.addTet(created[i]);
        }
        for (std::size_t i = common; i < slots.size(); ++i)
            removeTet(slots[i]);
    }

    /// 2-3 flip of the face of tet t opposite its corner `apexIndex`, if that face is shared.
    bool tryFlip23(int t, int apexIndex) {
        const Tet q1 = m.tet(t);
        const int d = q1[apexIndex];
        int t2 = -1, e = -1;
        // The other tet with the face's three nodes.
        const int a = q1[(apexIndex + 1) % 4], b = q1[(apexIndex + 2) % 4], c = q1[(apexIndex + 3) % 4];
        for (int u : m.nodeTets(a)) {
            if (u == t)
                continue;
            const Tet& q = m.tet(u);
            if (std::find(q.begin(), q.end(), b) != q.end() && std::find(q.begin(), q.end(), c) != q.end()) {
                t2 = u;
                for (int v : q)
                    if (v != a && v != b && v != c)
                        e = v;
                break;
            }
        }
        if (t2 < 0 || e < 0 || !flippableTet(m.tet(t2)) || isCrack({a, b, c}))
            return false;
        // The new edge d-e must not exist already.
        for (int u : m.nodeTets(d)) {
            const Tet& q = m.tet(u);
            if (std::find(q.begin(), q.end(), e) != q.end())
                return false;
        }
        const double worstOld = std::min(tetRatio(t), tetRatio(t2));
        const std::vector<Tet> created{replaced(q1, a, e), replaced(q1, b, e), replaced(q1, c, e)};
        if (!better(created, worstOld))
            return false;
        replaceTets({t, t2}, created);
        ++r.flips;
        return true;
    }

    /// Edge removal (Shewchuk; the 3-2 flip for three tets): the n tets (3 <= n <= 7) around
    /// the interior edge (p, q), whose other nodes form a closed ring, are replaced by the
    /// 2 (n - 2) tets joining p and q to the triangles of the ring polygon's best triangulation
    /// (dynamic programming over the triangulations for the largest smallest radius ratio).
    bool tryEdgeRemoval(int p, int q) {
        std::vector<int> ring;
        for (int u : m.nodeTets(p)) {
            const Tet& x = m.tet(u);
            if (std::find(x.begin(), x.end(), q) != x.end())
                ring.push_back(u);
        }
        const int n = static_cast<int>(ring.size());
        if (n < 3 || n > 7)
            return false;
        // The ring of other nodes, in order: each ring tet holds two consecutive ones.
        std::vector<std::array<int, 2>> pairs;
        for (int u : ring) {
            if (!flippableTet(m.tet(u)))
                return false;
            std::array<int, 2> pr{-1, -1};
            int k = 0;
            for (int v : m.tet(u))
                if (v != p && v != q)
                    pr[k++] = v;
            if (isCrack({p, q, pr[0]}) || isCrack({p, q, pr[1]}))
                return false;  // an edge of a glued crack: removing it would remove the crack's faces
            pairs.push_back(pr);
        }
        std::vector<int> polygon{pairs[0][0], pairs[0][1]};
        std::vector<char> used(n, 0);
        used[0] = 1;
        for (int step = 1; step < n; ++step) {
            const int last = polygon.back();
            int next = -1;
            for (int i = 0; i < n && next < 0; ++i)
                if (!used[i] && (pairs[i][0] == last || pairs[i][1] == last)) {
                    used[i] = 1;
                    next = pairs[i][0] == last ? pairs[i][1] : pairs[i][0];
                }
            if (next < 0)
                return false;  // an open ring: the edge is on the boundary
            polygon.push_back(next);
        }
        if (polygon.back() != polygon.front())
            return false;
        polygon.pop_back();
        {
            std::vector<int> sorted = polygon;
            std::sort(sorted.begin(), sorted.end());
            if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
                return false;
        }
        // Orientation: with orient3d(p, q, v0, v1) < 0, the new tets (vi, vj, vk, p) and
        // (vj, vi, vk, q) are positive for i < j < k.
        if (orient3d(m.ref(p), m.ref(q), m.ref(polygon[0]), m.ref(polygon[1])) > 0)
            std::reverse(polygon.begin(), polygon.end());
        const auto connected = [&](int u, int v) {
            for (int t : m.nodeTets(u)) {
                const Tet& x = m.tet(t);
                if (std::find(x.begin(), x.end(), v) != x.end())
                    return true;
            }
            return false;
        };
        const auto faceExists = [&](int u, int v, int w) {
            for (int t : m.nodeTets(u)) {
                const Tet& x = m.tet(t);
                if (std::find(x.begin(), x.end(), v) != x.end() && std::find(x.begin(), x.end(), w) != x.end())
                    return true;
            }
            return false;
        };
        constexpr double kInvalid = -1;
        const auto quality = [&](int i, int j, int k) {
            const int vi = polygon[i], vj = polygon[j], vk = polygon[k];
            // Diagonals (not ring edges) must be new, and so must the triangle.
            const auto diagonal = [&](int x, int y) { return (y - x) != 1 && !(x == 0 && y == n - 1); };
            if ((diagonal(i, j) && connected(vi, vj)) || (diagonal(j, k) && connected(vj, vk)) ||
                (diagonal(i, k) && connected(vi, vk)) || faceExists(vi, vj, vk))
                return kInvalid;
            const Tet up{vi, vj, vk, p}, down{vj, vi, vk, q};
            double worst = 1;
            for (const Tet& x : {up, down}) {
                if (orient3d(m.ref(x[0]), m.ref(x[1]), m.ref(x[2]), m.ref(x[3])) <= 0 ||
                    orient3d(m.pos(x[0]), m.pos(x[1]), m.pos(x[2]), m.pos(x[3])) <= 0)
                    return kInvalid;
                worst = std::min(worst, radiusRatio(m.ref(x[0]), m.ref(x[1]), m.ref(x[2]), m.ref(x[3])));
            }
            return worst;
        };
        double best[7][7];
        int split[7][7];
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < n; ++k) {
                best[i][k] = k == i + 1 ? 2.0 : kInvalid;
                split[i][k] = -1;
            }
        for (int len = 2; len < n; ++len)
            for (int i = 0; i + len < n; ++i) {
                const int k = i + len;
                for (int j = i + 1; j < k; ++j) {
                    const double v = std::min({best[i][j], best[j][k], quality(i, j, k)});
                    if (v > best[i][k]) {
                        best[i][k] = v;
                        split[i][k] = j;
                    }
                }
            }
        double worstOld = 1;
        for (int u : ring)
            worstOld = std::min(worstOld, tetRatio(u));
        if (!(best[0][n - 1] > worstOld * (1 + 1e-9) + 1e-12))
            return false;
        std::vector<Tet> created;
        std::vector<std::array<int, 2>> stack{{0, n - 1}};
        while (!stack.empty()) {
            const auto [i, k] = stack.back();
            stack.pop_back();
            if (k - i < 2)
                continue;
            const int j = split[i][k];
            created.push_back({polygon[i], polygon[j], polygon[k], p});
            created.push_back({polygon[j], polygon[i], polygon[k], q});
            stack.push_back({i, j});
            stack.push_back({j, k});
        }
        replaceTets(ring, created);
        ++r.flips;
        return true;
    }

    /// The bad tets around `around` whose nodes are all in the region, by their nodes (indices
    /// change as tets are replaced).
    std::vector<Tet> badTetsAround(const std::vector<int>& around) const {
        std::vector<Tet> bad;
        std::unordered_set<int> seen;
        for (int n : around) {
            if (!alive(n))
                continue;
            for (int t : m.nodeTets(n))
                if (seen.insert(t).second && tetRatio(t) < o.badRatio && flippableTet(m.tet(t)))
                    bad.push_back(m.tet(t));
        }
        return bad;
    }

    void flipSweep() {
        std::vector<int> around = nodes;
        around.insert(around.end(), fixedInRegion.begin(), fixedInRegion.end());
        for (const Tet& nodesOfBad : badTetsAround(around)) {
            const int t = findTet(nodesOfBad);
            if (t < 0)
                continue;
            bool flipped = false;
            for (const auto& e : kTetEdges)
                if (!flipped && tryEdgeRemoval(m.tet(t)[e[0]], m.tet(t)[e[1]]))
                    flipped = true;
            for (int i = 0; i < 4 && !flipped; ++i)
                flipped = tryFlip23(t, i);
        }
    }

    // --- edge split (vertex insertion) ---

    /// Splits an edge of tet t, longest first, at a new node where smoothing puts it among the
    /// tets the split makes, if that raises the worst tet around the edge by kSplitGain. The
    /// new node starts at the edge's midpoint: the split tets fill exactly the space of the old
    /// ones, on the boundary the new node lies on the old boundary, and its placement keeps
    /// the volume as smoothing does. Halves shorter than twice shortEdge or coarsenEdge are
    /// not made (the collapses would undo them).
    bool trySplit(int t) {
        const Tet q = m.tet(t);
        std::array<int, 6> order{0, 1, 2, 3, 4, 5};
        const auto length = [&](int e) { return (m.ref(q[kTetEdges[e][0]]) - m.ref(q[kTetEdges[e][1]])).norm(); };
        std::sort(order.begin(), order.end(), [&](int x, int y) { return length(x) > length(y); });
        std::vector<int> ring;
        for (int k = 0; k < kSplitEdges; ++k) {
            const int a = q[kTetEdges[order[k]][0]], b = q[kTetEdges[order[k]][1]];
            if (length(order[k]) < 2 * std::max(o.shortEdge, o.coarsenEdge))
                return false;
            m.edgeTets(a, b, ring);
            double worstBefore = 2;
            std::vector<Tet> children;
            bool inRegion = true;
            for (int u : ring) {
                inRegion = inRegion && flippableTet(m.tet(u));
                worstBefore = std::min(worstBefore, tetRatio(u));
                for (int v : m.tet(u))
                    if (v != a && v != b && isCrack({a, b, v}))
                        inRegion = false;  // an edge of a glued crack stays whole
            }
            if (!inRegion)
                continue;
            const Vec3 mid = 0.5 * (m.ref(a) + m.ref(b));
            if (keptOut(mid))
                continue;
            // A split point of the body's surface alone starts on it (the midpoint of a chord
            // from a rim node that went into the body does not).
            if (o.body && !(onCut(a) && onCut(b)) && isBoundaryEdge(m, a, b) &&
                leavesBody(mid, mid, true, length(order[k])))
                continue;
            const int v = m.addNode(mid, 0.5 * (m.pos(a) + m.pos(b)));
            cutMarkOf[v] = onCut(a) && onCut(b);
            m.velocities()[v] = 0.5 * (m.velocities()[a] + m.velocities()[b]);
            std::vector<Tet> old;
            for (int u : ring) {
                old.push_back(m.tet(u));
                children.push_back(replaced(m.tet(u), b, v));
                children.push_back(replaced(m.tet(u), a, v));
            }
            const GuardEdge guardScope(*this, a, b);
            const double worstAtMid = worstAround(children, v, mid);
            Vec3 x = mid;
            if (const std::optional<Vec3> better = bestPosition(v, children, worstAtMid))
                x = *better;
            const double worstAfter = worstAround(children, v, x);
            Vec3 pos = m.pos(v), vel = m.velocities()[v];
            mapToCurrent(old, x, pos, vel);
            // Nor may the new node lie outside the body. The midpoint of a chord between two
            // nodes of a cut's rim can, where the body's surface between them is concave, and
            // bestPosition checks where it moves the node, not where it starts (polyp, stroke
            // rows' seed 15, pass 15: 0.022 mean edges outside).
            if (!(worstAfter > worstBefore + kSplitGain && allPositive(children, v, x) && allPositive(children, v, pos, true)) ||
                leavesBody(x, x, false, length(order[k]))) {
                m.removeNode(v);  // the last node, in no tet yet
                cutMarkOf.erase(v);
                continue;
            }
            replaceTets(ring, children);
            moveNode(v, x, pos, vel);
            editable.insert(v);
            flippable.insert(v);
            nodes.push_back(v);
            ++r.splits;
            return true;
        }
        return false;
    }

    void splitSweep() {
        for (const Tet& nodesOfBad : badTetsAround(nodes))
            if (const int t = findTet(nodesOfBad); t >= 0 && tetRatio(t) < o.badRatio)
                trySplit(t);
    }

    // --- smoothing ---
    double worstAround(const std::vector<Tet>& star, int v, const Vec3& p, int* worstIndex = nullptr) const {
        double worst = 2;
        for (std::size_t i = 0; i < star.size(); ++i) {
            const double q = ratioWith(m, star[i], v, p);
            if (q < worst) {
                worst = q;
                if (worstIndex)
                    *worstIndex = static_cast<int>(i);
            }
        }
        return worst;
    }

    /// Whether every tet of `star` is positive with node v at p (reference positions, or with
    /// `current` the deformed ones).
    bool allPositive(const std::vector<Tet>& star, int v, const Vec3& p, bool current = false) const {
        for (const Tet& q : star)
            if (!positiveWith(m, q, v, p, current))
                return false;
        return true;
    }

    // --- overlap guard ---
    // Where the walls of a crack are not glued (their triangulations differ, cracks meet, or
    // the pass runs unglued), a boundary node moved on its own can go into the tissue on the
    // other side, or bring the other side into its tets. The guard measures that in reference
    // positions and refuses a placement that makes it deeper than it was.

    /// Tets and nodes near the tets `star` (within `margin` of their box, reference positions)
    /// that the star does not replace (those at v, and see guardEdge): the cutter's grid's
    /// (registered by current positions at the start of the pass) and those the pass changed or
    /// moved (in changed slots, at touched nodes); without a grid, those at the region's nodes.
    /// Corners and boxes are taken once; a placement the guard checks stays in `box`.
    struct Nearby {
        Eigen::AlignedBox3d box;
        std::vector<Tet> tets;
        std::vector<std::array<Vec3, 4>> corners;
        std::vector<Eigen::AlignedBox3d> boxes;
        std::vector<int> nodes;
        /// A grid over `box` (at most kCells cells along an axis): per cell the tets (indices
        /// into `tets`) whose box reaches into it and the nodes in it, so that intrusion() looks
        /// at what is near each point and tet only (it looked at all of them: a third of a small
        /// mesh each time). Each cell's list is a range of one array (cell c: [start[c],
        /// start[c + 1])): a vector per cell cost an allocation per cell and guard, and the guard
        /// is most of the improvement's time where crack walls are not glued.
        static constexpr int kCells = 8;
        UniformCells cells;
        std::vector<int> tetStart, tetItems, nodeStart, nodeItems;
        void buildGrid(const TetMesh& m) {
            const double size = (box.max() - box.min()).maxCoeff() / kCells;
            cells = UniformCells(box.min(), box.max(), std::max(size, 1e-300), kCells);
            fill(tetStart, tetItems, boxes.size(), [&](std::size_t t, const auto& add) { forEachCell(boxes[t], add); });
            fill(nodeStart, nodeItems, nodes.size(),
                 [&](std::size_t i, const auto& add) { add(cells.index(cells.of(m.ref(nodes[i])))); });
        }
        /// Lists each item i (below count) in the cells that cellsOf(i, add) passes to add, in
        /// the order of i within a cell: counts, then places.
        template <class F>
        void fill(std::vector<int>& start, std::vector<int>& items, std::size_t count, F cellsOf) const {
            const auto n = static_cast<std::size_t>(cells.count());
            start.assign(n + 1, 0);
            for (std::size_t i = 0; i < count; ++i)
                cellsOf(i, [&](std::int64_t c) { ++start[static_cast<std::size_t>(c) + 1]; });
            for (std::size_t c = 0; c < n; ++c)
                start[c + 1] += start[c];
            items.resize(static_cast<std::size_t>(start[n]));
            std::vector<int> next(start.begin(), start.end() - 1);
            for (std::size_t i = 0; i < count; ++i)
                cellsOf(i, [&](std::int64_t c) { items[static_cast<std::size_t>(next[static_cast<std::size_t>(c)]++)] = static_cast<int>(i); });
        }
        template <class F>
        void forEachCell(const Eigen::AlignedBox3d& b, F f) const {
            const Eigen::Array3i lo = cells.of(b.min()), hi = cells.of(b.max());
            for (int z = lo.z(); z <= hi.z(); ++z)
                for (int y = lo.y(); y <= hi.y(); ++y)
                    for (int x = lo.x(); x <= hi.x(); ++x)
                        f(cells.index({x, y, z}));
        }
        /// The tets whose box may contain x (x in `box`; each once).
        std::span<const int> tetsAt(const Vec3& x) const {
            const auto c = static_cast<std::size_t>(cells.index(cells.of(x)));
            return {tetItems.data() + tetStart[c], tetItems.data() + tetStart[c + 1]};
        }
        /// Calls f for every node that may lie in `b` (each once).
        template <class F>
        void forEachNodeIn(const Eigen::AlignedBox3d& b, F f) const {
            forEachCell(b, [&](std::int64_t c) {
                for (int k = nodeStart[c]; k < nodeStart[c + 1]; ++k)
                    f(nodes[static_cast<std::size_t>(nodeItems[k])]);
            });
        }
    };
    Nearby nearby(const std::vector<Tet>& star, int v, double margin) const {
        Eigen::AlignedBox3d refBox, posBox;
        for (const Tet& q : star)
            for (int u : q) {
                refBox.extend(m.ref(u));
                posBox.extend(m.pos(u));
            }
        const auto padded = [](const Eigen::AlignedBox3d& b, double pad) {
            return Eigen::AlignedBox3d(b.min() - Vec3::Constant(pad), b.max() + Vec3::Constant(pad));
        };
        Nearby n;
        n.box = padded(refBox, margin);
        // The candidates that reach into the box and that the star does not replace, each
        // once: marked per tet slot (IndexMarks, kept per thread across passes, so that it grows
        // with the mesh once and costs what it marks; sorting the hits instead cost a third of
        // the pass where many walls are not glued).
        std::vector<int> hits;
        const auto [ga, gb] = guardEdge;
        thread_local IndexMarks<char> taken;
        const auto scope = taken.use(static_cast<std::size_t>(m.tetCount()));
        const auto consider = [&](int t) {
            if (t < 0 || t >= m.tetCount() || taken[t])
                return;
            taken.set(t, 1);
            const Tet& q = m.tet(t);
            if (contains(q, v) || (ga >= 0 && contains(q, ga) && (gb < 0 || contains(q, gb))))
                return;
            Eigen::AlignedBox3d box;
            for (int u : q)
                box.extend(m.ref(u));
            if (box.intersects(n.box))
                hits.push_back(t);
        };
        const Eigen::AlignedBox3d reach = padded(n.box, std::max(margin, o.maxEdge));
        const auto tetsAt = [&](int u) {
            if (alive(u) && reach.contains(m.ref(u)))
                for (int t : m.nodeTets(u))
                    consider(t);
        };
        if (o.grid && !o.grid->empty()) {
            // The grid holds the tets as they were at the start of the pass; those it may not
            // hold where they are now are in slots that changed (new, or taken by the last tet
            // at a removal) or at nodes whose tets the pass changed.
            std::vector<int> found;
            o.grid->query(padded(posBox, margin), found);
            for (int t : found)
                consider(t);
            tetOrigin.forEachChangedSlot(m.tetCount(), consider);
            for (int u : touched)
                tetsAt(u);
        } else {
            for (int u : nodes)
                tetsAt(u);
        }
        thread_local IndexMarks<char> nodeTaken;
        const auto nodeScope = nodeTaken.use(static_cast<std::size_t>(m.nodeCount()));
        for (int t : hits) {
            const Tet& q = m.tet(t);
            n.tets.push_back(q);
            n.corners.push_back({m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3])});
            Eigen::AlignedBox3d box;
            for (const Vec3& x : n.corners.back())
                box.extend(x);
            n.boxes.push_back(box);
            for (int u : q)
                if (!nodeTaken[u] && n.box.contains(m.ref(u))) {
                    nodeTaken.set(u, 1);
                    n.nodes.push_back(u);
                }
        }
        std::sort(n.nodes.begin(), n.nodes.end());  // (taken once each: sorting the repeats cost a tenth)
        n.buildGrid(m);
        return n;
    }
    static bool contains(const Tet& q, int u) { return u >= 0 && std::find(q.begin(), q.end(), u) != q.end(); }

    /// Whether the tets `star` with node v at p make a hanging node as checkValidity finds them
    /// (hangsOn, exactly): a nearby node on a boundary face of the star at v (on an edge or
    /// inside, not at a corner's position), or v at p on a boundary face of a nearby tet. The
    /// overlap the guard measures is a depth, and a node slid along a flat boundary makes none:
    /// where the walls of a crack are not glued, a rim node moved along the crack's mouth on the
    /// box's flat side left its unglued copy on the moved wall's faces (box, twenty partial
    /// strokes, seed 9, pass 1; issue 16).
    bool hangs(const std::vector<Tet>& star, int v, const Vec3& p, const Nearby& near) const {
        // The star's faces at v that no other tet of the star has: its boundary there.
        std::vector<TriKey> facesAtV;
        for (const Tet& q : star)
            for (const auto& lf : kTetFaces) {
                const Tri f{q[lf[0]], q[lf[1]], q[lf[2]]};
                if (f[0] == v || f[1] == v || f[2] == v)
                    facesAtV.push_back(TriKey::of(f));
            }
        const auto byNodes = [](const TriKey& x, const TriKey& y) { return std::tie(x.a, x.b, x.c) < std::tie(y.a, y.b, y.c); };
        std::sort(facesAtV.begin(), facesAtV.end(), byNodes);
        const auto at = [&](int u) -> const Vec3& { return u == v ? p : m.ref(u); };
        for (std::size_t i = 0; i < facesAtV.size(); ++i) {
            if ((i > 0 && facesAtV[i] == facesAtV[i - 1]) || (i + 1 < facesAtV.size() && facesAtV[i] == facesAtV[i + 1]))
                continue;
            const TriKey& f = facesAtV[i];
            const Vec3 &a = at(f.a), &b = at(f.b), &c = at(f.c);
            Eigen::AlignedBox3d box(a);
            box.extend(b);
            box.extend(c);
            bool found = false;
            near.forEachNodeIn(box, [&](int u) {
                const Vec3& x = m.ref(u);
                if (!found && u != f.a && u != f.b && u != f.c && u != v && box.contains(x))
                    found = hangsOn(x, a, b, c);
            });
            if (found)
                return true;
        }
        // v at p on a face of a nearby tet that is on the boundary (in no other tet).
        if (!near.box.contains(p))
            return false;
        std::vector<int> sharing;
        for (int i : near.tetsAt(p)) {
            if (!near.boxes[i].contains(p))
                continue;
            const Tet& q = near.tets[i];
            const std::array<Vec3, 4>& c = near.corners[i];
            if (p == c[0] || p == c[1] || p == c[2] || p == c[3])
                continue;
            for (const auto& lf : kTetFaces) {
                if (!hangsOn(p, c[lf[0]], c[lf[1]], c[lf[2]]))
                    continue;
                m.faceTets(q[lf[0]], q[lf[1]], q[lf[2]], sharing);
                if (sharing.size() < 2)
                    return true;
            }
        }
        return false;
    }

    /// The longest edge of the tets `star` (reference positions).
    double longestEdge(const std::vector<Tet>& star) const {
        double longest = 0;
        for (const Tet& q : star)
            for (const auto& e : kTetEdges)
                longest = std::max(longest, (m.ref(q[e[0]]) - m.ref(q[e[1]])).norm());
        return longest;
    }

    /// Which pairs intrusion() measures: all, those that move with v (v itself, the tets at v),
    /// or those that do not (the same for every place of v).
    enum class Pairs { All, WithV, WithoutV };
    /// How deep the tets `star` (with their nodes `starNodes`; node v at p) and the mesh `near`
    /// them reach into each other: the deepest of a star node strictly inside a nearby tet, and
    /// of a node strictly inside a star tet it is not a corner of (a nearby node, or a star node
    /// where the star folds over itself; the node a collapse removes, guardEdge, is not counted).
    double intrusion(const std::vector<Tet>& star, const std::vector<int>& starNodes, int v, const Vec3& p,
                     const Nearby& near, Pairs pairs = Pairs::All) const {
        if (pairs != Pairs::WithoutV && !near.box.contains(p))
            return std::numeric_limits<double>::infinity();  // beyond what `near` holds
        const auto [ga, gb] = guardEdge;
        const int gone = gb < 0 ? ga : -1;
        const auto at = [&](int u) -> const Vec3& { return u == v ? p : m.ref(u); };
        const auto measured = [&](bool withV) { return pairs == Pairs::All || withV == (pairs == Pairs::WithV); };
        double deepest = 0;
        for (int u : starNodes) {
            if (!measured(u == v))
                continue;
            const auto inside = [&](int i) {
                if (near.boxes[i].contains(at(u)) && !contains(near.tets[i], u))
                    deepest = std::max(deepest, depthInside(at(u), near.corners[i]));
            };
            if (near.box.contains(at(u))) {
                for (int i : near.tetsAt(at(u)))
                    inside(i);
            } else {  // (the grid covers `box` only)
                for (std::size_t i = 0; i < near.tets.size(); ++i)
                    inside(static_cast<int>(i));
            }
        }
        for (const Tet& q : star) {
            if (!measured(contains(q, v)))
                continue;
            const std::array<Vec3, 4> c = {at(q[0]), at(q[1]), at(q[2]), at(q[3])};
            Eigen::AlignedBox3d box;
            for (const Vec3& x : c)
                box.extend(x);
            near.forEachNodeIn(box, [&](int u) {
                if (u != v && u != gone && !contains(q, u) && box.contains(m.ref(u)))
                    deepest = std::max(deepest, depthInside(m.ref(u), c));
            });
            for (int u : starNodes)
                if (u != v && !contains(q, u) && box.contains(at(u)))
                    deepest = std::max(deepest, depthInside(at(u), c));
        }
        return deepest;
    }

    /// The edge whose tets the star being placed replaces (see intrusion()); {-1, -1}: none.
    mutable std::pair<int, int> guardEdge{-1, -1};
    struct GuardEdge {
        const Pass& pass;
        GuardEdge(const Pass& p, int a, int b) : pass(p) { pass.guardEdge = {a, b}; }
        ~GuardEdge() { pass.guardEdge = {-1, -1}; }
    };

    /// The overlap guard for placing node v (now at its reference position) with the tets
    /// `before` around it as the tets `after`: on first use it measures `before` (intrusion()),
    /// then refuses a placement that makes `after` reach deeper, and deeper than
    /// ImproveOptions::overlapSlack times the longest edge of `before`, or that makes a hanging
    /// node (hangs()).
    class OverlapGuard {
    public:
        OverlapGuard(const Pass& pass, const std::vector<Tet>& before, const std::vector<Tet>& after, int v, bool on)
            : m_pass(pass), m_before(before), m_after(after), m_v(v), m_on(on) {}
        bool refuses(const Vec3& p) {
            if (!m_on)
                return false;
            if (!m_near) {
                const double longest = m_pass.longestEdge(m_before);
                m_near = m_pass.nearby(m_before, m_v, longest);
                const double slack = m_pass.o.overlapSlack * longest;
                m_depth = std::max(m_pass.intrusion(m_before, nodesOf(m_before), m_v, m_pass.m.ref(m_v), *m_near), slack);
                m_afterNodes = nodesOf(m_after);
                m_still = m_pass.intrusion(m_after, m_afterNodes, m_v, p, *m_near, Pairs::WithoutV);
            }
            return m_still > m_depth || m_pass.intrusion(m_after, m_afterNodes, m_v, p, *m_near, Pairs::WithV) > m_depth ||
                   m_pass.hangs(m_after, m_v, p, *m_near);
        }

    private:
        const Pass& m_pass;
        const std::vector<Tet>& m_before;
        const std::vector<Tet>& m_after;
        int m_v;
        bool m_on;
        std::optional<Nearby> m_near;
        double m_depth = 0;
        double m_still = 0;  ///< the pairs of `after` that do not move with v
        std::vector<int> m_afterNodes;
        static std::vector<int> nodesOf(const std::vector<Tet>& tets) {
            std::vector<int> n;
            for (const Tet& q : tets)
                n.insert(n.end(), q.begin(), q.end());
            std::sort(n.begin(), n.end());
            n.erase(std::unique(n.begin(), n.end()), n.end());
            return n;
        }
    };

    bool smoothNode(int v) {
        const std::vector<Tet> star = starOf(v);
        if (star.empty())
            return false;
        double worstNow = 2;  // the star as it is: the tets' own (remembered) ratios
        for (int t : m.nodeTets(v))
            worstNow = std::min(worstNow, tetRatio(t));
        const std::optional<Vec3> x = bestPosition(v, star, worstNow);
        if (!x)
            return false;
        Vec3 pos = m.pos(v), vel = m.velocities()[v];
        mapToCurrent(star, *x, pos, vel);
        if (!allPositive(star, v, pos, true))
            return false;
        moveNode(v, *x, pos, vel);
        ++r.smoothed;
        return true;
    }

    /// Where smoothing would move node v with the tets `star` around it (its star, or the tets
    /// an edge split would make; worstNow: their worst radius ratio as they are); none if
    /// nowhere better.
    std::optional<Vec3> bestPosition(int v, const std::vector<Tet>& star, double worstNow) const {
        const Vec3 x0 = m.ref(v);
        // The node's score: its worst tet against badRatio and its shortest edge against
        // shortEdge, the smaller of the two (1: nothing to improve).
        std::vector<int> neighbours;
        for (const Tet& q : star)
            for (int u : q)
                if (u != v)
                    neighbours.push_back(u);
        std::sort(neighbours.begin(), neighbours.end());
        neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
        // On the boundary, the volume gradient's direction (set below): ascents go across it.
        bool boundary = false;
        Vec3 normal = Vec3::Zero();
        Vec3 rimLine = Vec3::Zero();  // a rim node's line of motion (below), else zero
        // (`known`: the star's worst ratio at p if known, else negative.)
        const auto score = [&](const Vec3& p, Vec3* ascent, double known = -1) {
            int wi = 0;
            // (Both terms are capped at 2: above 1 neither limits the node.)
            const double worstHere = known >= 0 ? known : worstAround(star, v, p, &wi);
            const double ratio = o.badRatio > 0 ? std::min(2.0, worstHere / o.badRatio) : 2.0;
            double edge = 2.0;
            int nearest = -1;
            if (o.shortEdge > 0)
                for (int u : neighbours)
                    if (const double l = (p - m.ref(u)).norm() / o.shortEdge; l < edge) {
                        edge = l;
                        nearest = u;
                    }
            if (ascent) {
                if (ratio <= edge || nearest < 0) {
                    // The gradients (central differences) of the tets within kActiveRatio of the
                    // worst, at most kMaxActive of them, across the volume gradient on the
                    // boundary; the ascent is the point of their convex hull nearest to zero,
                    // the direction that raises them all at once (Klingner & Shewchuk). With
                    // the worst tet's gradient alone, the search stops where two tets tie.
                    std::vector<std::pair<double, int>> near;
                    for (std::size_t i = 0; i < star.size(); ++i)
                        if (const double q = ratioWith(m, star[i], v, p); q <= worstHere + kActiveRatio)
                            near.emplace_back(q, static_cast<int>(i));
                    std::sort(near.begin(), near.end());
                    if (near.empty())
                        near.emplace_back(worstHere, wi);
                    if (near.size() > kMaxActive)
                        near.resize(kMaxActive);
                    std::vector<Vec3> gradients;
                    for (const auto& [q, i] : near) {
                        const double h = 1e-4 * (m.ref(star[i][0]) - m.ref(star[i][1])).norm();
                        Vec3 g;
                        for (int k = 0; k < 3; ++k) {
                            Vec3 e = Vec3::Zero();
                            e[k] = h;
                            g[k] = ratioWith(m, star[i], v, p + e) - ratioWith(m, star[i], v, p - e);
                        }
                        if (rimLine.norm() > 0)
                            g = g.dot(rimLine) * rimLine;
                        else if (boundary)
                            g -= g.dot(normal) * normal;
                        gradients.push_back(g);
                    }
                    *ascent = nearestToZeroInHull(gradients);
                    if (!(ascent->norm() > 1e-9 * gradients.front().norm()))
                        *ascent = gradients.front();
                } else {
                    *ascent = p - m.ref(nearest);  // lengthen the shortest edge
                }
            }
            return std::min({ratio, edge, 1.0});
        };
        double worst = score(x0, nullptr, worstNow);
        if (worst >= 1)
            return std::nullopt;
        const std::vector<Face> faces = boundaryFacesAt(star, v);
        boundary = !faces.empty();
        // On a glued crack a node slides along it keeping the volume of each side (the volume
        // gradient of one side's tets).
        int sides = 1;
        std::vector<int> side;
        bool rim = false;
        const bool onCrack = std::any_of(faces.begin(), faces.end(), [](const Face& f) { return f.crack; });
        if (onCrack) {
            side = sidesOf(star, sides);
            // A front (one side: the crack ends at the node) moves as any boundary node, within
            // the crack's old faces and the body's surface. A rim (two sides, and on the body's
            // surface too) keeps both volumes (below). Where cracks meet (three sides or more)
            // the node stays.
            rim = sides == 2 && anyOuter(faces);
            if (sides > 2)
                return std::nullopt;
        }
        Vec3 gradient = Vec3::Zero();  // of the volume of the star (one side's), in the node's position
        double tolerance = 0, edgeScale = 0;
        bool pure = false;
        if (boundary) {
            for (std::size_t i = 0; i < star.size(); ++i) {
                if (sides == 2 && side[i] != 0)
                    continue;
                Vec3 g;
                volumeAndGradient(m, star[i], v, x0, g);
                gradient += g;
            }
            if (!(gradient.norm() > 0))
                return std::nullopt;
            edgeScale = meanEdgeOf(faces);
            tolerance = o.maxDeviation * edgeScale;
            pure = bodyOnly({v}, edgeScale);
        }
        if (boundary)
            normal = gradient.normalized();
        OverlapGuard guard(*this, star, star, v, anyOuter(faces) && o.overlapGuard);
        // A rim node (crack and body's surface) keeps the body's volume and each side's: it
        // moves only along the line where both are what they are (both are affine in its place).
        if (rim) {
            if (sides != 2)
                return std::nullopt;
            Vec3 total = Vec3::Zero();
            for (const Tet& q : star) {
                Vec3 g;
                volumeAndGradient(m, q, v, x0, g);
                total += g;
            }
            rimLine = total.cross(gradient);
            if (!(rimLine.norm() > 1e-6 * total.norm() * gradient.norm()))
                return std::nullopt;
            rimLine.normalize();
        }
        double shortest = std::numeric_limits<double>::infinity();
        for (const Tet& q : star)
            for (const auto& e : kTetEdges)
                shortest = std::min(shortest, (m.ref(q[e[0]]) - m.ref(q[e[1]])).norm());
        // Where a trial position p puts the node: p itself inside the mesh; on the boundary,
        // the point of the old boundary nearest to p where the volume is what it was (the node
        // stays on the body's surface or the cut surface; the volume is kept).
        const auto place = [&](const Vec3& p) -> std::optional<Vec3> {
            std::optional<Vec3> at = p;
            if (rim) {
                at = x0 + rimLine.dot(p - x0) * rimLine;
                if (!o.offSurface || distanceTo(*at, faces, v, x0) > tolerance)
                    return std::nullopt;
            } else if (boundary) {
                // (p is across the volume gradient from x0: it keeps the volume too, a little
                // off the boundary where it is curved.)
                at = onBoundaryWithVolume(faces, gradient, p, gradient.dot(x0 - p));
                if (!at && o.offSurface && !pure && distanceTo(p, faces, v, x0) <= tolerance)
                    at = p;
            }
            if (!at || misplaced({v}, *at) || (boundary && leavesBody(x0, *at, pure, edgeScale)) ||
                !allPositive(star, v, *at) || (onCrack && drifts(x0, *at)))
                return std::nullopt;
            if (guard.refuses(*at))
                return std::nullopt;
            if (boundary && distanceTo(x0, faces, v, *at) > tolerance)
                return std::nullopt;
            return at;
        };
        Vec3 x = x0;
        if (!boundary) {
            // The neighbours' centroid first (Laplacian smoothing), kept only if it helps.
            Vec3 centroid = Vec3::Zero();
            int count = 0;
            for (const Tet& q : star)
                for (int u : q)
                    if (u != v) {
                        centroid += m.ref(u);
                        ++count;
                    }
            centroid /= count;
            const double q = score(centroid, nullptr);
            if (q > worst && place(centroid)) {
                x = centroid;
                worst = q;
            }
        }
        for (int iteration = 0; iteration < kSmoothingIterations; ++iteration) {
            Vec3 d = Vec3::Zero();
            worst = score(x, &d);
            if (worst >= 1)
                break;
            if (rim)
                d = d.dot(rimLine) * rimLine;
            else if (boundary)
                d -= d.dot(normal) * normal;
            const double norm = d.norm();
            if (!(norm > 0))
                break;
            d /= norm;
            bool stepped = false;
            for (double step = 0.5 * shortest; step > 1e-3 * shortest; step *= 0.5) {
                const std::optional<Vec3> p = place(x + step * d);
                if (!p)
                    continue;
                const double q = score(*p, nullptr);
                if (q > worst + 1e-12) {
                    x = *p;
                    stepped = true;
                    break;
                }
            }
            if (!stepped)
                break;
        }
        if (x == x0)
            return std::nullopt;
        return x;
    }

    void smoothSweep() {
        for (int n : nodes)
            if (alive(n) && editable.count(n))
                smoothNode(n);
    }

    // --- glued cracks ---
    // A crack whose two walls are both in the region (a cut partway in, a chip left hanging)
    // has two coincident nodes at each place, one per wall. Improving each wall on its own
    // pushes one into the other: on a curved or uneven wall a collapse or a move that keeps the
    // volume of one side bulges it out as much as it dents it. So for the pass the copies are
    // glued into one node and the walls' faces become inner faces of the mesh ("crack faces",
    // kept: no flip or split removes them, a collapse only where the link condition, which sees
    // them as boundary, holds); what the pass does to the crack it then does to both walls at
    // once. Afterwards every node is given one copy per side of the crack around it again.

    /// Glues each group of coincident region nodes (same reference and current position and
    /// velocity; two walls of a crack, or more where cracks meet) into its first node, where
    /// the glued star is sound (gluedStarIsSound).
    void glue() {
        // The candidates, by exact reference position.
        std::unordered_map<std::uint64_t, std::vector<int>> byPlace;
        const auto hashOf = [](const Vec3& p) {
            std::uint64_t h = 0;
            for (int k = 0; k < 3; ++k) {
                std::uint64_t bits;
                const double x = p[k] == 0 ? 0.0 : p[k];  // -0 and 0 alike
                std::memcpy(&bits, &x, sizeof bits);
                h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
            }
            return h;
        };
        for (int n : nodes)
            if (editable.count(n) && !m.nodeTets(n).empty())
                byPlace[hashOf(m.ref(n))].push_back(n);
        // Their twins outside the region (the other wall of an old crack, beyond the rings)
        // join it: glued, both walls change together.
        if (o.grid && !o.grid->empty()) {
            std::vector<int> near, joining;
            for (const auto& [h, group] : byPlace) {
                const int n = group.front();
                const Vec3 p = m.pos(n);
                o.grid->query(Eigen::AlignedBox3d(p, p), near);
                for (int t : near) {
                    if (t >= m.tetCount())
                        continue;
                    for (int u : m.tet(t))
                        if (u != n && !editable.count(u) && m.ref(u) == m.ref(n) && m.pos(u) == p && !keptOut(m.ref(u)) &&
                            std::find(fixedInRegion.begin(), fixedInRegion.end(), u) == fixedInRegion.end())
                            joining.push_back(u);
                }
            }
            std::sort(joining.begin(), joining.end());
            joining.erase(std::unique(joining.begin(), joining.end()), joining.end());
            for (int u : joining) {
                byPlace[hashOf(m.ref(u))].push_back(u);
                editable.insert(u);
                flippable.insert(u);
                nodes.push_back(u);
            }
        }
        std::vector<std::vector<int>> groups;
        for (auto& [h, group] : byPlace) {
            if (group.size() != 2)
                continue;
            std::sort(group.begin(), group.end());
            const int x = group.front();
            const bool same = std::all_of(group.begin(), group.end(), [&](int y) {
                return m.ref(x) == m.ref(y) && m.pos(x) == m.pos(y) && m.velocities()[x] == m.velocities()[y];
            });
            if (same)
                groups.push_back(group);
        }
        std::sort(groups.begin(), groups.end());
        std::unordered_map<int, int> repOf;  // copy -> the node it is glued into
        const auto mapped = [&](int v) {
            const auto it = repOf.find(v);
            return it == repOf.end() ? v : it->second;
        };
        const auto mapAll = [&] {
            repOf.clear();
            for (const std::vector<int>& g : groups)
                for (std::size_t k = 1; k < g.size(); ++k)
                    repOf[g[k]] = g[0];
        };
        // Drop the groups whose glued stars would be wrong, until none is.
        for (int round = 0; round < 8 && !groups.empty(); ++round) {
            mapAll();
            std::vector<std::vector<int>> kept;
            for (const std::vector<int>& g : groups)
                if (gluedStarIsSound(g, mapped))
                    kept.push_back(g);
            const bool stable = kept.size() == groups.size();
            groups = std::move(kept);
            if (stable)
                break;
        }
        mapAll();
        if (groups.empty())
            return;
        // The crack faces: boundary faces at glued nodes (each once) that pair up once mapped.
        std::unordered_set<TriKey, TriKeyHash> seen;
        std::unordered_map<TriKey, int, TriKeyHash> count;
        for (const std::vector<int>& g : groups)
            for (int v : g)
                for (const Face& f : boundaryFacesAt(starOf(v), v))
                    if (seen.insert(TriKey::of(f.nodes)).second)
                        ++count[TriKey::of(mapped(f.nodes[0]), mapped(f.nodes[1]), mapped(f.nodes[2]))];
        for (const auto& [key, c] : count)
            if (c == 2)
                crack.insert(key);
        for (const std::vector<int>& g : groups) {
            const int x = g.front();
            for (std::size_t k = 1; k < g.size(); ++k) {
                const int y = g[k];
                const std::vector<int> tets(m.nodeTets(y).begin(), m.nodeTets(y).end());
                for (int t : tets) {
                    forget(t);
                    m.replaceTet(t, replaced(m.tet(t), y, x));
                }
                editable.erase(y);
                spares[x].push_back(y);
                ++r.gluedNodes;
            }
            touched.insert(x);
        }
    }

    /// Whether gluing the group into its first node x (and the other groups, `mapped`) gives x
    /// a sound star: no tet with a repeated node or twice, every face at x in at most two tets
    /// and, in two, with opposite orientations, and the star one piece across its faces.
    template <class Map>
    bool gluedStarIsSound(const std::vector<int>& group, const Map& mapped) const {
        const int x = group.front();
        std::vector<Tet> star;
        for (int v : group)
            for (int t : m.nodeTets(v)) {
                Tet q = m.tet(t);
                for (int& u : q)
                    u = mapped(u);
                star.push_back(q);
            }
        std::vector<Tet> sortedTets;
        for (const Tet& q : star) {
            Tet sq = q;
            std::sort(sq.begin(), sq.end());
            if (std::adjacent_find(sq.begin(), sq.end()) != sq.end())
                return false;
            sortedTets.push_back(sq);
        }
        std::sort(sortedTets.begin(), sortedTets.end());
        if (std::adjacent_find(sortedTets.begin(), sortedTets.end()) != sortedTets.end())
            return false;
        // Faces at x: by their other two nodes, with the tets that have them and the orientation.
        std::unordered_map<std::uint64_t, std::vector<std::pair<int, Tri>>> faces;
        for (int i = 0; i < static_cast<int>(star.size()); ++i)
            for (const auto& lf : kTetFaces) {
                const Tri f{star[i][lf[0]], star[i][lf[1]], star[i][lf[2]]};
                const int k = f[0] == x ? 0 : f[1] == x ? 1 : f[2] == x ? 2 : -1;
                if (k >= 0)
                    faces[linkEdge(f[(k + 1) % 3], f[(k + 2) % 3])].push_back({i, f});
            }
        std::vector<int> parent(star.size());
        std::iota(parent.begin(), parent.end(), 0);
        const auto root = [&](int i) {
            while (parent[i] != i)
                i = parent[i] = parent[parent[i]];
            return i;
        };
        const auto rot = [&](const Tri& f) {
            const int k = f[0] == x ? 0 : f[1] == x ? 1 : 2;
            return std::array<int, 2>{f[(k + 1) % 3], f[(k + 2) % 3]};
        };
        for (const auto& [key, list] : faces) {
            if (list.size() > 2)
                return false;
            if (list.size() == 2) {
                const auto p = rot(list[0].second), q = rot(list[1].second);
                if (!(p[0] == q[1] && p[1] == q[0]))
                    return false;
                parent[root(list[0].first)] = root(list[1].first);
            }
        }
        for (std::size_t i = 0; i < star.size(); ++i)
            if (root(static_cast<int>(i)) != root(0))
                return false;
        return true;
    }

    /// Gives each node of a glued crack one copy per side of the crack around it (its tets
    /// joined across faces that are not crack faces), reusing the copies glued into it; the
    /// copies left over merge into it.
    void unglue() {
        std::vector<int> onCrack;
        for (const auto& [x, pool] : spares)
            if (!pool.empty())
                onCrack.push_back(x);
        for (const TriKey& k : crack)
            for (int v : {k.a, k.b, k.c})
                onCrack.push_back(v);
        std::sort(onCrack.begin(), onCrack.end());
        onCrack.erase(std::unique(onCrack.begin(), onCrack.end()), onCrack.end());
        for (int x : onCrack) {
            if (!alive(x))
                continue;
            const std::vector<int> tets(m.nodeTets(x).begin(), m.nodeTets(x).end());
            std::vector<int> parent(tets.size());
            std::iota(parent.begin(), parent.end(), 0);
            const auto root = [&](int i) {
                while (parent[i] != i)
                    i = parent[i] = parent[parent[i]];
                return i;
            };
            std::unordered_map<std::uint64_t, int> firstWith;
            for (int i = 0; i < static_cast<int>(tets.size()); ++i) {
                const Tet& q = m.tet(tets[i]);
                for (const auto& lf : kTetFaces) {
                    const Tri f{q[lf[0]], q[lf[1]], q[lf[2]]};
                    const int k = f[0] == x ? 0 : f[1] == x ? 1 : f[2] == x ? 2 : -1;
                    if (k < 0 || crack.count(TriKey::of(f)))
                        continue;
                    const auto [it, inserted] = firstWith.emplace(linkEdge(f[(k + 1) % 3], f[(k + 2) % 3]), i);
                    if (!inserted)
                        parent[root(i)] = root(it->second);
                }
            }
            std::vector<int> sectorRoots;
            for (int i = 0; i < static_cast<int>(tets.size()); ++i)
                if (root(i) == i)
                    sectorRoots.push_back(i);
            if (sectorRoots.size() < 2)
                continue;
            std::vector<int>& pool = spares[x];
            const Vec3 ref = m.ref(x), pos = m.pos(x), vel = m.velocities()[x];
            for (std::size_t s = 1; s < sectorRoots.size(); ++s) {
                int v;
                if (!pool.empty()) {
                    v = pool.back();
                    pool.pop_back();
                } else {
                    v = m.addNode(ref, pos);
                    nodes.push_back(v);
                }
                cutMarkOf[v] = true;
                for (int i = 0; i < static_cast<int>(tets.size()); ++i)
                    if (root(i) == sectorRoots[s]) {
                        forget(tets[i]);
                        m.replaceTet(tets[i], replaced(m.tet(tets[i]), x, v));
                    }
                moveNode(v, ref, pos, vel);
                ++r.ungluedNodes;
            }
            for (int t : m.nodeTets(x))
                touched.insert(m.tet(t).begin(), m.tet(t).end());
        }
        // Copies no side needs: merged into the node they were glued into (or its successor).
        for (auto& [x, pool] : spares)
            for (int y : pool) {
                int into = x;
                while (mergedInto.count(into))
                    into = mergedInto.at(into);
                mergedInto[y] = into;
                moved.erase(y);
                touched.erase(y);
            }
        spares.clear();
        crack.clear();
    }

    // --- the end: removed nodes leave, the renumbering, masses ---
    void finish() {
        std::vector<int> dead;
        for (const auto& [n, into] : mergedInto)
            dead.push_back(n);
        std::sort(dead.rbegin(), dead.rend());  // highest first: the last node never is a dead one
        // Nodes added by splits have no index at the start, so the renumbering cannot name
        // them: the moved and touched nodes, and those the pass put on a cut's surface (split
        // points of cut edges, merged nodes that took such a point's mark), follow the removals
        // here instead.
        std::vector<int> movedNow(moved.begin(), moved.end()), touchedNow, addedOnCut;
        for (const auto& [n, mark] : cutMarkOf)
            if (mark && alive(n) && n < m.nodeCount())
                addedOnCut.push_back(n);
        for (int n : touched)
            if (alive(n))
                touchedNow.push_back(n);
        for (int n : dead) {
            const int last = m.nodeCount() - 1;
            for (std::vector<int>* list : {&movedNow, &touchedNow, &addedOnCut})
                for (int& x : *list)
                    if (x == last)
                        x = n;
            nodeOrigin.remove(n, m.nodeCount());
            m.removeNode(n);
            ++r.removedNodes;
        }
        if (tetOrigin.changed() || nodeOrigin.changed()) {
            r.renumbering.tets = tetOrigin.renumbering(m.tetCount());
            r.createdTets = tetOrigin.newSlots(m.tetCount());
            const SparseRenumbering survivors = nodeOrigin.renumbering(m.nodeCount());
            SparseRenumbering nodeMap = survivors;
            // A collapsed node stands for the node it merged into.
            for (auto& [old, now] : nodeMap.changed)
                if (now < 0 && mergedInto.count(old)) {
                    int into = old;
                    while (mergedInto.count(into))
                        into = mergedInto.at(into);
                    now = survivors(into);
                }
            r.renumbering.nodes = std::move(nodeMap);
        }
        r.addedOnCutSurface = std::move(addedOnCut);
        std::sort(r.addedOnCutSurface.begin(), r.addedOnCutSurface.end());
        r.movedNodes = std::move(movedNow);
        r.touchedNodes = std::move(touchedNow);
        std::sort(r.movedNodes.begin(), r.movedNodes.end());
        r.movedNodes.erase(std::unique(r.movedNodes.begin(), r.movedNodes.end()), r.movedNodes.end());
        std::sort(r.touchedNodes.begin(), r.touchedNodes.end());
        r.touchedNodes.erase(std::unique(r.touchedNodes.begin(), r.touchedNodes.end()), r.touchedNodes.end());
        updateMasses(m, r.touchedNodes, o.density);
    }
};

} // namespace

ImproveResult improveMesh(TetMesh& mesh, const ImproveRegion& region, const ImproveOptions& options) {
    ImproveResult result;
    if (region.nodes.empty() || (options.badRatio <= 0 && options.shortEdge <= 0) || options.sweeps <= 0)
        return result;
    Pass(mesh, region, options, result).run();
    return result;
}

} // namespace resect
