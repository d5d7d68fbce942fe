#!/usr/bin/env bash
# CTest: ptview_subdivide keeps a closed mesh closed. Subdivides a tetrahedron (2 levels) and a
# quad cube (1 level) and checks the counts Euler predicts (V' = V + E, F' = 4F) and that every
# edge is shared by exactly two triangles, once in each direction (closed, consistently wound).
# Usage: subdivide_test.sh PATH/TO/ptview_subdivide
set -euo pipefail
tool=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Outward-wound tetrahedron; the corners use every face syntax the tool accepts (plain, v/vt,
# v//vn, negative) and the file has records it must skip.
cat >"$work/tetra.obj" <<'OBJ'
# closed tetrahedron
o tetra
v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
vn 0 0 1
vt 0 0
s off
f 1 3 2
f 1/1 2/1 4/1
f -3//1 -2//1 -1//1
f 3/1/1 1/1/1 4/1/1
l 1 2
OBJ

# Unit cube of six outward quads: checks the fan split as well.
cat >"$work/cube.obj" <<'OBJ'
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
OBJ

# check OUT.obj VERTICES TRIANGLES: counts, index range, and closedness of the written mesh.
check() {
  awk -v wantV="$2" -v wantF="$3" '
    /^v / { v++ }
    /^f / {
      f++
      if (NF != 4) { printf "line %d: face with %d corners\n", NR, NF - 1; bad = 1 }
      for (i = 2; i <= 4; i++) {
        c[i] = $i + 0
        if (c[i] < 1 || c[i] > v) { printf "line %d: index %s out of range\n", NR, $i; bad = 1 }
      }
      for (i = 2; i <= 4; i++) {
        a = c[i]; b = c[i == 4 ? 2 : i + 1]
        directed[a " " b]++
        undirected[a < b ? a " " b : b " " a]++
      }
    }
    END {
      if (v != wantV) { printf "%d vertices, expected %d\n", v, wantV; bad = 1 }
      if (f != wantF) { printf "%d triangles, expected %d\n", f, wantF; bad = 1 }
      for (e in undirected) if (undirected[e] != 2) {
        printf "edge %s used by %d triangles, expected 2 (not closed)\n", e, undirected[e]; bad = 1
      }
      for (e in directed) if (directed[e] != 1) {
        printf "directed edge %s used %d times (inconsistent winding)\n", e, directed[e]; bad = 1
      }
      exit bad
    }' "$1" || { echo "FAIL: $1"; exit 1; }
  [ ! -e "$1.tmp" ] || { echo "FAIL: $1.tmp left behind"; exit 1; }
  echo "ok: $1 ($2 vertices, $3 triangles, closed)"
}

# Tetrahedron V=4 E=6 F=4 -> V=10 E=24 F=16 -> V=34 E=96 F=64.
summary=$("$tool" "$work/tetra.obj" "$work/tetra2.obj" --levels 2)
echo "$summary"
[[ $summary == "wrote $work/tetra2.obj (34 vertices, 64 triangles) in "*" s" ]] ||
  { echo "FAIL: unexpected summary line"; exit 1; }
check "$work/tetra2.obj" 34 64

# Cube: V=8, 12 triangles, E=18 -> V=26, F=48.
"$tool" "$work/cube.obj" "$work/cube1.obj" --levels 1
check "$work/cube1.obj" 26 48

# A face pointing at a missing vertex is an error, and no output appears.
printf 'v 0 0 0\nv 1 0 0\nf 1 2 3\n' >"$work/broken.obj"
if "$tool" "$work/broken.obj" "$work/broken_out.obj" 2>/dev/null; then
  echo "FAIL: accepted a face with a missing vertex"; exit 1
fi
[ ! -e "$work/broken_out.obj" ] || { echo "FAIL: wrote output for a broken input"; exit 1; }
echo "ok: bad input rejected"
