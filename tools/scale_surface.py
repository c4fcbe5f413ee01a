#!/usr/bin/env python3
"""Writes an OFF surface moved to the origin and scaled so that its largest extent is SIZE (in
the units the samples use, mm): CGAL's scanned meshes come in units of about 1, where the
samples' material and contact radius crush them (README, "Crack walls").

    python3 tools/scale_surface.py IN.off OUT.off [SIZE]      (SIZE: 30 by default)

Reads OFF and COFF (vertex colours and comments are dropped); writes plain OFF, faces as they
were.
"""
import sys

def read_off(path):
    """The vertices (x, y, z lists) and faces (token lists: count, then indices) of an OFF or
    COFF file; vertex colours and comments are dropped."""
    lines = [l.split("#")[0].strip() for l in open(path)]
    lines = [l for l in lines if l]
    first = 0
    while not lines[first][0].isdigit() and not lines[first][0] == "-":
        # the header ("OFF", "COFF"), possibly with the counts on the same line
        rest = lines[first].split()[1:]
        if rest:
            lines[first] = " ".join(rest)
            break
        first += 1
    counts = lines[first].split()
    vertices, faces = int(counts[0]), int(counts[1])
    body = lines[first + 1:]
    points = [list(map(float, l.split()[:3])) for l in body[:vertices]]
    polygons = []
    for l in body[vertices:vertices + faces]:
        t = l.split()
        polygons.append(t[:1 + int(t[0])])
    return points, polygons

def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    source, out = sys.argv[1], sys.argv[2]
    size = float(sys.argv[3]) if len(sys.argv) == 4 else 30.0
    points, polygons = read_off(source)
    vertices, faces = len(points), len(polygons)
    lo = [min(p[k] for p in points) for k in range(3)]
    hi = [max(p[k] for p in points) for k in range(3)]
    scale = size / max(hi[k] - lo[k] for k in range(3))
    with open(out, "w") as f:
        f.write("OFF\n%d %d 0\n" % (vertices, faces))
        for p in points:
            f.write("%.9g %.9g %.9g\n" % tuple((p[k] - lo[k]) * scale for k in range(3)))
        for polygon in polygons:
            f.write(" ".join(polygon) + "\n")

if __name__ == "__main__":
    main()
