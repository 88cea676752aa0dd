#!/usr/bin/env bash
# CloudCompare 2.11's PCV side by side with the 3D skydome (`stylos-cli ao`) on generated scans, in one run,
# both against the ANALYTIC truth (issue 17, docs/benchmarks.md "3D skydome against the true geometry"):
#
#   scripts/bench-pcv-truth.sh BUILD_DIR [WORK_DIR]
#
# For each kind (KINDS, default "drum fragment"): `stylos-cli generate KIND --spacing SPACING --noise NOISE
# --seed SEED` into WORK_DIR (default /tmp/stylos-pcv-truth) under the name stylos_ao_truth caches it by,
# so both read the same file; then, back to back, each after recording /proc/loadavg and timed with
# /usr/bin/time (wall, user, system, peak RSS): CloudCompare's PCV exactly as scripts/bench-pcv.sh runs it
# (-N_RAYS RAYS -RESOLUTION RESOLUTION, PLY out), and `stylos-cli ao` end to end on the same PLY (octree
# build, normals, skydome, PLY out; RAYS directions, defaults otherwise); then stylos_ao_truth --pcv: PCV
# and the method against the analytic truth at the same 2000 true points (POINTS). JSON, logs and times
# go to WORK_DIR, a table to stdout. The clouds run one at a time: never two heavy jobs at once.
# Environment: KINDS, RAYS (256), RESOLUTION (1024), SPACING (0.002), NOISE (0.00033), SEED (1), POINTS (2000).
# Needs: cmake, ninja, CloudCompare with qPCV (apt-get install cloudcompare), xvfb-run, python3.
set -euo pipefail

build=${1:?usage: scripts/bench-pcv-truth.sh BUILD_DIR [WORK_DIR]}
work=${2:-/tmp/stylos-pcv-truth}
repo=$(cd "$(dirname "$0")/.." && pwd)
kinds=${KINDS:-drum fragment}
rays=${RAYS:-256}
resolution=${RESOLUTION:-1024}
spacing=${SPACING:-0.002}
noise=${NOISE:-0.00033}
seed=${SEED:-1}
points=${POINTS:-2000}

[ -f "$build/CMakeCache.txt" ] || cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DSTYLOS_BUILD_GUI=OFF -DSTYLOS_BUILD_BENCHMARKS=ON > /dev/null
cmake --build "$build" --target stylos-cli stylos_ao_truth >&2
. "$repo/scripts/build-programs.sh"
cli=$(program stylos-cli)
truth=$(program stylos_ao_truth)
mkdir -p "$work"
work=$(cd "$work" && pwd)

# timed NAME COMMAND...: records the load before, then wall / user / system seconds and peak KiB.
timed() {
  local name=$1; shift
  cut -d' ' -f1-3 /proc/loadavg > "$work/$name.load"
  /usr/bin/time -f '%e %U %S %M' -o "$work/$name.time" "$@"
}

for kind in $kinds; do
  # stylos_ao_truth's cache name: KIND-s<spacing in mm>mm-n<noise in mm>mm-seed<seed> (C++ stream format).
  stem=$(python3 -c "import sys; print('%s-s%smm-n%smm-seed%s' % (sys.argv[1], '%g' % (float(sys.argv[2]) * 1000), '%g' % (float(sys.argv[3]) * 1000), sys.argv[4]))" \
         "$kind" "$spacing" "$noise" "$seed")
  ply="$work/$stem.ply"
  [ -f "$ply" ] || "$cli" generate "$kind" -o "$ply" --spacing "$spacing" --noise "$noise" --seed "$seed" --json \
    > "$work/$kind.generate.json"
  echo "== $kind: $ply, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2

  # CloudCompare's PCV (writes STEM_PCV.ply next to its input).
  rm -f "$work/${stem}_PCV.ply"
  (cd "$work" && timed "$kind.pcv" xvfb-run -a CloudCompare -SILENT -C_EXPORT_FMT PLY -NO_TIMESTAMP -O "$ply" \
     -PCV -N_RAYS "$rays" -RESOLUTION "$resolution" -SAVE_CLOUDS > "$work/$kind.pcv.log" 2>&1)
  [ -f "$work/${stem}_PCV.ply" ] || { echo "CloudCompare wrote no ${stem}_PCV.ply (see $work/$kind.pcv.log)" >&2; exit 1; }

  # The 3D skydome end to end, as a user runs it, right after.
  timed "$kind.ao" "$cli" ao "$ply" -o "$work/$stem.ao.ply" --directions "$rays" --json \
    > "$work/$kind.ao.json" 2> "$work/$kind.ao.log"

  # Both against the analytic truth at the same true points.
  "$truth" --kind "$kind" --spacing "$spacing" --noise "$noise" --seed "$seed" --directions "$rays" \
    --points "$points" --dir "$work" --pcv "$work/${stem}_PCV.ply" > "$work/$kind.truth.json" 2> "$work/$kind.truth.log"
  python3 - "$work/$kind.truth.json" "$ply" <<'PY'
import json, os, sys
j = json.load(open(sys.argv[1]))
if os.path.realpath(j["scan"]["file"]) != os.path.realpath(sys.argv[2]):
    sys.exit(f"stylos_ao_truth read {j['scan']['file']}, not {sys.argv[2]}")
PY
done

python3 - "$work" "$rays" "$resolution" $kinds <<'PY'
import json, os, sys
work, rays, resolution, kinds = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
def times(name):
    wall, user, system, rss = open(os.path.join(work, name + ".time")).read().split()[-4:]
    return float(wall), float(user) + float(system), int(rss)
def load(name): return open(os.path.join(work, name + ".load")).read().split()[0]
def ra(a): return f"{a['r']:.3f} / {a['mae']:.3f}"
print(f"PCV: -N_RAYS {rays} -RESOLUTION {resolution}; stylos-cli ao --directions {rays}; r / MAE against the analytic truth\n")
print("| scan | points | PCV s wall (CPU), load before | stylos-cli ao s wall (CPU), load before; of which octree + normals / skydome "
      "| PCV ÷ ao, wall (CPU); ÷ skydome alone | PCV, its definition | method, PCV's definition | PCV ÷ F, ours (≤ 1) "
      "| method, ours | PCV 5 / 50 / 95 % |")
print("|---|---:|---|---|---|---|---|---|---|---|")
for kind in kinds:
    j = json.load(open(os.path.join(work, f"{kind}.truth.json")))
    p, a = j["pcv"], j["pcv"]["parts"]["all"]
    pw, pc, _ = times(f"{kind}.pcv")
    aw, ac, _ = times(f"{kind}.ao")
    pct = p["percentiles"]
    cli = json.load(open(os.path.join(work, f"{kind}.ao.json")))
    print(f"| {kind} | {p['points']:,} | {pw:.1f} ({pc:.1f}), {load(kind + '.pcv')} | {aw:.1f} ({ac:.1f}), {load(kind + '.ao')}; "
          f"{cli['build_seconds']:.2f} / {cli['ao_seconds']:.2f} "
          f"| **{pw / aw:.1f}×** ({pc / ac:.1f}×); {pw / cli['ao_seconds']:.1f}× | {ra(a['pcvDefinition']['pcv'])} | {ra(a['pcvDefinition']['method'])} "
          f"| {ra(a['stylosDefinition']['pcv'])} | {ra(a['stylosDefinition']['method'])} | {pct['5']:.3f} / {pct['50']:.3f} / {pct['95']:.3f} |")
print("\nPer part, ours (visible / directions in front of the true normal): mean (truth, method, PCV ÷ F unbounded), "
      "r of PCV and of the method (PCV's definition)\n")
print("| scan | part | n | truth | method | PCV ÷ F | r PCV | r method |")
print("|---|---|---:|---:|---:|---:|---:|---:|")
for kind in kinds:
    j = json.load(open(os.path.join(work, f"{kind}.truth.json")))
    for part, o in sorted(j["pcv"]["parts"].items()):
        s, d = o["stylosDefinition"], o["pcvDefinition"]
        print(f"| {kind} | {part} | {s['method']['n']} | {s['method']['truthMean']:.3f} | {s['method']['mean']:.3f} "
              f"| {s['pcvUnclipped']['mean']:.3f} | {d['pcv']['r']:.3f} | {d['method']['r']:.3f} |")
    print(f"| {kind} | flutes darker than fillets: method {j['flutesDarkerThanFillets']}, PCV {j['pcv']['flutesDarkerThanFillets']} | | | | | | |")
PY
