#!/usr/bin/env bash
# The fuzz seed corpus, made at run time (docs/fuzzing.md):  scripts/fuzz-corpus.sh OUT [SHARED_DATA] [FUZZ_BIN]
#  - the project's own seeds, written by FUZZ_BIN/stylos_fuzz_seeds (tests/fuzz/FuzzSeeds.cpp);
#  - small files and slices (the first points of a scan, its header patched) of SHARED_DATA (../shared/data),
#    when it is there; never committed;
#  - the inputs that once crashed a reader (tests/data/fuzz/CORPUS/, each read by a regression test), kept as regression seeds.
# One folder per corpus name of tests/fuzz/harnesses.txt. Exit 77 (skipped) when the harnesses are not built.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?usage: fuzz-corpus.sh OUT [SHARED_DATA] [FUZZ_BIN]}"
shared="${2:-$here/../shared/data}"
bin="${3:-$here/build/fuzz/bin}"
if [ ! -x "$bin/stylos_fuzz_seeds" ]; then
  echo "fuzz-corpus: $bin/stylos_fuzz_seeds is not built (clang++ with libFuzzer not found): skipped"
  exit 77
fi
rm -rf "$out"
mkdir -p "$out"
"$bin/stylos_fuzz_seeds" "$out"
mkdir -p "$out"/{las,e57,ptx}

# PLY: the header with the vertex count set to N and every other element dropped, then N records.
ply_slice() { # SRC N OUT
  local src="$1" n="$2" dst="$3" header stride
  header="$(sed -n '1,/^end_header/p' "$src" | tr -d '\r')"
  if grep -q '^format ascii' <<<"$header"; then
    awk -v n="$n" '/^element / { keep = ($2 == "vertex") } /^element vertex/ { print "element vertex " n; next }
                   /^end_header/ { print; exit } keep || !/^(element|property)/ { print }' <<<"$header" > "$dst"
    sed -n '/^end_header/,$p' "$src" | sed -n "2,$((n + 1))p" >> "$dst"
  else
    stride="$(awk '/^element / { v = ($2 == "vertex") }
        v && /^property/ { t = $2; if (t ~ /^(char|uchar|int8|uint8)$/) s += 1; else if (t ~ /^(short|ushort|int16|uint16)$/) s += 2;
                           else if (t ~ /^(double|float64)$/) s += 8; else s += 4 }
        END { print s }' <<<"$header")"
    awk -v n="$n" '/^element / { keep = ($2 == "vertex") } /^element vertex/ { print "element vertex " n; next }
                   /^end_header/ { print; exit } keep || !/^(element|property)/ { print }' <<<"$header" > "$dst"
    local skip; skip="$(grep -abo 'end_header' "$src" | head -1 | cut -d: -f1)"
    dd if="$src" iflag=skip_bytes,count_bytes skip="$((skip + 11))" count="$((n * stride))" bs=64K status=none >> "$dst"
  fi
}

# LAS 1.0-1.3: the header and VLRs, N records, the legacy point count set to N.
las_slice() { # SRC N OUT
  local src="$1" n="$2" dst="$3" offset length
  offset="$(od -A n -t u4 -j 96 -N 4 "$src" | tr -d ' ')"
  length="$(od -A n -t u2 -j 105 -N 2 "$src" | tr -d ' ')"
  head -c "$((offset + n * length))" "$src" > "$dst"
  printf "$(printf '\\%03o\\%03o\\%03o\\%03o' $((n & 255)) $((n >> 8 & 255)) $((n >> 16 & 255)) $((n >> 24)))" |
    dd of="$dst" bs=1 seek=107 conv=notrunc status=none
}

if [ -d "$shared/formats" ]; then
  f="$shared/formats"
  cp "$f"/minimal-ply-*.ply "$f"/invalid/*.ply "$out/ply/"
  ply_slice "$f/bun000_ascii_rangegrid.ply" 40 "$out/ply/bun000-slice40.ply"
  cp "$f"/minimal-las-*.las "$out/las/"
  las_slice "$f/mvk-thin.las" 60 "$out/las/mvk-thin-slice60.las"
  las_slice "$f/autzen_trim.las" 60 "$out/las/autzen-slice60.las"
  cp "$f"/e57/*.e57 "$out/e57/"
  for e in "$f"/e57/invalid/*; do [ -s "$e" ] && cp "$e" "$out/e57/invalid-$(basename "$e")"; done
  cp "$f"/ptx/*.ptx "$out/ptx/"
  cp "$f/pdal_test.pts" "$out/xyz/"
  head -n 60 "$f/cgal_kitten.xyz" > "$out/xyz/cgal-kitten-60.xyz"
else
  echo "fuzz-corpus: $shared/formats not found: only the project's own seeds"
fi
if [ -d "$shared/scans" ]; then
  for s in "$shared"/scans/*.ply; do ply_slice "$s" 200 "$out/ply/$(basename "$s" .ply)-slice200.ply"; done
fi
cp "$here"/tests/data/*.poct "$out/poct/"
if [ -d "$here/tests/data/fuzz" ]; then
  for d in "$here"/tests/data/fuzz/*/; do
    mkdir -p "$out/$(basename "$d")"
    cp "$d"* "$out/$(basename "$d")/" 2>/dev/null || true
  done
fi
echo "fuzz-corpus: $(find "$out" -type f | wc -l) seeds in $out"
