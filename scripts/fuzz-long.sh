#!/usr/bin/env bash
# The long fuzz run (docs/fuzzing.md, figures in docs/benchmarks.md): every harness in turn, one process, one
# worker, until RUNS executions (default 1 000 000) or SECONDS seconds (default 3600) each, whichever comes
# first, on the seed corpus plus what earlier long runs found (build/fuzz-long/HARNESS, kept).
#   scripts/fuzz-long.sh [BUILD_DIR] [RUNS] [SECONDS] [HARNESS…]
# Writes build/fuzz-long/HARNESS.log and prints one line per harness: executions, exec/s, corpus, crashes.
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$here/build}" && pwd)"; runs="${2:-1000000}"; seconds="${3:-3600}"; shift $(( $# < 3 ? $# : 3 ))
bin="$build/fuzz/bin"; corpus="$build/fuzz-corpus"; long="$build/fuzz-long"
mkdir -p "$long"
[ -d "$corpus" ] || bash "$here/scripts/fuzz-corpus.sh" "$corpus" "$here/../shared/data" "$bin" || exit 1
names=("$@")
[ ${#names[@]} -eq 0 ] && mapfile -t names < <(grep -E '^[A-Za-z]' "$here/tests/fuzz/harnesses.txt" | awk '{print $1}')
printf '%-20s %12s %8s %8s %8s %s\n' harness executions exec/s corpus crashes seconds
for name in "${names[@]}"; do
  read -r _ sub max_len dict < <(grep -E "^$name[[:space:]]" "$here/tests/fuzz/harnesses.txt")
  args=(-max_len="$max_len" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -runs="$runs"
        -max_total_time="$seconds" -artifact_prefix="$long/$name-")
  [ "$dict" != "-" ] && args+=(-dict="$here/tests/fuzz/dict/$dict")
  mkdir -p "$long/$name"
  start=$(date +%s)
  touch "$long/.start-$name"
  "$bin/$name" "${args[@]}" "$long/$name" "$corpus/$sub" > "$long/$name.log" 2>&1
  rc=$?
  end=$(date +%s)
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$long/$name.log" | grep -o '[0-9]*$')
  speed=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$long/$name.log" | grep -o '[0-9]*$')
  files=$(find "$long/$name" -type f | wc -l)
  crashes=$(find "$long" -maxdepth 1 -name "$name-*" -type f -newer "$long/.start-$name" | wc -l)  # this run's only
  printf '%-20s %12s %8s %8s %8s %s%s\n' "$name" "${execs:-?}" "${speed:-?}" "$files" "$crashes" "$((end - start))" \
         "$([ $rc -ne 0 ] && echo "  (exit $rc: see $long/$name.log)")"
done
