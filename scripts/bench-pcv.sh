#!/usr/bin/env bash
# The 3D skydome side by side with CloudCompare 2.11's PCV (issue 5, docs/benchmarks.md), from a clean build:
#
#   scripts/bench-pcv.sh BUILD_DIR [WORK_DIR]
#
# Builds stylos-cli and stylos_ao_quality in BUILD_DIR (Release, no GUI), generates the fluted, broken drum
# (~2.9 M points, 1.2 mm spacing) into WORK_DIR (default /tmp/stylos-bench-pcv) and takes real scans from
# ../shared/data (STYLOS_DATA overrides). For each cloud: CloudCompare's PCV exactly as the issue runs it
# (plus a PLY export), timed with /usr/bin/time; `stylos-cli ao` end to end (octree build included) when
# the CLI has the command; then stylos_ao_quality: every method against the brute-force reference and
# PCV's scalar field against the same reference on the same points. Each JSON goes to WORK_DIR, a table
# to stdout. Environment: RAYS (default 256), CLOUDS (default "drum buddha igea"), SAMPLES (default 2000).
# Needs: cmake, ninja, CloudCompare (apt-get install cloudcompare), xvfb-run, python3.
# Against the ANALYTIC truth of generated scans instead of the cell reference: scripts/bench-pcv-truth.sh.
set -euo pipefail

build=${1:?usage: scripts/bench-pcv.sh BUILD_DIR [WORK_DIR]}
work=${2:-/tmp/stylos-bench-pcv}
repo=$(cd "$(dirname "$0")/.." && pwd)
data=${STYLOS_DATA:-$repo/../shared/data}
rays=${RAYS:-256}
clouds=${CLOUDS:-drum buddha igea}
samples=${SAMPLES:-2000}

cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSTYLOS_BUILD_GUI=OFF \
      -DSTYLOS_BUILD_BENCHMARKS=ON > /dev/null
cmake --build "$build" --target stylos-cli stylos_ao_quality
. "$repo/scripts/build-programs.sh"
cli=$(program stylos-cli)
quality=$(program stylos_ao_quality)
mkdir -p "$work"
build=$(cd "$build" && pwd)
work=$(cd "$work" && pwd)

# Inputs: CloudCompare writes NAME_PCV.ply next to its input, so every input is a link inside WORK_DIR.
for name in $clouds; do
  case $name in
    drum) [ -f "$work/drum.ply" ] || "$cli" generate drum -o "$work/drum.ply" --spacing 0.0012 --seed 1 ;;
    buddha) ln -sf "$data/scans/happy_buddha_1.1M.ply" "$work/buddha.ply" ;;
    igea) ln -sf "$data/scans/igea_134k.ply" "$work/igea.ply" ;;
    lion) ln -sf "$data/scans/lion_takanawa_342k.ply" "$work/lion.ply" ;;
    *) echo "unknown cloud $name" >&2; exit 2 ;;
  esac
done

has_ao=0
"$cli" ao --help > /dev/null 2>&1 && has_ao=1

for name in $clouds; do
  in="$work/$name.ply"
  echo "== $name: $(uptime)" >&2
  # CloudCompare's PCV, the issue's command line (-C_EXPORT_FMT PLY so the scalar field can be read back).
  rm -f "$work/${name}_PCV.ply"
  load_pcv=$(cut -d' ' -f1-3 /proc/loadavg)
  /usr/bin/time -f '%e %M' -o "$work/$name.pcv.time" \
    xvfb-run -a CloudCompare -SILENT -C_EXPORT_FMT PLY -NO_TIMESTAMP -O "$in" \
      -PCV -N_RAYS "$rays" -RESOLUTION 1024 -SAVE_CLOUDS > "$work/$name.pcv.log" 2>&1
  pcv_seconds=$(cut -d' ' -f1 "$work/$name.pcv.time")

  # The skydome's quality against the reference, PCV's on the same points; its level is then used by the CLI.
  "$quality" "$in" --directions "$rays" --samples "$samples" --pcv "$work/${name}_PCV.ply" \
    --pcv-seconds "$pcv_seconds" > "$work/$name.quality.json"
  level=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['level'])" "$work/$name.quality.json")

  # stylos-cli ao end to end (the octree build from the point file included), both methods.
  echo "{\"pcvLoad\": \"$load_pcv\"}" > "$work/$name.cli.json"
  if [ "$has_ao" = 1 ]; then
    for method in depthmap slices; do
      load=$(cut -d' ' -f1-3 /proc/loadavg)
      /usr/bin/time -f '%e %M' -o "$work/$name.$method.time" \
        "$cli" ao "$in" -o "$work/$name.$method.ao.ply" --directions "$rays" --level "$level" \
          --method "$method" --json > "$work/$name.$method.ao.json" 2> "$work/$name.$method.ao.log" || true
      python3 - "$work/$name.cli.json" "$method" "$work/$name.$method.time" "$load" <<'EOF'
import json, sys
path, method, timefile, load = sys.argv[1:5]
j = json.load(open(path))
wall, rss = open(timefile).read().split()[-2:]
j[method] = {"wall": float(wall), "maxRssKiB": int(rss), "load": load}
json.dump(j, open(path, "w"))
EOF
    done
  fi
done

python3 - "$work" "$rays" $clouds <<'EOF'
import json, os, sys
work, rays, clouds = sys.argv[1], sys.argv[2], sys.argv[3:]
def fmt(a): return f"{a['correlation']:.3f} / {a['mae']:.3f}" if a.get("n") else "–"
print("| cloud | points | level: cells | PCV s | stylos-cli ao s: depthmap, slices | PCV ÷ depthmap "
      "| r / MAE vs reference: PCV (two-sided, per point) | depthmap (cells) | slices (cells) |")
print("|---|---|---|---|---|---|---|---|---|")
for name in clouds:
    q = json.load(open(os.path.join(work, f"{name}.quality.json")))
    cli = json.load(open(os.path.join(work, f"{name}.cli.json")))
    p, m = q["pcv"], q["methods"]
    wall = {k: cli[k]["wall"] for k in ("depthmap", "slices") if k in cli}
    ratio = f"{p['pcvSeconds'] / wall['depthmap']:.1f}×" if "depthmap" in wall else "–"
    print(f"| {name} | {p['points']} | {q['level']}: {q['cells']} | {p['pcvSeconds']:.1f} "
          f"| {wall.get('depthmap', float('nan')):.1f}, {wall.get('slices', float('nan')):.1f} | {ratio} "
          f"| {fmt(p['perPoint']['twoSided']['pcv'])} | {fmt(m.get('depthmap', {}))} | {fmt(m.get('slices', {}))} |")
print(f"\nLoad (1/5/15 min) before each run: {work}/NAME.cli.json, NAME.quality.json. Details (PCV in its own"
      " definition, per cell, the Stylos methods on PCV's points, the drum's class means): NAME.quality.json")
EOF
