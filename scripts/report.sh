#!/usr/bin/env bash
# Rebuilds ridt in Release, runs every benchmark and rewrites docs/performance.md and everything
# under docs/results/ (tables as .txt, .csv and .md, figures as .png) from what it measured.
#
#   scripts/report.sh [--quick | --large] [--build DIR]
#
# --quick: sizes up to 10^5 and fewer repetitions (a few minutes), to try the pipeline; without
# it, the paper's sizes up to 10^6, and 10^6 and 10^7 in the whole-process table (some 45
# minutes on 2 cores); --large: also 10^7 points in the Python table (another hour: scipy takes
# minutes a run there), 10^8 LiDAR-like points to a DEM and 10^8 and 5 x 10^8 points out of
# core (some 26 GB of disk). Run it on a quiet machine: every figure is a median of interleaved runs, and
# anything else running skews them. Installs what it needs first (scripts/deps.sh bench, as
# root): the test dependencies, Qhull, Triangle (from Debian's non-free component, which it
# adds where apt lacks it), node and delaunator for the peers table.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=full
build=build/report
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) mode=quick ;;
    --large) mode=large ;;
    --build) build="$2"; shift ;;
    *) echo "usage: scripts/report.sh [--quick | --large] [--build DIR]" >&2; exit 2 ;;
  esac
  shift
done

py=/usr/bin/python3
out=docs/results
log() { printf '\n== %s\n' "$*" >&2; }

log "dependencies (scripts/deps.sh bench: the test set, Qhull, Triangle, node and delaunator)"
bash scripts/deps.sh bench >&2

log "build ($build, Release, with the Python module)"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRIDT_BUILD_TESTS=OFF -DRIDT_BUILD_BENCH=ON \
  -DRIDT_BUILD_PYTHON=ON -DPython_EXECUTABLE="$py" >/dev/null
ninja -C "$build" ridt_tool ridt_bench_serial ridt_bench_threads ridt_bench_peers ridt_cgal_triangulate ridt_bench_constrained \
  ridt_bench_weighted ridt_bench_periodic ridt_python_package >/dev/null

if [ "$mode" = quick ]; then
  serial_args=(--max-n 100000 --reps 3)
  threads_args=(--n 1000,10000,100000 --dist uniform,grid --reps 3 --threads 1,2,4)
  paper_args=(--n 1000,10000,100000 --dist uniform --reps 3 --threads 1,2)
  peers_args=(--sizes 100000 --reps 3)
  process_args=(--sizes 100000 --reps 3)
  python_args=(--sizes 10000,100000 --big "" --reps 2)
  interpolate_args=(--n 100000 --grid 500 --reps 2)
  sphere_args=(--sizes 10000,100000 --reps 2)
  weighted_args=(--sizes 100000 --reps 3)
  periodic_args=(--sizes 100000 --reps 3)
  terrain_args=(--sizes 100000 --reps 1 --gdal-nearest-max 100000)
  ooc_args=(--sizes 1000000 --limits 100M)
  cdt_args=(--n 100000 --lakes 10 --reps 3)
  cdt_extra_args=(--n 10000 --lakes 5 --extra 90000 --reps 3)
  quality_args=(--n 25000 --lakes 10 --angle 30 --reps 3)
  mesh_args=(--cdt 100000:10 --quality 25000:10:30 --size 25000:10:30 --reps 3)
  mesh_large_args=(--cdt "" --quality 250000:50:30 --reps 1)
else
  serial_args=(--reps 5)
  threads_args=(--n 1000,10000,100000,1000000 --dist uniform,grid --reps 5 --threads 1,2,4)
  paper_args=(--n 1000,10000,100000,1000000 --dist uniform --reps 5 --threads 1,2)
  peers_args=(--sizes 10000,100000,1000000 --reps 5)
  process_args=(--sizes 1000000,10000000 --reps 9)
  python_args=(--sizes 10000,100000,1000000 --big "" --reps 3)
  interpolate_args=(--n 1000000 --grid 2000 --reps 3)
  sphere_args=(--sizes 10000,100000,1000000 --reps 3)
  weighted_args=(--sizes 100000,1000000 --reps 5)
  periodic_args=(--sizes 100000,1000000 --reps 5)
  terrain_args=(--sizes 1000000,10000000 --reps 3)
  ooc_args=(--sizes 10000000 --limits 500M)
  cdt_args=(--n 1000000 --lakes 100 --reps 5)
  cdt_extra_args=(--n 100000 --lakes 10 --extra 900000 --reps 5)
  quality_args=(--n 250000 --lakes 50 --angle 30 --reps 5)
  mesh_args=(--cdt 1000000:100 --quality 250000:50:30 --size 250000:50:30 --reps 5)
  # The 10^7-triangle quality mesh on 1 and 2 threads beside Triangle's, and a size field over the
  # 10^6-vertex coastline beside the uniform bound of the same mesh size (some 5 minutes).
  mesh_large_args=(--cdt "" --quality 2500000:100:30 --size 1000000:100:30 --reps 1)
  if [ "$mode" = large ]; then
    ooc_args=(--sizes 10000000,100000000,500000000 --limits 500M,2G,4G)
    python_args=(--sizes 10000,100000,1000000 --big 10000000 --reps 3)
    terrain_args=(--sizes 1000000,10000000 --reps 3 --huge 100000000 --huge-threads 2)
  fi
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
commands="$tmp/commands.txt"
run() {  # run NAME COMMAND...: the command's output to $tmp/NAME.txt, and the command logged
  local name="$1"; shift
  log "$name: $*"
  printf '%s\t%s\n' "$name" "$*" >>"$commands"
  "$@" >"$tmp/$name.txt"
}

run serial "$build/ridt_bench_serial" "${serial_args[@]}" --csv "$tmp/serial.csv"
run threads "$build/ridt_bench_threads" "${threads_args[@]}" --csv "$tmp/threads.csv"
run table3 "$build/ridt_bench_threads" "${paper_args[@]}" --order random --locate root \
  --methods paper,pessimistic --csv "$tmp/table3.csv"
run peers "$build/ridt_bench_peers" "${peers_args[@]}" --node-modules build/peers/node_modules --csv "$tmp/peers.csv"
run process "$py" bench/process_table.py --build "$build" "${process_args[@]}" --threads 2 --out "$tmp/process.md"
run python env PYTHONPATH="$build/python" "$py" bench/python_table.py --python "$py" "${python_args[@]}" \
  --out "$tmp/python.md"
run interpolate env PYTHONPATH="$build/python" "$py" bench/interpolate_table.py --python "$py" \
  "${interpolate_args[@]}" --out "$tmp/interpolate.md"
run sphere env PYTHONPATH="$build/python" "$py" bench/sphere_table.py --python "$py" "${sphere_args[@]}" \
  --out "$tmp/sphere.md"
run weighted "$build/ridt_bench_weighted" "${weighted_args[@]}" --threads 2 --csv "$tmp/weighted.csv"
run periodic "$build/ridt_bench_periodic" "${periodic_args[@]}" --threads 2 --csv "$tmp/periodic.csv"
run terrain "$py" bench/terrain_table.py --build "$build" "${terrain_args[@]}" --dir "$tmp/terrain" \
  --out "$tmp/terrain.md"
rm -rf "$tmp/terrain"
mkdir -p "$tmp/ooc"
run out_of_core "$py" bench/out_of_core_table.py --build "$build" "${ooc_args[@]}" --threads 2 --dir "$tmp/ooc" \
  --out "$tmp/out_of_core.md"
rm -rf "$tmp/ooc"
run constrained_cdt "$build/ridt_bench_constrained" --task cdt "${cdt_args[@]}" --csv "$tmp/constrained.csv"
run constrained_extra "$build/ridt_bench_constrained" --task cdt "${cdt_extra_args[@]}" --csv "$tmp/constrained.csv"
run constrained_quality "$build/ridt_bench_constrained" --task quality "${quality_args[@]}" --csv "$tmp/constrained.csv"
if [ "$mode" = large ]; then  # some 5 minutes: Triangle and CGAL take 2 each
  run constrained_quality_large "$build/ridt_bench_constrained" --task quality --n 2500000 --lakes 100 --angle 30 \
    --reps 1 --csv "$tmp/constrained.csv"
fi
run mesh_process "$py" bench/mesh_process_table.py --build "$build" "${mesh_args[@]}" --threads 2 \
  --out "$tmp/mesh_process.md"
run mesh_process_large "$py" bench/mesh_process_table.py --build "$build" "${mesh_large_args[@]}" --threads 2 \
  --out "$tmp/mesh_process_large.md"
run plots "$py" bench/plot_threads.py "$tmp/threads.csv" "$tmp"
run plots_root "$py" bench/plot_threads.py "$tmp/table3.csv" "$tmp" root_

# Only now, with every part measured, replace what the last report wrote (scaling*, which
# scripts/scaling.sh writes on a many-core machine, stays).
mkdir -p "$out"
find "$out" -maxdepth 1 -type f ! -name 'scaling*' -delete
cp "$tmp"/*.txt "$tmp"/*.csv "$tmp"/*.md "$tmp"/*.png "$out"/
rm -f "$out/commands.txt" "$out/plots.txt" "$out/plots_root.txt"
sed -i "s#$tmp#$out#g" "$commands"
"$py" bench/report.py --results "$out" --commands "$commands" --mode "$mode" --out docs/performance.md
log "wrote docs/performance.md and $out/"
