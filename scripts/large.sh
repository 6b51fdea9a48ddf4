#!/usr/bin/env bash
# N uniform points (default 10,000,000) through every method, order and location mode: the
# time of the whole call and of its insertion phase, the peak memory of the process per point
# (the input, the triangulation, its output in canonical order), and the exact validator on
# every output; and that the peak, less the input's 16 bytes a point, stays within what the
# library estimated before the run (estimate_memory). One run each: a check of size, not a
# benchmark.
#
# Usage: scripts/large.sh [N] [THREADS] [all|quick]
#   THREADS for the threaded methods (default 2); quick leaves out the paper's random order,
#   the slowest, and the pessimistic and batch methods, which drive the same DAG kernel as
#   optimistic and which the suites test at every thread count on smaller sets (scripts/test.sh
#   runs quick).
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-10000000}
threads=${2:-2}
modes=${3:-all}
scripts/deps.sh build
[ -f build/build.ninja ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target ridt_tool >/dev/null
dir=build/large
mkdir -p "$dir"
trap 'rm -f "$dir"/out.bin "$dir"/check.txt' EXIT
build/ridt generate --dist uniform -n "$n" --seed 1 -o "$dir/points.bin"

printf '%-20s %9s %9s %13s %9s %9s  %s\n' mode "total s" "insert s" "peak bytes" "bytes/pt" "estimate" validator
while read -r name flags; do
  [ "$modes" = quick ] && [[ "$flags" == *"--order random"* || "$name" == pessimistic* || "$name" == batch* ]] && continue
  # shellcheck disable=SC2086
  stats=$(build/ridt triangulate "$dir/points.bin" $flags --stats -o "$dir/out.bin")
  if ! build/ridt check "$dir/points.bin" "$dir/out.bin" >"$dir/check.txt"; then
    echo "$name: $(cat "$dir/check.txt")"
    exit 1
  fi
  verdict=$(cut -d: -f1 "$dir/check.txt")
  field() { grep -o "\"$1\": [0-9.e+-]*" <<<"$stats" | head -n 1 | cut -d' ' -f2; }
  peak=$(field peak_rss_bytes)
  estimate=$(field memory_estimate)
  printf '%-20s %9.2f %9.2f %13d %9.0f %9.0f  %s\n' "$name" "$(field time_triangulate_s)" \
    "$(field time_insert_s)" "$peak" "$(awk -v p="$peak" -v n="$n" 'BEGIN { print p / n }')" \
    "$(awk -v e="$estimate" -v n="$n" 'BEGIN { print e / n }')" "$verdict"
  if [ "$((peak - 16 * n))" -gt "$estimate" ]; then
    echo "$name: the peak less the input, $((peak - 16 * n)) bytes, is over the estimate, $estimate"
    exit 1
  fi
done <<MODES
serial,random,dag --method serial --order random
serial,brio,dag --method serial --locate dag
serial,brio,walk --method serial --locate walk
pessimistic,$threads --method pessimistic --threads $threads
optimistic,$threads --method optimistic --threads $threads
batch,$threads --method batch --threads $threads
partition,$threads --method partition --threads $threads
MODES
