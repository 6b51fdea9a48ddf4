#!/usr/bin/env bash
# Thread scaling on a many-core machine: rewrites docs/scaling.md, docs/results/scaling.csv,
# docs/results/scaling_more.csv (the other distributions at 10^7, 10^8 points) and
# docs/results/scaling_process.md (the 2-thread whole-process table of docs/performance.md, taken
# on a machine whose other cores are idle). Figures: bench/plot_scaling.py.
#
#   scripts/scaling.sh [--build DIR] [--out DIR] [--quick]
#
# --build DIR: time the `ridt` and `ridt_cgal_triangulate` already in DIR; without it, builds
#   them in build/report first (scripts/deps.sh bench installs what it needs). For a machine
#   without the build's dependencies, link both statically where they are, then copy DIR there:
#     L=/usr/lib/x86_64-linux-gnu; cmake -S . -B build/static -G Ninja -DCMAKE_BUILD_TYPE=Release \
#       -DRIDT_BUILD_TESTS=OFF -DRIDT_BUILD_BENCH=ON -DRIDT_BUILD_PYTHON=OFF -DRIDT_BUILD_MPI=OFF \
#       -DCMAKE_EXE_LINKER_FLAGS=-static -DPNG_LIBRARY=$L/libpng16.a -DZLIB_LIBRARY=$L/libz.a \
#       -DGMP_LIBRARY_RELEASE=$L/libgmp.a -DGMPXX_LIBRARIES=$L/libgmpxx.a -DMPFR_LIBRARIES=$L/libmpfr.a
#     cmake --build build/static --target ridt_tool ridt_cgal_triangulate
# --out DIR: write the page there instead of docs/ (its results/ beside it).
# --quick: 10^5 points, 2 repetitions: tries the pipeline in a minute.
# Threads: 1, 2, 4, ... up to the machine's hardware threads, and that count. Run it with nothing
# else on the machine: each figure is a median of interleaved runs.
set -euo pipefail
cd "$(dirname "$0")/.."

build="" out=docs quick=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift ;;
    --out) out="$2"; shift ;;
    --quick) quick=1 ;;
    *) echo "usage: scripts/scaling.sh [--build DIR] [--out DIR] [--quick]" >&2; exit 2 ;;
  esac
  shift
done

if [ -z "$build" ]; then
  build=build/report
  bash scripts/deps.sh bench >&2
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRIDT_BUILD_TESTS=OFF -DRIDT_BUILD_BENCH=ON >/dev/null
  cmake --build "$build" --target ridt_tool ridt_cgal_triangulate >/dev/null
fi
build=$(cd "$build" && pwd)
mkdir -p "$out/results"
out=$(cd "$out" && pwd)

cores=$(nproc)
threads="" t=1
while [ "$t" -lt "$cores" ]; do threads="$threads$t,"; t=$((t * 2)); done
threads="$threads$cores"

py=$(command -v /usr/bin/python3 || command -v python3)
cd bench
if [ "$quick" = 1 ]; then
  "$py" scaling_table.py --build "$build" --sizes 100000 --threads "$threads" --reps 2 --out "$out/scaling.md"
  exit 0
fi
"$py" process_table.py --build "$build" --sizes 1000000 --reps 9 --threads 2 --out "$out/results/scaling_process.md"
"$py" scaling_table.py --build "$build" --sizes 1000000,10000000 --threads "$threads" --reps 5 \
  --dag-max-n 1000000 --dists normal,grid,clusters --huge 100000000 --out "$out/scaling.md"
"$py" plot_scaling.py "$out/results/scaling.csv" "$out/results/scaling.png" || echo "scaling.sh: no figure (matplotlib missing)" >&2
