#!/usr/bin/env python3
"""Writes the scanned-style surface corpus (resources/corpus/, issue 18): six small closed
triangle surfaces that imitate segmented or scanned anatomy, for testing the tetrahedral
mesher on input that is not as clean as the built-in samples.

    python3 tools/make_scan_corpus.py [OUT_DIR]        (default: resources/corpus)

Pure Python 3 (no numpy), deterministic: every surface draws from its own seeded
random.Random, so running it again rewrites the same files (the README beside them lists
what each file is; update its table by hand if the recipes change).

How a surface is made. A geodesic sphere (an icosahedron whose faces are split n x n) gives
unit directions; these are optionally warped (a stereographic dilation, so that triangles
bunch up around one pole: a graded tessellation), jittered tangentially (irregular
triangles) and some vertices are slid most of the way towards a neighbour (very short edges,
small triangles), always keeping every spherical triangle positively oriented. Each
direction d is then pushed out to r(d), a radial function of unions (max: concave creases)
and intersections (min: sharp ridges) of convex pieces that all contain the centre, plus
smooth bumps and radial noise: a star-shaped surface, hence embedded. Smooth injective maps
(shear bends, a twist), a rotation, the scale and an offset follow, then, for some, a
smoothed staircase in world z (the terraces a slice-by-slice segmentation leaves).

Every output is checked after rounding to float32 (what assimp keeps): closed, 2-manifold
(each edge in two triangles of opposite direction, each vertex link one cycle), genus 0,
one component, outward (positive volume), no duplicate vertices, no zero-area triangle, no
folded neighbours and no self-intersection (grid-accelerated triangle-triangle tests).
The script stops with an error if any check fails.
"""
import math
import os
import random
import struct
import sys

# ---------------------------------------------------------------------------------------
# Small vector helpers (tuples of three floats)


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    n = length(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def det3(a, b, c):
    return dot(a, cross(b, c))


def orient(a, b, c, d):
    """Six times the signed volume of tetrahedron abcd (> 0: d above the plane abc)."""
    return det3(sub(b, a), sub(c, a), sub(d, a))


def rotation_matrix(axis, angle):
    x, y, z = normalize(axis)
    c, s = math.cos(angle), math.sin(angle)
    t = 1 - c
    return ((t * x * x + c, t * x * y - s * z, t * x * z + s * y),
            (t * x * y + s * z, t * y * y + c, t * y * z - s * x),
            (t * x * z - s * y, t * y * z + s * x, t * z * z + c))


def apply(m, p):
    return (dot(m[0], p), dot(m[1], p), dot(m[2], p))


def f32(values):
    """The values rounded to float32 (as assimp stores them)."""
    n = len(values)
    return struct.unpack("<%df" % n, struct.pack("<%df" % n, *values))


# ---------------------------------------------------------------------------------------
# Geodesic sphere: 10 n^2 + 2 vertices, 20 n^2 triangles, outward (counter-clockwise)


def geodesic_sphere(n):
    t = (1 + math.sqrt(5)) / 2
    ico = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
           (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    ico = [normalize(v) for v in ico]
    index = {}
    dirs = []
    tris = []

    def vertex(face, a, b, c):
        # Keyed exactly by the icosahedron corners and integer weights, so that points on a
        # shared edge or corner are the same vertex for both faces.
        key = tuple(sorted((v, w) for v, w in zip(face, (a, b, c)) if w > 0))
        if key not in index:
            p = (0.0, 0.0, 0.0)
            for v, w in key:
                p = add(p, mul(ico[v], w / n))
            index[key] = len(dirs)
            dirs.append(normalize(p))
        return index[key]

    for face in faces:
        def pt(i, j):
            return vertex(face, n - i - j, i, j)
        for i in range(n):
            for j in range(n - i):
                tris.append((pt(i, j), pt(i + 1, j), pt(i, j + 1)))
                if i + j <= n - 2:
                    tris.append((pt(i + 1, j), pt(i + 1, j + 1), pt(i, j + 1)))
    return dirs, tris


def vertex_neighbours(nverts, tris):
    nbr = [set() for _ in range(nverts)]
    inc = [[] for _ in range(nverts)]
    for t, (a, b, c) in enumerate(tris):
        nbr[a].update((b, c))
        nbr[b].update((a, c))
        nbr[c].update((a, b))
        inc[a].append(t)
        inc[b].append(t)
        inc[c].append(t)
    return [sorted(s) for s in nbr], inc


# ---------------------------------------------------------------------------------------
# Direction edits (all keep every spherical triangle positively oriented)


def tri_quality(a, b, c):
    """Signed area over the longest edge squared (equilateral: 0.433; < 0: inverted)."""
    n = cross(sub(b, a), sub(c, a))
    longest = max(dot(sub(b, a), sub(b, a)), dot(sub(c, b), sub(c, b)), dot(sub(a, c), sub(a, c)))
    s = 1.0 if dot(n, add(add(a, b), c)) > 0 else -1.0
    return s * 0.5 * length(n) / longest


def star_ok(dirs, tris, inc, v, minq):
    for t in inc[v]:
        a, b, c = tris[t]
        if tri_quality(dirs[a], dirs[b], dirs[c]) < minq:
            return False
    return True


def graded_warp(dirs, pole, k):
    """Stereographic dilation about `pole`: tan(theta'/2) = k tan(theta/2). With k < 1 the
    triangles near the pole shrink by k and those opposite grow by 1/k (conformal)."""
    p = normalize(pole)
    out = []
    for d in dirs:
        c = dot(d, p)
        tang = sub(d, mul(p, c))
        s = length(tang)
        if s < 1e-12:
            out.append(d)
            continue
        theta = math.atan2(s, c)
        theta2 = 2 * math.atan(k * math.tan(theta / 2)) if theta < math.pi - 1e-9 else theta
        u = mul(tang, 1 / s)
        out.append(normalize(add(mul(p, math.cos(theta2)), mul(u, math.sin(theta2)))))
    return out


def tangential_jitter(rng, dirs, tris, nbr, inc, frac, minq=0.05):
    """Moves each direction by up to `frac` of its shortest edge, sideways."""
    dirs = list(dirs)
    for v in range(len(dirs)):
        d = dirs[v]
        spacing = min(length(sub(dirs[w], d)) for w in nbr[v])
        g = (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))
        g = sub(g, mul(d, dot(g, d)))
        if length(g) < 1e-9:
            continue
        step = mul(normalize(g), frac * spacing * rng.random())
        for _ in range(4):
            dirs[v] = normalize(add(d, step))
            if star_ok(dirs, tris, inc, v, minq):
                break
            step = mul(step, 0.5)
        else:
            dirs[v] = d
    return dirs


def short_edges(rng, dirs, tris, nbr, inc, count, lo, hi, minq=2e-3):
    """Slides `count` vertices most of the way (lo..hi) towards a neighbour: very short
    edges and the small, thin triangles around them (as marching cubes leaves near grid
    points). Returns the (moved, neighbour) pairs."""
    dirs = list(dirs)
    pairs = []
    taken = set()
    order = list(range(len(dirs)))
    rng.shuffle(order)
    for v in order:
        if len(pairs) >= count:
            break
        if v in taken or any(w in taken for w in nbr[v]):
            continue
        d = dirs[v]
        cands = list(nbr[v])
        rng.shuffle(cands)
        for w in cands:
            f = rng.uniform(lo, hi)
            dirs[v] = normalize(add(mul(d, 1 - f), mul(dirs[w], f)))
            if star_ok(dirs, tris, inc, v, minq):
                pairs.append((v, w))
                taken.add(v)
                taken.update(nbr[v])
                break
            dirs[v] = d
    return dirs, pairs


def check_directions(dirs, tris):
    """Every spherical triangle positively oriented and the solid angles summing to 4 pi:
    the cones over the triangles tile space once, so any positive r(d) is embedded."""
    total = 0.0
    for a, b, c in tris:
        da, db, dc = dirs[a], dirs[b], dirs[c]
        det = det3(da, db, dc)
        if det <= 0:
            raise SystemExit("direction mesh: an inverted triangle")
        total += 2 * math.atan2(det, 1 + dot(da, db) + dot(db, dc) + dot(dc, da))
    if abs(total - 4 * math.pi) > 1e-6:
        raise SystemExit("direction mesh covers %.9f sr, not 4 pi" % total)


# ---------------------------------------------------------------------------------------
# Radial functions of convex pieces that contain the origin: the distance along a unit
# direction d from the origin to where the ray leaves the piece.


class Ellipsoid:
    def __init__(self, centre, axes, frame=None):
        self.c = centre
        self.axes = axes
        self.frame = frame or ((1, 0, 0), (0, 1, 0), (0, 0, 1))  # rows: the axes' directions

    def _local(self, p):
        return tuple(dot(self.frame[i], p) / self.axes[i] for i in range(3))

    def exit(self, d):
        md = self._local(d)
        mc = self._local(self.c)
        qa = dot(md, md)
        qb = dot(md, mc)
        qc = dot(mc, mc) - 1
        if qc >= 0:
            raise SystemExit("an ellipsoid does not contain the centre")
        return (qb + math.sqrt(qb * qb - qa * qc)) / qa


def Ball(centre, radius):
    return Ellipsoid(centre, (radius, radius, radius))


class Capsule:
    def __init__(self, p0, p1, radius):
        self.p0, self.p1, self.r = p0, p1, radius
        if self.dist((0.0, 0.0, 0.0)) >= 0:
            raise SystemExit("a capsule does not contain the centre")

    def dist(self, p):
        ab = sub(self.p1, self.p0)
        t = max(0.0, min(1.0, dot(sub(p, self.p0), ab) / dot(ab, ab)))
        return length(sub(p, add(self.p0, mul(ab, t)))) - self.r

    def exit(self, d):
        lo, hi = 0.0, 1.0
        while self.dist(mul(d, hi)) < 0:
            lo, hi = hi, hi * 2
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if self.dist(mul(d, mid)) < 0:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)


def bumps(d, spots):
    """Smooth relative radial bumps: sum of amplitude * exp(-angle^2 / (2 width^2))."""
    s = 0.0
    for centre, width, amp in spots:
        ang2 = 2.0 * max(0.0, 1.0 - dot(d, centre))  # ~ angle^2
        s += amp * math.exp(-ang2 / (2 * width * width))
    return s


def random_spots(rng, count, width, amp):
    spots = []
    for _ in range(count):
        c = normalize((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1)))
        spots.append((c, width * rng.uniform(0.7, 1.3), amp * rng.uniform(-1, 1)))
    return spots


def vertex_noise(rng, nbr, smooth):
    """Per-vertex Gaussian noise, optionally smoothed over the 1-ring, rescaled to std 1."""
    g = [rng.gauss(0, 1) for _ in nbr]
    for _ in range(smooth):
        g = [0.5 * g[v] + 0.5 * sum(g[w] for w in nbr[v]) / len(nbr[v]) for v in range(len(g))]
    mean = sum(g) / len(g)
    std = math.sqrt(sum((x - mean) ** 2 for x in g) / len(g))
    return [(x - mean) / std for x in g]


# ---------------------------------------------------------------------------------------
# Smooth injective maps of space


def bend(points, axis, towards, start, c):
    """Shear bend: p += towards * c * max(0, p.axis - start)^2 (towards perpendicular to
    axis): the part beyond `start` curves away smoothly; the Jacobian's determinant is 1."""
    out = []
    for p in points:
        s = max(0.0, dot(p, axis) - start)
        out.append(add(p, mul(towards, c * s * s)))
    return out


def twist(points, rate):
    """Rotation about z by rate * z (injective: each z slice is rotated rigidly)."""
    out = []
    for x, y, z in points:
        a = rate * z
        ca, sa = math.cos(a), math.sin(a)
        out.append((ca * x - sa * y, sa * x + ca * y, z))
    return out


def terrace(points, period, sharpness):
    """z' = z - sharpness * period / (2 pi) * sin(2 pi z / period): a smoothed staircase
    (flat treads at multiples of the period, steep risers between), monotone for
    sharpness < 1. Amplitude sharpness * period / (2 pi)."""
    w = 2 * math.pi / period
    return [(x, y, z - sharpness / w * math.sin(w * z)) for x, y, z in points]


# ---------------------------------------------------------------------------------------
# Checks on the final (float32) surface


def check_surface(name, pts, tris):
    nv, nt = len(pts), len(tris)
    report = {}
    if len(set(pts)) != nv:
        raise SystemExit("%s: duplicate vertices after rounding to float32" % name)
    used = set(v for t in tris for v in t)
    if len(used) != nv:
        raise SystemExit("%s: unused vertices" % name)
    # Edge manifold: every directed edge once, with its reverse once.
    directed = {}
    for t, (a, b, c) in enumerate(tris):
        if len({a, b, c}) != 3:
            raise SystemExit("%s: a triangle repeats a vertex" % name)
        for e in ((a, b), (b, c), (c, a)):
            if e in directed:
                raise SystemExit("%s: edge %s used twice in the same direction" % (name, e))
            directed[e] = t
    for (a, b) in directed:
        if (b, a) not in directed:
            raise SystemExit("%s: boundary edge %s" % (name, (a, b)))
    nedges = len(directed) // 2
    # Vertex manifold: the triangles around each vertex form one cycle.
    nxt = [dict() for _ in range(nv)]
    for a, b, c in tris:
        nxt[a][b] = c
        nxt[b][c] = a
        nxt[c][a] = b
    for v in range(nv):
        ring = nxt[v]
        start = next(iter(ring))
        w, steps = ring[start], 1
        while w != start:
            w = ring[w]
            steps += 1
            if steps > len(ring):
                break
        if steps != len(ring):
            raise SystemExit("%s: vertex %d is not manifold" % (name, v))
    if nv - nedges + nt != 2:
        raise SystemExit("%s: Euler characteristic %d, not 2" % (name, nv - nedges + nt))
    # One component.
    adj = [[] for _ in range(nv)]
    for (a, b) in directed:
        adj[a].append(b)
    seen = [False] * nv
    stack = [0]
    seen[0] = True
    while stack:
        v = stack.pop()
        for w in adj[v]:
            if not seen[w]:
                seen[w] = True
                stack.append(w)
    if not all(seen):
        raise SystemExit("%s: more than one component" % name)
    # Sizes, areas, angles, volume.
    lo = tuple(min(p[i] for p in pts) for i in range(3))
    hi = tuple(max(p[i] for p in pts) for i in range(3))
    extent = max(hi[i] - lo[i] for i in range(3))
    normals = []
    volume = 0.0
    min_area = float("inf")
    min_edge = float("inf")
    max_edge = 0.0
    min_angle = 180.0
    ref = mul(add(lo, hi), 0.5)  # volume about the box centre: less cancellation
    for a, b, c in tris:
        pa, pb, pc = sub(pts[a], ref), sub(pts[b], ref), sub(pts[c], ref)
        n = cross(sub(pb, pa), sub(pc, pa))
        area = 0.5 * length(n)
        volume += det3(pa, pb, pc) / 6.0
        min_area = min(min_area, area)
        edges = (length(sub(pb, pa)), length(sub(pc, pb)), length(sub(pa, pc)))
        min_edge = min(min_edge, min(edges))
        max_edge = max(max_edge, max(edges))
        for i in range(3):
            e1, e2 = edges[i], edges[(i + 2) % 3]
            opp = edges[(i + 1) % 3]
            cosang = (e1 * e1 + e2 * e2 - opp * opp) / (2 * e1 * e2)
            min_angle = min(min_angle, math.degrees(math.acos(max(-1.0, min(1.0, cosang)))))
        normals.append(mul(n, 1 / (2 * area)) if area > 0 else (0.0, 0.0, 0.0))
    if min_area <= 1e-12 * extent * extent or min_edge <= 1e-6 * extent:
        raise SystemExit("%s: degenerate triangle (area %g, edge %g, extent %g)"
                         % (name, min_area, min_edge, extent))
    if volume <= 0:
        raise SystemExit("%s: inward or inside-out (volume %g)" % (name, volume))
    # Folds: no two neighbours facing (nearly) opposite ways.
    max_turn = 0.0
    for (a, b), t in directed.items():
        if a < b:
            u = directed[(b, a)]
            cosang = max(-1.0, min(1.0, dot(normals[t], normals[u])))
            max_turn = max(max_turn, math.degrees(math.acos(cosang)))
    if max_turn > 170.0:
        raise SystemExit("%s: folded neighbours (normals %.1f degrees apart)" % (name, max_turn))
    self_intersections(name, pts, tris, max_edge)
    report.update(lo=lo, hi=hi, volume=volume, min_area=min_area, min_edge=min_edge,
                  max_edge=max_edge, min_angle=min_angle, max_turn=max_turn, edges=nedges)
    return report


def _seg_tri_coplanar(p, q, a, b, c):
    n = cross(sub(b, a), sub(c, a))
    k = max(range(3), key=lambda i: abs(n[i]))
    i, j = [(1, 2), (0, 2), (0, 1)][k]

    def o2(u, v, w):
        return (v[i] - u[i]) * (w[j] - u[j]) - (v[j] - u[j]) * (w[i] - u[i])

    def inside(x):
        s1, s2, s3 = o2(a, b, x), o2(b, c, x), o2(c, a, x)
        return (s1 >= 0 and s2 >= 0 and s3 >= 0) or (s1 <= 0 and s2 <= 0 and s3 <= 0)

    if inside(p) or inside(q):
        return True
    for u, v in ((a, b), (b, c), (c, a)):
        if o2(p, q, u) * o2(p, q, v) <= 0 and o2(u, v, p) * o2(u, v, q) <= 0:
            return True
    return False


def seg_tri(p, q, a, b, c):
    """Does the closed segment pq meet the closed triangle abc?"""
    s1, s2 = orient(a, b, c, p), orient(a, b, c, q)
    if (s1 > 0 and s2 > 0) or (s1 < 0 and s2 < 0):
        return False
    if s1 == 0 and s2 == 0:
        return _seg_tri_coplanar(p, q, a, b, c)
    o1, o2, o3 = orient(p, q, a, b), orient(p, q, b, c), orient(p, q, c, a)
    return (o1 >= 0 and o2 >= 0 and o3 >= 0) or (o1 <= 0 and o2 <= 0 and o3 <= 0)


def self_intersections(name, pts, tris, cell):
    """Every pair of triangles with overlapping boxes: disjoint unless they share
    vertices; a pair sharing one vertex meets nowhere else (edge neighbours were checked
    for folds)."""
    boxes = []
    grid = {}
    for t, tri in enumerate(tris):
        ps = [pts[v] for v in tri]
        lo = tuple(min(p[i] for p in ps) for i in range(3))
        hi = tuple(max(p[i] for p in ps) for i in range(3))
        boxes.append((lo, hi))
        ilo = [int(math.floor(lo[i] / cell)) for i in range(3)]
        ihi = [int(math.floor(hi[i] / cell)) for i in range(3)]
        for x in range(ilo[0], ihi[0] + 1):
            for y in range(ilo[1], ihi[1] + 1):
                for z in range(ilo[2], ihi[2] + 1):
                    grid.setdefault((x, y, z), []).append(t)
    tested = set()
    for key in sorted(grid):
        members = grid[key]
        for ii in range(len(members)):
            t = members[ii]
            lo1, hi1 = boxes[t]
            for jj in range(ii + 1, len(members)):
                u = members[jj]
                lo2, hi2 = boxes[u]
                if (lo1[0] > hi2[0] or lo2[0] > hi1[0] or lo1[1] > hi2[1] or lo2[1] > hi1[1]
                        or lo1[2] > hi2[2] or lo2[2] > hi1[2]):
                    continue
                pair = (t, u) if t < u else (u, t)
                if pair in tested:
                    continue
                tested.add(pair)
                T, U = tris[t], tris[u]
                shared = set(T) & set(U)
                if len(shared) >= 2:
                    continue
                A = [pts[v] for v in T]
                B = [pts[v] for v in U]
                if len(shared) == 1:
                    s = shared.pop()
                    ea = [pts[v] for v in T if v != s]
                    eb = [pts[v] for v in U if v != s]
                    hit = seg_tri(ea[0], ea[1], *B) or seg_tri(eb[0], eb[1], *A)
                else:
                    hit = any(seg_tri(A[k], A[(k + 1) % 3], *B) for k in range(3)) or \
                        any(seg_tri(B[k], B[(k + 1) % 3], *A) for k in range(3))
                if hit:
                    raise SystemExit("%s: triangles %d and %d intersect" % (name, t, u))


# ---------------------------------------------------------------------------------------
# Writers (coordinates are the float32 values, printed with 9 significant digits, which
# read back to the same float32)


def fmt(x):
    return "%.9g" % x


def write_off(path, pts, tris, comment):
    # No comment lines: not every OFF reader skips them (the comment goes in the README).
    with open(path, "w", newline="\n") as f:
        f.write("OFF\n%d %d 0\n" % (len(pts), len(tris)))
        for p in pts:
            f.write("%s %s %s\n" % tuple(fmt(x) for x in p))
        for a, b, c in tris:
            f.write("3 %d %d %d\n" % (a, b, c))


def write_obj(path, pts, tris, comment):
    with open(path, "w", newline="\n") as f:
        f.write("# %s\n# %d vertices, %d triangles (tools/make_scan_corpus.py)\n"
                % (comment, len(pts), len(tris)))
        for p in pts:
            f.write("v %s %s %s\n" % tuple(fmt(x) for x in p))
        for a, b, c in tris:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def write_stl(path, pts, tris, comment):
    header = ("Resect Studio corpus: " + comment)[:80].encode("ascii").ljust(80, b" ")
    out = [header, struct.pack("<I", len(tris))]
    for a, b, c in tris:
        pa, pb, pc = pts[a], pts[b], pts[c]
        n = normalize(cross(sub(pb, pa), sub(pc, pa)))  # from the winding (outward)
        out.append(struct.pack("<12fH", *(n + pa + pb + pc), 0))
    with open(path, "wb") as f:
        f.write(b"".join(out))


WRITERS = {".off": write_off, ".obj": write_obj, ".stl": write_stl}


# ---------------------------------------------------------------------------------------
# The surfaces. Each recipe returns (directions, triangles, radius per vertex, maps in
# local units) in a frame where the shape is about 2 across; `finish` places it.


def random_rotation(rng):
    """A uniformly random rotation (from a random unit quaternion)."""
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    q = (math.sqrt(1 - u1) * math.sin(2 * math.pi * u2), math.sqrt(1 - u1) * math.cos(2 * math.pi * u2),
         math.sqrt(u1) * math.sin(2 * math.pi * u3), math.sqrt(u1) * math.cos(2 * math.pi * u3))
    x, y, z, w = q
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def radial_surface(dirs, radii):
    return [mul(d, r) for d, r in zip(dirs, radii)]


def finish(rng, pts, size, offset, terraces=None):
    """Random rotation, scale so that the longest box side is `size`, move the box centre
    to `offset`; then terraces (period, sharpness as fractions of size) in world z."""
    rot = random_rotation(rng)
    pts = [apply(rot, p) for p in pts]
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    s = size / max(hi[i] - lo[i] for i in range(3))
    c = [(lo[i] + hi[i]) / 2 for i in range(3)]
    pts = [tuple((p[i] - c[i]) * s + offset[i] for i in range(3)) for p in pts]
    if terraces:
        period, sharpness = terraces
        pts = terrace(pts, period * size, sharpness)
    return pts


def kidney(rng):
    """Bean: a flattened ellipsoid bent around its hilum, with a smooth hilar dent;
    irregular triangles and unsmoothed noise."""
    dirs, tris = geodesic_sphere(20)
    nbr, inc = vertex_neighbours(len(dirs), tris)
    dirs = tangential_jitter(rng, dirs, tris, nbr, inc, 0.4)
    check_directions(dirs, tris)
    body = Ellipsoid((0.04, 0.0, 0.0), (1.0, 0.52, 0.42),
                     rotation_matrix((0.3, 0.2, 1.0), 0.15))
    hilum = [((0.0, -1.0, 0.0), 0.35, -0.22), (normalize((0.2, -1.0, 0.3)), 0.2, -0.08)]
    spots = random_spots(rng, 10, 0.35, 0.03)
    noise = vertex_noise(rng, nbr, 0)
    radii = [body.exit(d) * (1 + bumps(d, hilum) + bumps(d, spots)) + 0.011 * g
             for d, g in zip(dirs, noise)]
    pts = radial_surface(dirs, radii)
    # Bend the poles towards -y (around the hilum): y -= c x^2 for |x| beyond 0.
    pts = [(x, y - 0.28 * x * x, z) for x, y, z in pts]
    return dirs, tris, pts


def polyp(rng):
    """Pedunculated polyp: a lobulated head on a curved stalk, directions bunched towards the
    stalk (graded), a concave crease where the stalk meets the head, smoothed noise."""
    dirs, tris = geodesic_sphere(20)
    nbr, inc = vertex_neighbours(len(dirs), tris)
    dirs = graded_warp(dirs, (0.05, 0.03, -1.0), 0.45)
    dirs = tangential_jitter(rng, dirs, tris, nbr, inc, 0.2)
    check_directions(dirs, tris)
    head = Ellipsoid((0.05, 0.0, 0.5), (0.78, 0.66, 0.62),
                     rotation_matrix((1.0, 0.4, 0.0), 0.25))
    stalk = Capsule((0.0, 0.0, 0.2), (0.12, 0.06, -1.7), 0.27)
    lobes = [(normalize((math.cos(a), math.sin(a), 0.9)), 0.32, 0.09)
             for a in (0.3, 1.9, 3.3, 4.6)] + [((0.0, 0.0, 1.0), 0.3, -0.05)]
    noise = vertex_noise(rng, nbr, 2)
    radii = []
    for d, g in zip(dirs, noise):
        rh = head.exit(d) * (1 + bumps(d, lobes))
        rs = stalk.exit(d)
        radii.append(max(rh, rs) + 0.02 * g)
    pts = radial_surface(dirs, radii)
    pts = bend(pts, (0.0, 0.0, -1.0), (1.0, 0.3, 0.0), 0.3, 0.22)
    return dirs, tris, pts


def liver_lobe(rng):
    """Liver lobe: a wedge cut from an ellipsoid by two large balls whose surfaces meet in a
    sharp ridge (the inferior border); noise, short edges and small triangles."""
    dirs, tris = geodesic_sphere(22)
    nbr, inc = vertex_neighbours(len(dirs), tris)
    dirs = tangential_jitter(rng, dirs, tris, nbr, inc, 0.25)
    dirs, pairs = short_edges(rng, dirs, tris, nbr, inc, 60, 0.88, 0.97)
    check_directions(dirs, tris)
    body = Ellipsoid((-0.15, 0.0, 0.05), (1.4, 1.0, 0.75), rotation_matrix((0, 0, 1), 0.2))
    n1 = normalize((0.6, 0.05, 1.0))
    n2 = normalize((0.7, -0.1, -1.0))
    top = Ball(mul(n1, 0.35 - 3.2), 3.2)      # surface 0.35 from the centre
    bottom = Ball(mul(n2, 0.25 - 4.5), 4.5)   # surface 0.25 from the centre
    spots = random_spots(rng, 8, 0.4, 0.03)
    noise = vertex_noise(rng, nbr, 1)
    for v, w in pairs:                           # keep the short edges short
        noise[v] = noise[w]
    radii = [min(body.exit(d), top.exit(d), bottom.exit(d)) * (1 + bumps(d, spots)) + 0.012 * g
             for d, g in zip(dirs, noise)]
    pts = radial_surface(dirs, radii)
    return dirs, tris, pts


def femur_head(rng):
    """Proximal femur: a ball (the head) on a shaft bent away, a concave crease at the neck,
    a trochanter bump; triangles bunched along the shaft; scanner terraces added later."""
    dirs, tris = geodesic_sphere(20)
    nbr, inc = vertex_neighbours(len(dirs), tris)
    dirs = graded_warp(dirs, (1.0, 0.05, -0.1), 0.42)
    dirs = tangential_jitter(rng, dirs, tris, nbr, inc, 0.15)
    check_directions(dirs, tris)
    head = Ball((-0.1, 0.02, 0.05), 0.72)
    shaft = Capsule((0.1, 0.0, 0.0), (2.6, 0.08, -0.25), 0.38)
    trochanter = [(normalize((0.55, 0.1, 0.5)), 0.18, 0.35)]
    noise = vertex_noise(rng, nbr, 1)
    radii = [max(head.exit(d), shaft.exit(d) * (1 + bumps(d, trochanter))) + 0.006 * g
             for d, g in zip(dirs, noise)]
    pts = radial_surface(dirs, radii)
    pts = bend(pts, (1.0, 0.0, 0.0), (0.0, 0.15, -1.0), 0.9, 0.3)
    return dirs, tris, pts


def myoma(rng):
    """Fibroid: a bumpy ball, the union of nine lobes and a core, with concave creases between;
    rough noise, many short edges and small triangles."""
    dirs, tris = geodesic_sphere(22)
    nbr, inc = vertex_neighbours(len(dirs), tris)
    dirs = tangential_jitter(rng, dirs, tris, nbr, inc, 0.3)
    dirs, pairs = short_edges(rng, dirs, tris, nbr, inc, 120, 0.85, 0.96)
    check_directions(dirs, tris)
    lobes = []
    for _ in range(9):
        c = normalize((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1)))
        dist = rng.uniform(0.35, 0.5)
        lobes.append(Ball(mul(c, dist), dist + rng.uniform(0.3, 0.45)))
    lobes.append(Ball((0.02, -0.03, 0.01), 0.72))   # the core between the lobes
    noise = vertex_noise(rng, nbr, 1)
    for v, w in pairs:
        noise[v] = noise[w]
    radii = [max(l.exit(d) for l in lobes) + 0.012 * g for d, g in zip(dirs, noise)]
    pts = radial_surface(dirs, radii)
    pts = [(1.0 * x, 0.93 * y, 0.86 * z) for x, y, z in pts]
    return dirs, tris, pts


def prostate(rng):
    """Prostate: a flattened chestnut (wide base, narrower apex, posterior groove) with a
    strongly graded tessellation (fine at the apex, coarse at the base), slightly twisted;
    slice terraces added later."""
    dirs, tris = geodesic_sphere(22)
    nbr, inc = vertex_neighbours(len(dirs), tris)
    dirs = graded_warp(dirs, (0.1, -0.2, -1.0), 0.3)
    dirs = tangential_jitter(rng, dirs, tris, nbr, inc, 0.2)
    check_directions(dirs, tris)
    body = Ellipsoid((0.0, 0.0, 0.08), (1.0, 0.72, 0.85), rotation_matrix((0, 1, 0), 0.1))
    groove = [((0.0, -1.0, 0.15), 0.22, -0.1)]
    noise = vertex_noise(rng, nbr, 2)
    radii = []
    for d, g in zip(dirs, noise):
        taper = 1 - 0.22 * max(0.0, -d[2]) ** 2       # narrower towards the apex (-z)
        radii.append(body.exit(d) * taper * (1 + bumps(d, groove)) + 0.01 * g)
    pts = radial_surface(dirs, radii)
    pts = twist(pts, 0.25)
    return dirs, tris, pts


# name, recipe, seed, size (longest box side, in the file's unit: m, mm or um), box centre,
# terraces (period as a fraction of size, sharpness) or None, file extension
SURFACES = [
    ("kidney", kidney, 1801, 0.0215, (0.031, -0.012, 0.0045), None, ".off"),
    ("polyp", polyp, 1802, 0.0188, (0.0, 0.0, 0.0), None, ".stl"),
    ("liver_lobe", liver_lobe, 1803, 23.5, (12.0, 40.0, -7.5), None, ".obj"),
    ("femur_head", femur_head, 1804, 26.0, (-3.0, 2.0, 110.0), (0.03, 0.8), ".stl"),
    ("myoma", myoma, 1805, 18500.0, (52000.0, -13000.0, 8000.0), None, ".off"),
    ("prostate", prostate, 1806, 21000.0, (0.0, 3500.0, -61000.0), (0.045, 0.85), ".obj"),
]


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "resources/corpus"
    only = sys.argv[2:]  # optional names, for debugging one recipe
    os.makedirs(out_dir, exist_ok=True)
    for name, recipe, seed, size, offset, terraces, ext in SURFACES:
        if only and name not in only:
            continue
        rng = random.Random(seed)
        _, tris, pts = recipe(rng)
        pts = finish(rng, pts, size, offset, terraces)
        flat = f32([x for p in pts for x in p])
        pts = [tuple(flat[3 * i:3 * i + 3]) for i in range(len(pts))]
        rep = check_surface(name, pts, tris)
        path = os.path.join(out_dir, name + ext)
        WRITERS[ext](path, pts, tris, "%s, %d triangles, seed %d" % (name, len(tris), seed))
        lo, hi = rep["lo"], rep["hi"]
        print("%-16s %6d tri %6d vert  box [%s] .. [%s]  size %s  volume %.6g  "
              "edges %.3g..%.3g  min area %.3g  min angle %.2f deg  max turn %.1f deg  %d bytes"
              % (name + ext, len(tris), len(pts), ", ".join("%.5g" % x for x in lo),
                 ", ".join("%.5g" % x for x in hi),
                 " x ".join("%.4g" % (hi[i] - lo[i]) for i in range(3)), rep["volume"],
                 rep["min_edge"], rep["max_edge"], rep["min_area"], rep["min_angle"],
                 rep["max_turn"], os.path.getsize(path)))


if __name__ == "__main__":
    main()
