#!/usr/bin/env bash
# One libFuzzer harness on its seed corpus (docs/fuzzing.md):
#   scripts/fuzz-run.sh HARNESS CORPUS_ROOT WORK_ROOT FUZZ_BIN [libFuzzer options…]
# e.g. scripts/fuzz-run.sh PlyReaderFuzzer build/fuzz-corpus build/fuzz-work build/fuzz/bin -max_total_time=5
# New inputs go to WORK_ROOT/HARNESS (emptied first), a crash to WORK_ROOT/HARNESS-crash-… ; the seeds stay as
# they are. Options from tests/fuzz/harnesses.txt (max_len, dictionary), then -timeout=10 -rss_limit_mb=2048.
# Exit: libFuzzer's (0: no crash), 77 (skipped) when the harness is not built.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
name="${1:?usage: fuzz-run.sh HARNESS CORPUS_ROOT WORK_ROOT FUZZ_BIN [options]}"
corpus_root="$2"; work_root="$3"; bin="$4"; shift 4
if [ ! -x "$bin/$name" ]; then
  echo "fuzz-run: $bin/$name is not built (clang++ with libFuzzer not found when configuring): skipped"
  exit 77
fi
read -r _ corpus max_len dict < <(grep -E "^$name[[:space:]]" "$here/tests/fuzz/harnesses.txt")
args=(-max_len="$max_len" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -error_exitcode=1
      -artifact_prefix="$work_root/$name-")
[ "$dict" != "-" ] && args+=(-dict="$here/tests/fuzz/dict/$dict")
rm -rf "${work_root:?}/$name"
mkdir -p "$work_root/$name" "$corpus_root/$corpus"
exec "$bin/$name" "${args[@]}" "$@" "$work_root/$name" "$corpus_root/$corpus"
