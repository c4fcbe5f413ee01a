#!/usr/bin/env python3
"""Writes resources/scenarios/polyp-resection-10.json: the bundled polyp resected by ten loop
scoops (the paper's Figure 10: the loop pulled through the tissue again and again, each pass
taking a chip where the last ones were). Each stroke pulls the half-loop electrode (arms up,
its plane across the pull) through the head along a direction turned by the golden angle from
the last, dipping a little deeper each time: five poses, 0.2 s apart.

    python3 tools/make_resection_scenario.py [OUT.json]
"""
import json, math, sys

GOLDEN = 2.399963229728653  # rad
TOP = 20.0                  # the polyp's apex (mm)
AXIS = (1.2, 0.5)           # where the head sits
SIZE = 3.5                  # the loop's half width and depth (tool.size)

def pose(t, x, y, z, heading):
    # The tool's loop lies in its xz plane (normal +y); turn it about z so that +y points
    # along the pull: angle heading - 90 degrees.
    theta = heading - math.pi / 2
    return {"t": round(t, 3), "position": [round(x, 6), round(y, 6), round(z, 6)],
            "orientation": [round(math.cos(theta / 2), 9), 0, 0, round(math.sin(theta / 2), 9)]}

def stroke(k, start):
    heading = k * GOLDEN
    dx, dy = math.cos(heading), math.sin(heading)
    depth = 2.2 + 0.45 * k            # below the apex, at the deepest
    reach = 9.0
    shift = 0.15 * k
    poses = []
    for i in range(5):
        f = -1 + 2 * i / 4            # -1 .. 1 along the pull
        bottom = TOP + 1.5 - (depth + 1.5) * (1 - f * f)
        along = f * reach + shift
        poses.append(pose(start + 0.2 * i, AXIS[0] + along * dx, AXIS[1] + along * dy, bottom + SIZE, heading))
    return {"name": "scoop %d" % (k + 1), "poses": poses}

def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "resources/scenarios/polyp-resection-10.json"
    with open("resources/scenarios/polyp-resection.json") as f:
        base = json.load(f)
    doc = {
        "format": base["format"], "version": base["version"],
        "metadata": {
            "title": "Resection of a polyp's head in ten loop scoops",
            "author": "Resect Studio examples (tools/make_resection_scenario.py)",
            "description": "The built-in polyp's head is taken off in ten passes of the loop electrode, "
                           "each pull turned by the golden angle from the last and a little deeper, each "
                           "taking a chip where the last ones were (the paper's Figure 10). The base of the "
                           "stalk is anchored; the tissue then settles under gravity for 50 ms.",
            "learning_objectives": ["Take a head off in repeated shallow passes",
                                    "Keep every pass's chip small and the remaining tissue healthy"],
            "difficulty": 3,
        },
        "tissues": base["tissues"],
        "tool": base["tool"],
        "strokes": [stroke(k, 1.0 * k) for k in range(10)],  # a stroke a second
        "cut_settings": base["cut_settings"],
        # The tissue settles under gravity after the passes (no loop contact: the strokes only
        # cut), with the implicit integrator at 1 ms; the chips each pass takes off leave the
        # scene (issue 16).
        "effects": [e for e in base["effects"] if e["name"] != "tool-contact"],
        "simulation": {"integrator": "implicit", "time_step": 0.001, "duration": 0.05,
                       "resected_pieces": "remove"},
        "expectations": [
            {"kind": "pieces_at_least", "value": 4},
            {"kind": "stays_finite", "value": True},
        ],
    }
    with open(out, "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")

if __name__ == "__main__":
    main()
