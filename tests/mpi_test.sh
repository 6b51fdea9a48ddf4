#!/usr/bin/env bash
# ridt-mpi end to end: on 1 to 8 ranks (more ranks than cores: correctness and communication,
# not speed), every distribution, degenerate sets, huge and tiny scales and the robustness
# fixtures give exactly the single process's triangles; the parts pass `ridt check`; bad input
# stops every rank with one message, exit status 2 and no output.
#   tests/mpi_test.sh RIDT RIDT_MPI FIXTURES_DIR
set -u
ridt=$1 mpi=$2 fixtures=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
# One machine: shared memory between ranks (the transports Open MPI would probe for a network
# cost half of each short run's start).
export OMPI_MCA_btl=self,vader OMPI_MCA_pml=ob1
# Under AddressSanitizer: memory errors are checked, leaks are not. Open MPI's plugins keep
# allocations to the end and are unloaded before the leak check, which then cannot tell them
# from ours (their frames have no module left to match a suppression).
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
. "$(dirname "$0")/shell_helpers.sh"
run() { timeout 120 mpirun -np "$1" --oversubscribe "$mpi" "${@:2}"; }  # a hang fails

# The point sets, as .bin files.
for d in uniform normal grid clusters; do
  "$ridt" generate --dist "$d" -n 30000 --seed 5 -o "$dir/$d.bin" || fail "generate $d"
done
/usr/bin/python3 "$(dirname "$0")/point_sets.py" "$dir" "$fixtures" || fail "making the degenerate sets"

sets=$(cd "$dir" && ls *.bin | sed 's/\.bin$//')
[ -n "$sets" ] && pass || fail "no point sets"
for s in $sets; do
  in="$dir/$s.bin"
  "$ridt" triangulate "$in" -o "$dir/$s.single.ele" 2>/dev/null
  [ -s "$dir/$s.single.ele" ] && pass || { fail "$s: no single-process output"; continue; }
  for np in 1 2 3 4 8; do
    if run "$np" "$in" -o "$dir/$s.$np.ele" --merge >/dev/null 2>"$dir/err"; then
      if cmp -s "$dir/$s.single.ele" "$dir/$s.$np.ele"; then pass; else fail "$s on $np ranks: not the single process's triangles"; fi
    else
      fail "$s on $np ranks: exit status $?"; cat "$dir/err"
    fi
  done
done

# Parts and their index: every rank's own file, checked whole; the same triangles as merged.
for np in 1 3 4 8; do
  if run "$np" "$dir/clusters.bin" -o "$dir/parts$np.ele" --stats >"$dir/stats" 2>"$dir/err"; then
    [ -f "$dir/parts$np.parts" ] && [ -f "$dir/parts$np.$((np - 1))-of-$np.ele" ] && pass || fail "parts of $np ranks missing"
    [ ! -e "$dir/parts$np.ele" ] && pass || fail "parts run wrote an ordinary file too"
    "$ridt" check "$dir/clusters.bin" "$dir/parts$np.parts" >"$dir/out" 2>&1 && grep -q "^valid" "$dir/out" && pass ||
      { fail "ridt check on $np parts"; cat "$dir/out"; }
    got=$(tail -n +2 "$dir/stats" | awk -F, '{s += $4} END {print s}')
    want=$(head -1 "$dir/clusters.single.ele" | awk '{print $1}')
    [ "$got" = "$want" ] && pass || fail "$np parts hold $got triangles, not $want"
    rounds=$(tail -n +2 "$dir/stats" | awk -F, 'BEGIN {m = 0} {if ($5 > m) m = $5} END {print m}')
    [ "$rounds" -ge 1 ] && pass || fail "no round of exchange on $np ranks"
    [ "$rounds" -le 3 ] && pass || fail "$rounds rounds of exchange on $np ranks, more than 3"
    # Only the points near a region's border travel, not whole clusters inside wide circles.
    share=$(tail -n +2 "$dir/stats" | awk -F, '{o += $2; r += $3} END {printf "%.3f", r / o}')
    awk -v s="$share" 'BEGIN {exit !(s <= 0.25)}' && pass || fail "$np ranks received $share of the points owned"
  else
    fail "parts on $np ranks"; cat "$dir/err"
  fi
done
# A part that lies: check fails.
sed -i '2d' "$dir/parts4.1-of-4.ele"
"$ridt" check "$dir/clusters.bin" "$dir/parts4.parts" >/dev/null 2>&1 && fail "check passed a damaged part" || pass

# Bad input: one message, exit 2, no output under the final names.
expect_bad() {
  local what=$1 message=$2; shift 2
  run 3 "$@" >"$dir/out" 2>"$dir/err"
  local got=$?
  [ "$got" -ne 0 ] && pass || fail "$what: exit $got"
  grep -q -- "$message" "$dir/err" && pass || { fail "$what: stderr lacks '$message'"; cat "$dir/err"; }
  [ "$(grep -c 'ridt-mpi: error' "$dir/err")" -le 1 ] && pass || fail "$what: more than one message"
  ls "$dir"/bad* >/dev/null 2>&1 && { fail "$what: left $(ls "$dir"/bad*)"; rm -f "$dir"/bad*; } || pass
}
expect_bad "missing file" "cannot read" "$dir/nothing.bin" -o "$dir/bad.ele"
head -c 17 "$dir/uniform.bin" >"$dir/odd.bin"
expect_bad "odd size" "not a whole number" "$dir/odd.bin" -o "$dir/bad.ele"
/usr/bin/python3 -c "import struct,sys; sys.stdout.buffer.write(struct.pack('<6d', 0, 0, 1, float('nan'), 0, 1))" >"$dir/nan.bin"
expect_bad "NaN" "not finite" "$dir/nan.bin" -o "$dir/bad.ele" --merge
expect_bad "text input" "reads .bin" "$dir/uniform.txt" -o "$dir/bad.ele"
expect_bad "output format" "writes .ele" "$dir/uniform.bin" -o "$dir/bad.off"
expect_bad "unwritable" "cannot write" "$dir/uniform.bin" -o "$dir/no/such/dir/bad.ele"
expect_bad "bad option" "unknown option" "$dir/uniform.bin" -o "$dir/bad.ele" --fast
expect_bad "bad threads" "threads" "$dir/uniform.bin" -o "$dir/bad.ele" --threads 0

echo "mpi: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
