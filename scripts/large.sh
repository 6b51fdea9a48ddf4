#!/usr/bin/env bash
# N uniform points (default 10,000,000) through every method, order and location mode: the
# time of the whole call and of its insertion phase, the peak memory of the process per point
# (the input, the triangulation, its output in canonical order), and the exact validator on
# every output. One run each: a check of size, not a benchmark.
#
# Usage: scripts/large.sh [N] [THREADS]   (THREADS for the threaded methods, default 2)
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-10000000}
threads=${2:-2}
scripts/deps.sh build
[ -f build/build.ninja ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target ridt_tool >/dev/null
dir=build/large
mkdir -p "$dir"
trap 'rm -f "$dir"/out.bin' EXIT
build/ridt generate --dist uniform -n "$n" --seed 1 -o "$dir/points.bin"

printf '%-20s %9s %9s %13s %9s  %s\n' mode "total s" "insert s" "peak bytes" "bytes/pt" validator
while read -r name flags; do
  # shellcheck disable=SC2086
  stats=$(build/ridt triangulate "$dir/points.bin" $flags --stats -o "$dir/out.bin")
  verdict=$(build/ridt check "$dir/points.bin" "$dir/out.bin" | cut -d: -f1)
  python3 -c '
import json, sys
s = json.loads(sys.argv[1]); n = int(sys.argv[2])
print("%-20s %9.2f %9.2f %13d %9.0f  %s" % (sys.argv[3], s["time_triangulate_s"], s["time_insert_s"],
      s["peak_rss_bytes"], s["peak_rss_bytes"] / n, sys.argv[4]))' "$stats" "$n" "$name" "$verdict"
done <<MODES
serial,random,dag --method serial --order random
serial,brio,dag --method serial
serial,brio,walk --method serial --locate walk
pessimistic,$threads --method pessimistic --threads $threads
optimistic,$threads --method optimistic --threads $threads
batch,$threads --method batch --threads $threads
MODES
