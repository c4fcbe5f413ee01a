#!/usr/bin/env python3
"""Writes a scenario that pulls the half-loop electrode 20 times through any closed surface at
random: each pull crosses the body along y at a random height in the upper half and a random
offset in x, its five poses jittered and the loop tilted a little (seeded, so a seed always
gives the same pulls). The body is anchored at its bottom 8 %; material, effects and
simulation are the polyp scenario's, the loop is 0.3 times the body's smaller width, and the
pulls are 0.05 s apart. For trying `resect run` on surfaces the code was not written around
(README, "Crack walls": the inverted tets this found on CGAL's femur).

    python3 tools/make_random_pulls.py SURFACE.(off|obj|stl) SEED OUT.json [--partial]
    resect run OUT.json --report REPORT.json

With --partial every second pull stops inside the body, 30-70 % of the way across: it leaves a
crack whose two walls stay in the tissue, as a mouse stroke cut partway in does.

Only the surface's vertices are read (OFF or COFF, OBJ, ASCII or binary STL), for its bounding box;
`resect run` reads the surface itself.
"""
import json, math, os, random, struct, sys

sys.dont_write_bytecode = True  # (no __pycache__ beside the tools)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scale_surface import read_off  # noqa: E402 (the one OFF reader of the tools)

def vertices(path):
    if path.endswith(".off"):
        return read_off(path)[0]
    if path.endswith(".obj"):
        return [list(map(float, l.split()[1:4])) for l in open(path) if l.startswith("v ")]
    if path.endswith(".stl"):
        data = open(path, "rb").read()
        if data[:5] == b"solid" and b"vertex" in data[:1000]:
            return [list(map(float, l.split()[1:4])) for l in data.decode().splitlines() if l.strip().startswith("vertex")]
        count = struct.unpack("<I", data[80:84])[0]
        return [list(struct.unpack("<3f", data[84 + 50 * i + 12 + 12 * k:84 + 50 * i + 24 + 12 * k]))
                for i in range(count) for k in range(3)]
    sys.exit("make_random_pulls: %s: OFF, OBJ or STL expected" % path)

def main():
    args = [a for a in sys.argv[1:] if a != "--partial"]
    partial = "--partial" in sys.argv[1:]
    if len(args) != 3:
        sys.exit(__doc__)
    surface, seed, out = os.path.abspath(args[0]), int(args[1]), args[2]
    pts = vertices(surface)
    lo = [min(p[k] for p in pts) for k in range(3)]
    hi = [max(p[k] for p in pts) for k in range(3)]
    size = [hi[k] - lo[k] for k in range(3)]
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "..", "resources", "scenarios", "polyp-resection.json")) as f:
        scenario = json.load(f)
    scenario["metadata"]["title"] = "%s: 20 random loop pulls%s (seed %d)" % (
        os.path.basename(surface), ", every second partway" if partial else "", seed)
    scenario["metadata"]["description"] = "Written by tools/make_random_pulls.py."
    tissue = scenario["tissues"][0]
    tissue["name"] = "body"
    tissue["surface"] = surface
    box_max = [hi[k] + 0.01 * size[k] for k in range(3)]
    box_max[2] = lo[2] + 0.08 * size[2]
    tissue["fixed_regions"] = [{"min": [lo[k] - 0.01 * size[k] for k in range(3)], "max": box_max}]
    scenario["tool"]["size"] = 0.3 * min(size[0], size[1])
    rng = random.Random(seed)
    centre = [(lo[k] + hi[k]) / 2 for k in range(3)]
    strokes = []
    for s in range(20):
        height = hi[2] - rng.uniform(0.0, 0.5) * size[2]
        offset = rng.uniform(-0.3, 0.3) * size[0]
        reach = 1.2 if not (partial and s % 2 == 1) else rng.uniform(0.4, 0.8)
        poses = []
        for i in range(5):
            p = [centre[0] + offset + rng.uniform(-0.03, 0.03) * size[0],
                 lo[1] - 0.1 * size[1] + i / 4 * reach * size[1],
                 height + rng.uniform(-0.01, 0.01) * size[2]]
            tilt = rng.uniform(-0.15, 0.15)
            poses.append({"t": round(0.05 * s + 0.01 * i, 4), "position": p,
                          "orientation": [math.cos(tilt / 2), math.sin(tilt / 2), 0, 0]})
        strokes.append({"name": "pull %d" % (s + 1), "poses": poses})
    scenario["strokes"] = strokes
    scenario["expectations"] = [{"kind": "stays_finite", "value": True}]
    scenario["simulation"]["duration"] = 0.05
    with open(out, "w") as f:
        json.dump(scenario, f, indent=1)

if __name__ == "__main__":
    main()
