#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UndefinedBehaviorSanitizer, and
# fuzzes each one for SECONDS (default 60). This is the open-ended search for new faults; the
# test command replays the corpora with a fixed number of seeded mutations instead
# (fuzz/replay.cpp), so that its result is the same on every run of a commit.
#
# Usage: scripts/fuzz.sh [SECONDS [TARGET...]]
#        scripts/fuzz.sh --build-only
#   TARGET is readers, triangulate or terrain (default all, one after the other). Two runs of the
#   script, one a target, use both cores of a two-core machine.
#   The corpora kept in the repository (fuzz/corpus/<target>) are read, never written; new
#   inputs go to build-fuzz/corpus/<target>. A finding (crash, sanitizer report, timeout, a
#   broken property) stops the run, is saved under build-fuzz/findings/ and fails the script.
#   To keep what a long run learned: RIDT_FUZZ_MERGE=1 scripts/fuzz.sh 3600 merges the new
#   inputs that add coverage into fuzz/corpus/.
set -euo pipefail
cd "$(dirname "$0")/.."
build_only=0
[ "${1:-}" = --build-only ] && build_only=1 && shift
seconds=${1:-60}
targets=("${@:2}")
[ "${#targets[@]}" -gt 0 ] || targets=(readers triangulate terrain sphere regular periodic)
scripts/deps.sh fuzz

cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DRIDT_BUILD_FUZZ=ON \
  -DRIDT_SANITIZE=address,undefined -DRIDT_BUILD_TESTS=OFF -DRIDT_BUILD_BENCH=OFF \
  -DRIDT_BUILD_TOOLS=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target fuzz_readers fuzz_triangulate fuzz_terrain fuzz_sphere fuzz_regular fuzz_periodic
[ "$build_only" = 1 ] && exit 0

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
mkdir -p build-fuzz/findings
# Inputs: readers up to 4 KiB of file; triangulations up to 256 points (of 256 positions), on the
# sphere up to 64 (of 120 kinds), weighted up to 64 (of 256 kinds).
declare -A max_len=([readers]=4096 [triangulate]=257 [terrain]=4096 [sphere]=65 [regular]=65 [periodic]=65)
for target in "${targets[@]}"; do
  [ -n "${max_len[$target]:-}" ] || { echo "unknown fuzz target '$target' (readers, triangulate, terrain, sphere, regular or periodic)"; exit 2; }
  echo "== fuzz_$target for ${seconds}s"
  rm -f build-fuzz/findings/"$target"-*
  mkdir -p "build-fuzz/corpus/$target"
  dict=()
  [ -f "fuzz/$target.dict" ] && dict=(-dict="fuzz/$target.dict")
  log=build-fuzz/fuzz_$target.log
  if ! build-fuzz/fuzz_$target "build-fuzz/corpus/$target" "fuzz/corpus/$target" "${dict[@]}" \
      -max_total_time="$seconds" -max_len="${max_len[$target]}" -timeout=20 -rss_limit_mb=4096 \
      -print_final_stats=1 -artifact_prefix="build-fuzz/findings/$target-" >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "fuzz_$target found a problem (log: $log):" build-fuzz/findings/$target-*
    exit 1
  fi
  grep -E "INFO: seed corpus|^#[0-9]+.*DONE|stat::number_of_executed_units" "$log" || true
  if [ "${RIDT_FUZZ_MERGE:-0}" = 1 ]; then
    build-fuzz/fuzz_$target -merge=1 "fuzz/corpus/$target" "build-fuzz/corpus/$target" \
      -max_len="${max_len[$target]}" 2>&1 | grep -E "MERGE-OUTER: [0-9]+ new files" || true
  fi
done
echo "fuzzing found nothing"
