#!/usr/bin/env bash
# The README's meshing table: `resect mesh` at the defaults on the built-in samples and on the
# scanned-style corpus (resources/corpus), one markdown row each: surface, triangles, tets,
# worst dihedral angle, volume error (after volume matching; the inscribed boundary's in
# brackets), seconds. Extra surfaces may be given as arguments.
#   tools/mesh_table.sh [build/release/app/resect] [SURFACE ...]
set -euo pipefail
cd "$(dirname "$0")/.."
resect=${1:-build/release/app/resect}
shift || true
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| surface | triangles | tets | worst dihedral | volume error (inscribed) | seconds |"
echo "|---|---|---|---|---|---|"
row() { # name, then the arguments for resect mesh
    local name=$1
    shift
    "$resect" mesh "$@" --out "$tmp/m.vtu" --report "$tmp/r.json" >/dev/null
    python3 - "$name" "$tmp/r.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[2]))
inscribed = 100 * (r["inscribed_volume"] - r["surface_volume"]) / r["surface_volume"]
print("| %s | %d | %d | %.1f° | %+.1e %% (%+.1f %%) | %.2f |" % (
    sys.argv[1], r["surface_triangles"], r["tets"], r["min_dihedral_deg"], 100 * r["volume_error"], inscribed,
    r["seconds"]))
PY
}
row "sample polyp" --sample polyp
row "sample myoma" --sample myoma
for f in resources/corpus/*.off resources/corpus/*.obj resources/corpus/*.stl "$@"; do
    row "$(basename "$f")" "$f"
done
