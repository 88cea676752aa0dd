#!/bin/sh
# The picture of "Docking to the flutes" in docs/workbench.md (docs/images/workbench-dock.png): a generated drum and a
# fragment of the same design (design seed 21), the fragment placed 2° about the drum axis and 5 mm out from its true
# place, docked by `stylos --grab --dock` under Xvfb.   Usage: scripts/dock-screenshot.sh BUILD_DIR OUT.png [--paint]
# With --paint (docs/images/assembly-paint.png, docs/annotation.md): coarser (4 mm spacing, depth 8), the two in an
# assembly "Drum 1 reconstruction", and `--grab --dock --paint` paints across fragment and drum on the assembly's
# développée. STYLOS_CLI overrides the stylos-cli used.
set -eu
build=${1:-build}; mode=${3:-}
if [ "$mode" = --paint ]; then out=${2:-docs/images/assembly-paint.png}; spacing=0.004; drumDepth=8; fragmentDepth=8
else out=${2:-docs/images/workbench-dock.png}; spacing=0.002; drumDepth=10; fragmentDepth=9; fi
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cli=${STYLOS_CLI:-"$build/bin/stylos-cli"}
"$cli" generate drum -o "$work/drum.ply" --spacing $spacing --seed 101 --design-seed 21 --normals >/dev/null
"$cli" generate fragment -o "$work/fragment.ply" --spacing $spacing --seed 5 --design-seed 21 --normals >/dev/null
"$cli" build "$work/drum.ply" -o "$work/drum.poct" --depth $drumDepth >/dev/null
"$cli" build "$work/fragment.ply" -o "$work/fragment.poct" --depth $fragmentDepth >/dev/null
python3 - "$work" "$mode" <<'PY'
import json, math, sys
w = sys.argv[1]; assembly = sys.argv[2] == '--paint'
def mat(v): return [v[4*i:4*i+4] for i in range(4)]
def mul(a, b): return [[sum(a[i][k]*b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
def inv(m):  # rigid
    r = [[m[j][i] for j in range(3)] for i in range(3)]
    t = [-sum(r[i][k]*m[k][3] for k in range(3)) for i in range(3)]
    return [r[0]+[t[0]], r[1]+[t[1]], r[2]+[t[2]], [0,0,0,1]]
d = json.load(open(w + '/drum.truth.json'))
f = json.load(open(w + '/fragment.truth.json'))
drum = inv(mat(d['stations'][0]['toOutput']))
truth = inv(mat(f['stations'][0]['toOutput']))
theta = f['fragment']['thetaCentre']
a = math.radians(2.0)
R = [[math.cos(a), -math.sin(a), 0, 0], [math.sin(a), math.cos(a), 0, 0], [0,0,1,0], [0,0,0,1]]
T = [[1,0,0,0.005*math.cos(theta)], [0,1,0,0.005*math.sin(theta)], [0,0,1,0], [0,0,0,1]]
start = mul(R, mul(T, truth))
# the whole scene turned about the vertical so that the fragment faces the front view (azimuth -90 deg)
phi = -math.pi / 2 - theta
Z = [[math.cos(phi), -math.sin(phi), 0, 0], [math.sin(phi), math.cos(phi), 0, 0], [0,0,1,0], [0,0,0,1]]
drum = mul(Z, drum); start = mul(Z, start)
def frag(i, name, octree, pose, colour):
    return {"id": i, "name": name, "octree": octree, "source": "", "pose": [x for row in pose for x in row], "colour": colour,
            "visible": True, "guides": [], "annotations": ""}
fragments = [frag(1, "Drum", "drum.poct", drum, "#b9ad98"), frag(2, "Fragment A", "fragment.poct", start, "#2f6fe0")]
project = {"format": "stylos-project", "version": 1, "nextId": 3, "fragments": fragments}
if assembly:
    fragments[0]["assembly"] = 0; fragments[1]["assembly"] = 1
    identity = [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]
    project = {"format": "stylos-project", "version": 2, "nextId": 3, "nextAssemblyId": 2,
               "assemblies": [{"id": 1, "name": "Drum 1 reconstruction", "pose": identity, "drum": 1, "visible": True}],
               "fragments": fragments}
json.dump(project, open(w + '/dock.stylos', 'w'), indent=1)
PY
paint=; [ "$mode" = --paint ] && paint=--paint
xvfb-run -a -s "-screen 0 1600x1000x24" "$build/bin/stylos" --grab "$out" --dock $paint "$work/dock.stylos"
