#!/usr/bin/env bash
# The tool end to end: generate, triangulate, check, every output format, and every bad input
# with its exit status and without a stray output file.
set -u
ridt=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
. "$(dirname "$0")/shell_helpers.sh"
# expect STATUS DESCRIPTION -- command...
expect() {
  local want=$1 what=$2; shift 3
  "$@" >"$dir/out" 2>"$dir/err"
  local got=$?
  if [ "$got" -eq "$want" ]; then pass; else fail "$what: exit $got, wanted $want"; cat "$dir/err"; fi
}
stderr_has() { if grep -q -- "$1" "$dir/err"; then pass; else fail "stderr lacks '$1'"; cat "$dir/err"; fi; }
stdout_has() { if grep -q -- "$1" "$dir/out"; then pass; else fail "stdout lacks '$1'"; cat "$dir/out"; fi; }
absent() { if [ ! -e "$1" ]; then pass; else fail "$1 should not exist"; fi; }

# The version names the release and the compiler; no subcommand is needed for it.
expect 0 "--version" -- "$ridt" --version
stdout_has "^ridt [0-9][0-9.]* (.*, assertions o[nf]*)$"

# Every distribution, every point format, checked.
for d in uniform normal grid clusters; do
  for ext in txt node bin; do
    expect 0 "generate $d.$ext" -- "$ridt" generate --dist "$d" -n 2000 --seed 3 -o "$dir/$d.$ext"
    expect 0 "triangulate $d.$ext" -- "$ridt" triangulate "$dir/$d.$ext" -o "$dir/$d.$ext.ele"
    expect 0 "check $d.$ext" -- "$ridt" check "$dir/$d.$ext" "$dir/$d.$ext.ele"
    stdout_has "^valid"
  done
done
# Same points in every format give the same file.
cmp -s "$dir/uniform.txt.ele" "$dir/uniform.bin.ele" && pass || fail "txt and bin inputs differ"
cmp -s "$dir/uniform.txt.ele" "$dir/uniform.node.ele" && pass || fail "txt and node inputs differ"
# The seed changes nothing in the output (canonical order).
expect 0 "seed 7" -- "$ridt" triangulate "$dir/grid.txt" --seed 7 -o "$dir/grid7.ele"
cmp -s "$dir/grid.txt.ele" "$dir/grid7.ele" && pass || fail "seed changed the output"
# Same file for the same seed on every run.
expect 0 "regenerate" -- "$ridt" generate --dist normal -n 2000 --seed 3 -o "$dir/again.txt"
cmp -s "$dir/normal.txt" "$dir/again.txt" && pass || fail "generate is not reproducible"
# Without --dist the points are uniform.
expect 0 "generate, no --dist" -- "$ridt" generate -n 2000 --seed 3 -o "$dir/default.txt"
cmp -s "$dir/uniform.txt" "$dir/default.txt" && pass || fail "generate's default is not uniform"

# Every threaded method writes the same file as the serial one, for any thread count.
for m in pessimistic optimistic batch; do
  for t in 1 2 3 8; do
    expect 0 "$m $t" -- "$ridt" triangulate "$dir/grid.txt" --method "$m" --threads "$t" -o "$dir/grid_${m}_$t.ele"
    cmp -s "$dir/grid.txt.ele" "$dir/grid_${m}_$t.ele" && pass || fail "$m with $t threads differs"
  done
done
expect 0 "optimistic stats" -- "$ridt" triangulate "$dir/uniform.txt" --method optimistic --threads 2 --stats
for key in retries time_critical_s per_thread; do stdout_has "\"$key\": "; done
expect 0 "batch stats" -- "$ridt" triangulate "$dir/uniform.txt" --method batch --threads 3 --stats
for key in time_idle_s time_stall_s queue_depth_mean stale_hints; do stdout_has "\"$key\": "; done
stdout_has '"role": "locator"'
expect 0 "batch table" -- "$ridt" triangulate "$dir/uniform.txt" --method batch --threads 2 --stats=table
stdout_has "modifier"
expect 0 "pessimistic paper" -- "$ridt" triangulate "$dir/clusters.txt" --method pessimistic --threads 2 --paper-locking -o "$dir/c_paper.ele"
cmp -s "$dir/clusters.txt.ele" "$dir/c_paper.ele" && pass || fail "paper locking differs"
expect 0 "pessimistic stats" -- "$ridt" triangulate "$dir/uniform.txt" --method pessimistic --threads 2 --stats
for key in time_insert_s time_critical_s time_wait_s per_thread; do stdout_has "\"$key\": "; done
stdout_has '"threads": 2'
expect 0 "pessimistic table" -- "$ridt" triangulate "$dir/uniform.txt" --method pessimistic --threads 2 --stats=table
stdout_has "^ *all "
expect 2 "profile is serial only" -- "$ridt" triangulate "$dir/uniform.txt" --method pessimistic --profile

# Output formats.
for ext in ele neigh off obj svg bin; do
  expect 0 "write .$ext" -- "$ridt" triangulate "$dir/uniform.txt" -o "$dir/u.$ext"
  [ -s "$dir/u.$ext" ] && pass || fail "empty .$ext"
done
expect 0 "check .bin triangles" -- "$ridt" check "$dir/uniform.txt" "$dir/u.bin"
head -c 4 "$dir/u.svg" | grep -q '<' && pass || fail "svg does not start with a tag"

# 1-based .node keeps its numbering in .ele.
printf '4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1.5\n' >"$dir/one.node"
expect 0 "1-based node" -- "$ridt" triangulate "$dir/one.node" -o "$dir/one.ele"
awk 'NR > 1 { for (i = 2; i <= 4; i++) if ($i < 1 || $i > 4) exit 1 }' "$dir/one.ele" && pass || fail "1-based .ele out of range"
expect 0 "check 1-based" -- "$ridt" check "$dir/one.node" "$dir/one.ele"

# --stats is one JSON object with the promised keys; --profile adds Fig. 8's.
expect 0 "stats" -- "$ridt" triangulate "$dir/uniform.txt" --stats --profile
for key in method threads seed points distinct duplicates triangles hull dag_nodes flips \
  time_read_s time_triangulate_s time_write_s peak_rss_bytes time_locate_s time_split_s time_legalize_s; do
  stdout_has "\"$key\": "
done
[ "$(wc -l <"$dir/out")" -eq 1 ] && pass || fail "stats is not one line"
if command -v /usr/bin/python3 >/dev/null; then
  /usr/bin/python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$dir/out" && pass || fail "stats is not JSON"
fi
expect 0 "stats table" -- "$ridt" triangulate "$dir/uniform.txt" --stats=table
stdout_has "^triangles "

# Degenerate input: exit 0, empty output, a warning that says why.
printf '0 0\n1 1\n2 2\n3 3\n' >"$dir/line.txt"
expect 0 "collinear" -- "$ridt" triangulate "$dir/line.txt" -o "$dir/line.ele"
stderr_has "collinear"
expect 0 "check collinear" -- "$ridt" check "$dir/line.txt" "$dir/line.ele"
: >"$dir/empty.txt"
expect 0 "no points" -- "$ridt" triangulate "$dir/empty.txt" -o "$dir/empty.ele"
stderr_has "fewer than three"
expect 0 "check no points" -- "$ridt" check "$dir/empty.txt" "$dir/empty.ele"
stdout_has "^valid: 0 triangles"
printf '1 1\n1 1\n' >"$dir/two.txt"
expect 0 "two points" -- "$ridt" triangulate "$dir/two.txt"
stderr_has "fewer than three"

# The paper's finite bounding triangle with k = 3 loses a hull edge: warned, and check says so.
printf '0 0\n1 0\n0.5 0.03\n0.5 1\n' >"$dir/flat.txt"
expect 0 "finite k 3" -- "$ridt" triangulate "$dir/flat.txt" --bounding finite --k 3 -o "$dir/flat.ele"
stderr_has "lost convex hull edges"
expect 1 "check finite k 3" -- "$ridt" check "$dir/flat.txt" "$dir/flat.ele"
stdout_has "^invalid: convex hull edge"
expect 0 "finite k 10" -- "$ridt" triangulate "$dir/flat.txt" --bounding finite --k 10 -o "$dir/flat10.ele"
expect 0 "check finite k 10" -- "$ridt" check "$dir/flat.txt" "$dir/flat10.ele"

# Bad input: exit 2, a clear message, no output file created or truncated.
expect 2 "missing file" -- "$ridt" triangulate "$dir/nope.txt" -o "$dir/bad1.ele"
stderr_has "cannot read"; absent "$dir/bad1.ele"
printf '0 0\n1 0\n0 1 oops\n' >"$dir/malformed.txt"
expect 2 "malformed line" -- "$ridt" triangulate "$dir/malformed.txt" -o "$dir/bad2.ele"
stderr_has "malformed.txt:3"; absent "$dir/bad2.ele"
printf '0 0\n1 0\nnan 1\n' >"$dir/nan.txt"
expect 2 "NaN" -- "$ridt" triangulate "$dir/nan.txt" -o "$dir/bad3.ele"
stderr_has "NaN"; absent "$dir/bad3.ele"
printf '0 0\ninf 0\n0 1\n' >"$dir/inf.txt"
expect 2 "infinity" -- "$ridt" triangulate "$dir/inf.txt" -o "$dir/bad4.ele"
stderr_has "infinite"; absent "$dir/bad4.ele"
printf '5 2 0 0\n0 0 0\n1 1 0\n2 0 1\n' >"$dir/short.node"
expect 2 ".node count" -- "$ridt" triangulate "$dir/short.node" -o "$dir/bad5.ele"
stderr_has "header says 5 points but the file has 3"; absent "$dir/bad5.ele"
expect 2 "unknown option" -- "$ridt" triangulate "$dir/uniform.txt" --frobnicate -o "$dir/bad6.ele"
absent "$dir/bad6.ele"
# Every order and location writes the same file; the combinations that cannot work say why.
for mode in "--order random" "--order brio" "--locate walk" "--order brio --locate walk" "--order random --locate root" \
  "--locate root --method pessimistic --threads 2 --paper-locking"; do
  expect 0 "mode $mode" -- "$ridt" triangulate "$dir/clusters.txt" $mode -o "$dir/c_mode.ele"
  cmp -s "$dir/clusters.txt.ele" "$dir/c_mode.ele" && pass || fail "$mode changed the output"
done
expect 0 "walk stats" -- "$ridt" triangulate "$dir/uniform.txt" --locate walk --stats
stdout_has '"locate": "walk"'
stdout_has '"dag_nodes": 0'
expect 2 "walk with a threaded method" -- "$ridt" triangulate "$dir/uniform.txt" --locate walk --method optimistic
stderr_has "serial and partition methods only"
expect 0 "default location stats" -- "$ridt" triangulate "$dir/uniform.txt" --stats
stdout_has '"locate": "walk"'
expect 0 "default location in random order" -- "$ridt" triangulate "$dir/uniform.txt" --order random --stats
stdout_has '"locate": "dag"'
expect 2 "partition on the DAG" -- "$ridt" triangulate "$dir/uniform.txt" --method partition --locate dag
stderr_has "keeps no DAG"
expect 0 "root stats" -- "$ridt" triangulate "$dir/uniform.txt" --order random --locate root --stats
stdout_has '"locate": "root"'
expect 2 "partition from the root" -- "$ridt" triangulate "$dir/uniform.txt" --method partition --locate root
stderr_has "keeps no DAG to descend"
expect 2 "partition in random order" -- "$ridt" triangulate "$dir/uniform.txt" --method partition --order random
stderr_has "needs the BRIO order"
expect 2 "walk in random order" -- "$ridt" triangulate "$dir/uniform.txt" --locate walk --order random
stderr_has "needs the BRIO order"
expect 2 "unknown order" -- "$ridt" triangulate "$dir/uniform.txt" --order sorted -o "$dir/bad7.ele"
stderr_has "unknown order"; absent "$dir/bad7.ele"
expect 2 "unknown location" -- "$ridt" triangulate "$dir/uniform.txt" --locate jump -o "$dir/bad8.ele"
stderr_has "unknown location"; absent "$dir/bad8.ele"
expect 2 "unknown method" -- "$ridt" triangulate "$dir/uniform.txt" --method magic -o "$dir/bad9.ele"
stderr_has "unknown method"; absent "$dir/bad9.ele"
expect 2 "unknown bounding" -- "$ridt" triangulate "$dir/uniform.txt" --bounding huge -o "$dir/bad10.ele"
absent "$dir/bad10.ele"
expect 2 "unknown output extension" -- "$ridt" triangulate "$dir/uniform.txt" -o "$dir/out.xyz"
stderr_has "unknown output extension"; absent "$dir/out.xyz"
expect 2 "unknown distribution" -- "$ridt" generate --dist zipf -n 10 -o "$dir/z.txt"
absent "$dir/z.txt"
expect 2 "small k" -- "$ridt" triangulate "$dir/uniform.txt" --bounding finite --k 1 -o "$dir/bad11.ele"
absent "$dir/bad11.ele"
# check: unreadable or malformed inputs are errors (2), not verdicts (0 or 1).
expect 2 "check missing points" -- "$ridt" check "$dir/nope.txt" "$dir/uniform.txt.ele"
stderr_has "cannot read"
expect 2 "check missing triangles" -- "$ridt" check "$dir/uniform.txt" "$dir/nope.ele"
stderr_has "cannot read"
printf '3\n0 0 1 x\n' >"$dir/malformed.ele"
expect 2 "check malformed triangles" -- "$ridt" check "$dir/uniform.txt" "$dir/malformed.ele"
stderr_has "malformed.ele:1"
# Seeds are 64-bit: "-1" and 2^64 are refused, not wrapped or saturated to 2^64 - 1.
for s in -1 18446744073709551616 99999999999999999999999 1.5 0x10; do
  expect 2 "generate --seed $s" -- "$ridt" generate --dist uniform -n 10 --seed "$s" -o "$dir/seed.txt"
  stderr_has "a seed is an integer from 0 to 18446744073709551615, got '$s'"
  absent "$dir/seed.txt"
  expect 2 "triangulate --seed $s" -- "$ridt" triangulate "$dir/uniform.txt" --seed "$s" -o "$dir/seed.ele"
  absent "$dir/seed.ele"
done
expect 0 "seed 2^64 - 1" -- "$ridt" generate --dist uniform -n 10 --seed 18446744073709551615 -o "$dir/seed.txt"
expect 0 "seed 0" -- "$ridt" generate --dist uniform -n 10 --seed 0 -o "$dir/seed0.txt"
cmp -s "$dir/seed.txt" "$dir/seed0.txt" && fail "seeds 0 and 2^64 - 1 gave the same points" || pass
# A vertex index at the bottom of the 64-bit range, against a 1-based .node: named as it was
# written and refused, never wrapped around (the reader once subtracted before comparing).
printf '3 2\n1 0 0\n2 1 0\n3 0 1\n' >"$dir/one3.node"
printf -- '-9223372036854775808 1 2\n' >"$dir/min.txt"
expect 2 "check index -2^63" -- "$ridt" check "$dir/one3.node" "$dir/min.txt"
stderr_has "min.txt:1: vertex index -9223372036854775808 is below the first index 1"
printf '1 2 9223372036854775807\n' >"$dir/max.txt"
expect 2 "check index 2^63-1" -- "$ridt" check "$dir/one3.node" "$dir/max.txt"
stderr_has "max.txt:1: vertex index 9223372036854775807 is too large (at most 4294967296)"
expect 2 "no subcommand" -- "$ridt"
# An existing output is left untouched when the input is bad.
echo keep >"$dir/keep.ele"
expect 2 "bad input keeps old output" -- "$ridt" triangulate "$dir/nan.txt" -o "$dir/keep.ele"
[ "$(cat "$dir/keep.ele")" = keep ] && pass || fail "old output was touched"
# SVG refuses politely above its size limit.
expect 0 "big points" -- "$ridt" generate --dist uniform -n 150000 -o "$dir/big.bin"
expect 2 "svg too big" -- "$ridt" triangulate "$dir/big.bin" -o "$dir/big.svg"
stderr_has "too many"; absent "$dir/big.svg"
# A .bin of triangles is written while the canonical sort puts them in place, on threads: the
# .ele's triangles, and nothing left beside it; into a directory that is not there, nothing.
expect 0 "bin while sorted" -- "$ridt" triangulate "$dir/big.bin" --method partition --threads 2 -o "$dir/big_t.bin"
expect 0 "ele of the same" -- "$ridt" triangulate "$dir/big.bin" --threads 1 -o "$dir/big_t.ele"
od -An -v -tu4 -w12 "$dir/big_t.bin" | awk '{print NR - 1, $1, $2, $3}' >"$dir/big_t.bin.txt"
tail -n +2 "$dir/big_t.ele" | awk '{print $1, $2, $3, $4}' | cmp -s - "$dir/big_t.bin.txt" && pass || fail "streamed .bin differs from .ele"
[ -z "$(find "$dir" -name 'big_t.bin.tmp-*')" ] && pass || fail "a temporary file was left"
expect 2 "bin into no directory" -- "$ridt" triangulate "$dir/big.bin" -o "$dir/none/t.bin"
stderr_has "cannot write"; absent "$dir/none"
# A file system that takes no more (a file size limit, its signal ignored: writes fail with
# EFBIG): a clear error, exit 2, nothing left, for the .bin written from the sorting threads
# and for text written from the formatting waves.
for ext in bin ele; do
  expect 2 "full .$ext" -- bash -c "trap '' XFSZ; ulimit -f 100; exec '$ridt' triangulate '$dir/big.bin' --threads 2 -o '$dir/full.$ext'"
  stderr_has "cannot write .*full.$ext: File too large"
  [ -z "$(find "$dir" -name "full.$ext*")" ] && pass || fail "a part of full.$ext was left"
done

# Progress: a line on stderr when it is a terminal (here a pseudo-terminal from script(1)),
# never when stderr is piped; --stats on stdout stays one JSON object either way.
expect 0 "million points" -- "$ridt" generate --dist uniform -n 1000000 -o "$dir/million.bin"
if command -v script >/dev/null; then
  script -qec "'$ridt' triangulate '$dir/million.bin' --method optimistic --threads 2" /dev/null >"$dir/tty" 2>&1
  grep -q "ridt: inserting .*%" "$dir/tty" && pass || fail "no progress line on a terminal"
else
  echo "cli: script(1) missing, progress on a terminal not tested"
fi
expect 0 "progress piped" -- "$ridt" triangulate "$dir/million.bin" --stats
[ ! -s "$dir/err" ] && pass || fail "stderr not empty when piped"
python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$dir/out" && pass || fail "stats not JSON"

# Voronoi and interpolation: every output format; the values exact on a plane at the points;
# bad arguments refused without output.
expect 0 "voronoi points" -- "$ridt" generate --dist uniform -n 500 --seed 4 -o "$dir/v.txt"
for ext in svg off json; do
  expect 0 "voronoi .$ext" -- "$ridt" voronoi "$dir/v.txt" -o "$dir/v.$ext" --threads 2
done
[ "$(grep -c '<polygon' "$dir/v.svg")" -eq 500 ] && pass || fail "voronoi .svg: not a polygon a site"
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); assert len(d["cells"]) == 500 and len(d["point_cell"]) == 500' \
  "$dir/v.json" && pass || fail "voronoi .json"
awk '{ printf "%.17g\n", 2 * $1 - 3 * $2 + 1 }' "$dir/v.txt" >"$dir/plane.txt"
for m in linear natural nearest; do
  expect 0 "interpolate $m at the points" -- "$ridt" interpolate "$dir/v.txt" "$dir/plane.txt" "$dir/v.txt" \
    --method "$m" -o "$dir/at.csv"
  python3 -c '
import sys
rows = [l.split(",") for l in open(sys.argv[1]).read().split()[1:]]
assert len(rows) == 500
assert all(abs(float(v) - (2 * float(x) - 3 * float(y) + 1)) < 1e-12 for x, y, v in rows)' "$dir/at.csv" \
    && pass || fail "interpolate $m: not the data at the points"
done
expect 0 "interpolate grid .png" -- "$ridt" interpolate "$dir/v.txt" "$dir/plane.txt" --grid 64,48 -o "$dir/g.png" --threads 2
head -c 8 "$dir/g.png" | od -An -c | grep -q "P   N   G" && pass || fail "grid .png is not a PNG"
expect 0 "interpolate grid .bin" -- "$ridt" interpolate "$dir/v.txt" "$dir/plane.txt" --grid 10,10,0,0,1,1 --fill -1 -o "$dir/g.bin"
[ "$(stat -c %s "$dir/g.bin")" -eq 800 ] && pass || fail "grid .bin size"
expect 2 "voronoi bad extension" -- "$ridt" voronoi "$dir/v.txt" -o "$dir/v.txt.png"
stderr_has "unknown Voronoi output extension"
absent "$dir/v.txt.png"
expect 2 "voronoi collinear" -- "$ridt" voronoi <(printf '0 0\n1 1\n2 2\n') -o "$dir/c.svg"
stderr_has "collinear"
absent "$dir/c.svg"
head -n 499 "$dir/plane.txt" >"$dir/short.txt"
expect 2 "interpolate a value short" -- "$ridt" interpolate "$dir/v.txt" "$dir/short.txt" --grid 4,4 -o "$dir/x.csv"
stderr_has "499 rows of values for 500 points"
expect 2 "interpolate queries and grid" -- "$ridt" interpolate "$dir/v.txt" "$dir/plane.txt" "$dir/v.txt" --grid 4,4 -o "$dir/x.csv"
expect 2 "interpolate bad grid" -- "$ridt" interpolate "$dir/v.txt" "$dir/plane.txt" --grid 4 -o "$dir/x.csv"
expect 2 "interpolate .png of queries" -- "$ridt" interpolate "$dir/v.txt" "$dir/plane.txt" "$dir/v.txt" -o "$dir/x.png"
expect 2 "interpolate bad method" -- "$ridt" interpolate "$dir/v.txt" "$dir/plane.txt" --grid 4,4 --method cubic -o "$dir/x.csv"
absent "$dir/x.csv"
absent "$dir/x.png"

# An index of parts (as ridt-mpi writes): the triangles of two .ele files checked as one.
"$ridt" triangulate "$dir/uniform.bin" -o "$dir/whole.ele"
total=$(head -1 "$dir/whole.ele" | awk '{print $1}')
half=$((total / 2))
{ echo "$half 3 0"; sed -n "2,$((half + 1))p" "$dir/whole.ele"; } >"$dir/p.0-of-2.ele"
{ echo "$((total - half)) 3 0"; tail -n +$((half + 2)) "$dir/whole.ele" | awk '{print NR - 1, $2, $3, $4}'; } >"$dir/p.1-of-2.ele"
printf 'ridt parts 2\np.0-of-2.ele\np.1-of-2.ele\n' >"$dir/p.parts"
expect 0 "check parts" -- "$ridt" check "$dir/uniform.bin" "$dir/p.parts"
stdout_has "^valid"
printf 'ridt parts 3\np.0-of-2.ele\np.1-of-2.ele\n' >"$dir/bad.parts"
expect 2 "parts count" -- "$ridt" check "$dir/uniform.bin" "$dir/bad.parts"
stderr_has "names 2"
printf 'ridt parts 1\np.0-of-2.ele\n' >"$dir/half.parts"
expect 1 "half the parts" -- "$ridt" check "$dir/uniform.bin" "$dir/half.parts"
printf 'parts 1\np.0-of-2.ele\n' >"$dir/bad.parts"
expect 2 "parts header" -- "$ridt" check "$dir/uniform.bin" "$dir/bad.parts"
stderr_has "not an index of parts"
printf 'ridt parts 1\nnothing.ele\n' >"$dir/bad.parts"
expect 2 "missing part" -- "$ridt" check "$dir/uniform.bin" "$dir/bad.parts"

# ridt mesh: a .poly in, Triangle's .ele, .node and .edge out; what it cannot do refused, nothing written.
printf '8 2 0 1\n1 0 0 1\n2 10 0 1\n3 10 10 1\n4 0 10 1\n5 4 4 1\n6 6 4 1\n7 6 6 1\n8 4 6 1\n8 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n1\n1 5 5\n' >"$dir/sq.poly"
expect 0 "mesh" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/sq.ele"
[ "$(head -1 "$dir/sq.ele")" = "8 3 0" ] && pass || fail "the holed square is not 8 triangles"
[ "$(head -1 "$dir/sq.node")" = "8 2 0 1" ] && pass || fail "sq.node: its header, with a marker a vertex"
[ "$(head -1 "$dir/sq.edge")" = "8 1" ] && pass || fail "sq.edge"
grep -q '^1 ' "$dir/sq.ele" && pass || fail ".ele not numbered from 1 as its .poly"
# The mesh checked from its files alone (as Triangle's are: no OUT.edge), the hole's boundary
# and an interior segment found along the .poly's segments; a mesh that breaks a segment fails.
expect 0 "check a holed mesh without its edges" -- "$ridt" check "$dir/sq.node" "$dir/sq.ele" --poly "$dir/sq.poly"
stdout_has "(found along them)"
printf '6 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 2\n6 3 2\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n0\n' >"$dir/inner.poly"
expect 0 "mesh -pq30 an interior segment" -- "$ridt" mesh "$dir/inner.poly" -o "$dir/inner.ele" --switches pq30
expect 0 "check an interior segment without its edges" -- "$ridt" check "$dir/inner.node" "$dir/inner.ele" --poly "$dir/inner.poly" --min-angle 30
printf '8 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 2\n6 3 2\n7 2 1.9\n8 2 2.1\n' >"$dir/beside.node"
"$ridt" triangulate "$dir/beside.node" -o "$dir/beside.ele" >/dev/null 2>&1
printf '0 2 0 0\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n0\n' >"$dir/beside.poly"
expect 1 "check a mesh that breaks a segment" -- "$ridt" check "$dir/beside.node" "$dir/beside.ele" --poly "$dir/beside.poly"
stdout_has "segment 4 (4-5)"
expect 0 "mesh -pz" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/z.ele" --switches pz
# O: the holes ignored (the inner square then meshed too: 10 triangles); i, F, l, X and I pick
# Triangle's algorithms and file names: ignored, the same mesh.
expect 0 "mesh -pO" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/sqO.ele" --switches pO
[ "$(head -1 "$dir/sqO.ele")" = "10 3 0" ] && pass || fail "O did not keep the hole's triangles"
expect 0 "mesh -piFlXI" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/sqi.ele" --switches piFlXIQ
cmp -s "$dir/sqi.ele" "$dir/sq.ele" && cmp -s "$dir/sqi.node" "$dir/sq.node" && pass || fail "i, F, l, X, I changed the mesh"
# --size: a target edge length from a grid (ESRI ASCII; the same grid as a GeoTIFF through GDAL
# gives the same mesh), from points (a .node's first attribute) and from a background mesh (a
# .ele and its .node); every triangle's longest edge within the size at its centroid; bad size
# files refused, nothing written.
printf '4 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$dir/ten.poly"
printf 'ncols 3\nnrows 2\nxllcenter 0\nyllcenter 0\ncellsize 5\n1.25 1.75 2.25\n0.25 0.75 1.25\n' >"$dir/h.asc"
expect 0 "mesh --size grid" -- "$ridt" mesh "$dir/ten.poly" -o "$dir/hg.ele" --switches pq30 --size "$dir/h.asc"
expect 0 "check the size-graded mesh" -- "$ridt" check "$dir/hg.node" "$dir/hg.ele" --poly "$dir/ten.poly" --min-angle 30
within_size() {  # MESH.node MESH.ele: every triangle's longest edge <= 0.25 + 0.1 x + 0.2 y at its centroid
  /usr/bin/python3 - "$1" "$2" <<'PY'
import math, sys
node = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")][1:]
ele = [l.split() for l in open(sys.argv[2]) if l.strip() and not l.startswith("#")][1:]
p = {r[0]: (float(r[1]), float(r[2])) for r in node}
assert len(ele) > 300, len(ele)
for r in ele:
    a, b, c = (p[r[1]], p[r[2]], p[r[3]])
    x, y = (a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3
    longest = max(math.dist(a, b), math.dist(b, c), math.dist(c, a))
    assert longest <= (0.25 + 0.1 * x + 0.2 * y) * (1 + 1e-9), (r, longest, x, y)
PY
}
within_size "$dir/hg.node" "$dir/hg.ele" && pass || fail "a triangle above the grid's size"
gdal_translate -q -of GTiff -ot Float64 "$dir/h.asc" "$dir/h.tif" && pass || fail "gdal_translate of the size grid"
expect 0 "mesh --size GeoTIFF" -- "$ridt" mesh "$dir/ten.poly" -o "$dir/ht.ele" --switches pq30 --size "$dir/h.tif"
cmp -s "$dir/hg.ele" "$dir/ht.ele" && cmp -s "$dir/hg.node" "$dir/ht.node" && pass || fail "the GeoTIFF's mesh differs from the .asc's"
printf '4 2 1 0\n1 0 0 0.25\n2 10 0 1.25\n3 10 10 3.25\n4 0 10 2.25\n' >"$dir/hp.node"
expect 0 "mesh --size points" -- "$ridt" mesh "$dir/ten.poly" -o "$dir/hpm.ele" --switches pq30 --size "$dir/hp.node"
within_size "$dir/hpm.node" "$dir/hpm.ele" && pass || fail "a triangle above the points' size"
printf '2 3 0\n1 1 2 3\n2 1 3 4\n' >"$dir/hp.ele"
expect 0 "mesh --size background mesh" -- "$ridt" mesh "$dir/ten.poly" -o "$dir/hm.ele" --switches pq30 --size "$dir/hp.ele"
within_size "$dir/hm.node" "$dir/hm.ele" && pass || fail "a triangle above the background mesh's size"
# --gradation: the grid's sizes lowered where they grow faster than G (this one grows by 0.1 and
# 0.2 a unit): by 0.05 more triangles, each still within the grid's own size; by 0.5 nothing
# lowered, the same files as without; refused without --size or below 0.
expect 0 "mesh --size --gradation" -- "$ridt" mesh "$dir/ten.poly" -o "$dir/hgg.ele" --switches pq30 --size "$dir/h.asc" --gradation 0.05
within_size "$dir/hgg.node" "$dir/hgg.ele" && pass || fail "a triangle above the graded grid's size"
[ "$(head -1 "$dir/hgg.ele" | cut -d' ' -f1)" -gt "$(head -1 "$dir/hg.ele" | cut -d' ' -f1)" ] && pass ||
  fail "a gradation of 0.05 did not make the mesh finer"
expect 0 "mesh --size --gradation above the field's" -- "$ridt" mesh "$dir/ten.poly" -o "$dir/hg5.ele" --switches pq30 --size "$dir/h.asc" --gradation 0.5
cmp -s "$dir/hg.ele" "$dir/hg5.ele" && cmp -s "$dir/hg.node" "$dir/hg5.node" && pass || fail "a gradation above the field's changed it"
expect 2 "--gradation without --size" -- "$ridt" mesh "$dir/ten.poly" -o "$dir/hgx.ele" --switches pq30 --gradation 0.1
expect 2 "--gradation below 0" -- "$ridt" mesh "$dir/ten.poly" -o "$dir/hgx.ele" --switches pq30 --size "$dir/h.asc" --gradation -1
stderr_has "finite number >= 0"
absent "$dir/hgx.ele"
printf 'ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 5\nnodata_value -9999\n1 -9999\n' >"$dir/nodata.asc"
printf 'ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 5\n1 0\n' >"$dir/zero.asc"
for bad in nodata.asc zero.asc ten.poly sq.node missing.tif; do
  expect 2 "mesh --size $bad" -- "$ridt" mesh "$dir/ten.poly" -o "$dir/bad_size.ele" --switches pq30 --size "$dir/$bad"
  absent "$dir/bad_size.ele"
done

# A SIGBUS (an input file cut short while it is mapped) ends the tool with a message and status
# 2, and no output: here sent while the tool waits to open a FIFO no one writes.
mkfifo "$dir/wait.fifo"
"$ridt" triangulate "$dir/wait.fifo" -o "$dir/never.ele" 2>"$dir/err" &
bus_pid=$!
sleep 1
kill -BUS "$bus_pid"
wait "$bus_pid"
bus_rc=$?
[ "$bus_rc" = 2 ] && pass || fail "SIGBUS: exit $bus_rc, wanted 2"
stderr_has "could not be read to its end"
absent "$dir/never.ele"
# SIGTERM while a large file is written (its temporary file seen): the tool ends by that signal,
# and neither the file nor its temporary name is left (the unit tests raise each signal mid-file
# in a writer; this is the tool's).
terminate_once "$dir/killed.txt.tmp-*" -- "$ridt" generate -n 10000000 -o "$dir/killed.txt"
[ "$seen" = 1 ] && pass || fail "SIGTERM: the temporary file never appeared"
[ "$term_rc" = 143 ] && pass || fail "SIGTERM: exit $term_rc, wanted 143"
left=$(find "$dir" -name 'killed.txt*' | wc -l)
[ "$left" = 0 ] && pass || fail "SIGTERM left $left files"
# Extensions in any case: the same formats, the same files.
cp "$dir/sq.poly" "$dir/SQ.POLY"
expect 0 "mesh, upper-case names" -- "$ridt" mesh "$dir/SQ.POLY" -o "$dir/SQ.ELE"
cmp -s "$dir/SQ.ELE" "$dir/sq.ele" && cmp -s "$dir/SQ.node" "$dir/sq.node" && pass || fail "SQ.POLY meshed otherwise"
expect 0 "generate .BIN" -- "$ridt" generate -n 500 --seed 4 -o "$dir/up.BIN"
[ "$(stat -c %s "$dir/up.BIN")" = 8000 ] && pass || fail "up.BIN is not 500 float64 pairs"
expect 0 "triangulate .BIN to .Ele" -- "$ridt" triangulate "$dir/up.BIN" -o "$dir/up.Ele"
expect 0 "check .BIN .Ele" -- "$ridt" check "$dir/up.BIN" "$dir/up.Ele"
sed -n 2p "$dir/z.ele" | grep -q '^0 ' && pass || fail "-z: .ele not numbered from 0"
# An L: its notch is outside the segments (4 triangles), inside the convex hull (5).
printf '6 2
0 0 0
1 2 0
2 2 1
3 1 1
4 1 2
5 0 2
6 0
0 0 1
1 1 2
2 2 3
3 3 4
4 4 5
5 5 0
0
' >"$dir/l.poly"
expect 0 "mesh L" -- "$ridt" mesh "$dir/l.poly" -o "$dir/l.ele"
[ "$(head -1 "$dir/l.ele")" = "4 3 0" ] && pass || fail "the L is not 4 triangles"
expect 0 "mesh L -c" -- "$ridt" mesh "$dir/l.poly" -o "$dir/lc.ele" --convex-hull
[ "$(head -1 "$dir/lc.ele")" = "5 3 0" ] && pass || fail "the L's convex hull is not 5 triangles"
# A quality mesh: Triangle's switches or long options; ridt check validates it (segments as
# chains of OUT.edge's edges, the hole empty, the bounds kept).
expect 0 "mesh quality" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/q.ele" --switches pq30a2
[ "$(head -1 "$dir/q.node" | cut -d' ' -f1)" -gt 8 ] && pass || fail "-q added no points"
expect 0 "check the mesh" -- "$ridt" check "$dir/q.node" "$dir/q.ele" --poly "$dir/sq.poly" --edges "$dir/q.edge" --min-angle 30 --max-area 2
expect 1 "check the mesh, a tighter bound" -- "$ridt" check "$dir/q.node" "$dir/q.ele" --poly "$dir/sq.poly" --edges "$dir/q.edge" --max-area 0.5
# A quality mesh of bare points (its hull the boundary, split) checked without its segments is
# no Delaunay triangulation of its points: refused, with the way to check it as a mesh.
"$ridt" generate -n 300 --seed 3 -o "$dir/s300.node" >/dev/null
expect 0 "mesh bare points" -- "$ridt" mesh "$dir/s300.node" -o "$dir/s300m.ele" --switches q30
expect 1 "check the points' mesh as a triangulation" -- "$ridt" check "$dir/s300m.node" "$dir/s300m.ele"
stderr_has "give its segments: --edges $dir/s300m.edge"
expect 0 "check the points' mesh with its edges" -- "$ridt" check "$dir/s300m.node" "$dir/s300m.ele" --edges "$dir/s300m.edge" --min-angle 30
expect 0 "mesh long options" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/q2.ele" --quality 33 --max-area 1 --neighbours
[ -s "$dir/q2.neigh" ] && pass || fail "--neighbours wrote no .neigh"
expect 0 "check the mesh at 33" -- "$ridt" check "$dir/q2.node" "$dir/q2.ele" --poly "$dir/sq.poly" --edges "$dir/q2.edge" --min-angle 33 --max-area 1
# Markers by Triangle's rule: a segment's pieces keep its marker (7 along y = 0, 9 along
# y = 10), other boundary edges 1, an inner segment (x = 5, unmarked) 0; a vertex its own
# marker where not 0 (3 at the origin), else a marked piece's, else 1 on the boundary, else 0;
# the vertices' attributes are carried, those of the points added interpolated linearly (here
# 2x + 3y + 1 and 7, which that reproduces).
printf '6 2 2 1\n1 0 0 1 7 3\n2 10 0 21 7 0\n3 10 10 51 7 0\n4 0 10 31 7 0\n5 5 2 17 7 0\n6 5 8 35 7 0\n5 1\n1 1 2 7\n2 2 3 0\n3 3 4 9\n4 4 1 0\n5 5 6 0\n0\n' >"$dir/marked.poly"
expect 0 "mesh with markers and attributes" -- "$ridt" mesh "$dir/marked.poly" -o "$dir/marked.ele" --switches pq30a5
/usr/bin/python3 - "$dir/marked" <<'PY' && pass || fail "markers not as Triangle gives them, or attributes not carried"
import sys
rows = lambda ext: [l.split() for l in open(sys.argv[1] + ext) if l.strip() and not l.startswith("#")][1:]
xy = {r[0]: (float(r[1]), float(r[2])) for r in rows(".node")}
seen = set()
for _, a, b, m in rows(".edge"):
    (ax, ay), (bx, by) = xy[a], xy[b]
    want = 7 if ay == by == 0 else 9 if ay == by == 10 else 0 if ax == bx == 5 else 1
    assert int(m) == want, (a, b, m, want)
    seen.add(want)
assert seen == {0, 1, 7, 9}, seen
assert open(sys.argv[1] + ".node").readline().split() == [str(len(xy)), "2", "2", "1"]
for _, x, y, a1, a2, m in rows(".node"):
    x, y = float(x), float(y)
    want = 3 if x == y == 0 else 7 if y == 0 else 9 if y == 10 else 1 if x in (0, 10) else 0
    assert int(m) == want, (x, y, m, want)
    assert abs(float(a1) - (2 * x + 3 * y + 1)) < 1e-12 * 60 and abs(float(a2) - 7) < 1e-13, (x, y, a1, a2)
PY

# Six-node triangles (o2): the same corners, then a node at the middle of each edge, one an edge,
# shared by its two triangles, the exact mean of its ends; its marker and attributes by the
# vertices' rules (the middle of a marked segment edge takes its marker; attributes linear).
expect 0 "mesh with six-node triangles" -- "$ridt" mesh "$dir/marked.poly" -o "$dir/marked6.ele" --switches pq30a5o2
/usr/bin/python3 - "$dir/marked" "$dir/marked6" <<'PY' && pass || fail "six-node triangles wrong"
import sys
rows = lambda base, ext: [l.split() for l in open(base + ext) if l.strip() and not l.startswith("#")]
three, six = rows(sys.argv[1], ".ele"), rows(sys.argv[2], ".ele")
assert six[0] == [three[0][0], "6", "0"], six[0]
assert [r[:4] for r in six[1:]] == [r[:4] for r in three[1:]]  # the same corners
nodes = rows(sys.argv[2], ".node")
xy = {r[0]: (float(r[1]), float(r[2])) for r in nodes[1:]}
first = len(rows(sys.argv[1], ".node")) - 1
middle = {}
for r in six[1:]:
    for k in range(3):
        a, b, m = r[1 + (k + 1) % 3], r[1 + (k + 2) % 3], r[4 + k]
        assert int(m) > first and middle.setdefault(frozenset((a, b)), m) == m, (r, k)
        assert xy[m] == ((xy[a][0] + xy[b][0]) / 2, (xy[a][1] + xy[b][1]) / 2), (r, k)
assert sorted(middle.values(), key=int) == [str(v) for v in range(first + 1, len(nodes))]
for _, x, y, a1, a2, m in nodes[1 + first:]:
    x, y = float(x), float(y)
    want = 7 if y == 0 else 9 if y == 10 else 1 if x in (0, 10) else 0
    assert int(m) == want, (x, y, m, want)
    assert abs(float(a1) - (2 * x + 3 * y + 1)) < 1e-12 * 60 and abs(float(a2) - 7) < 1e-13, (x, y, a1, a2)
PY
expect 0 "mesh --second-order" -- "$ridt" mesh "$dir/marked.poly" -o "$dir/marked6b.ele" --quality 30 --max-area 5 --second-order
cmp -s "$dir/marked6.ele" "$dir/marked6b.ele" && cmp -s "$dir/marked6.node" "$dir/marked6b.node" && pass || fail "--second-order is not o2"
# ridt check takes six-node triangles: their corners as a mesh, then each middle node the rounded
# mean of its edge's ends, one an edge, shared by the edge's triangles; a node moved is found.
expect 0 "check of six-node triangles" -- "$ridt" check "$dir/marked6.node" "$dir/marked6.ele" --poly "$dir/marked.poly" --edges "$dir/marked6.edge" --min-angle 30 --max-area 5
stdout_has "six-node triangles"
awk 'NR == 2 {$7 = $6} {print}' "$dir/marked6.ele" >"$dir/bad6.ele"
expect 1 "check of a six-node triangle with a wrong middle" -- "$ridt" check "$dir/marked6.node" "$dir/bad6.ele" --poly "$dir/marked.poly" --edges "$dir/marked6.edge"
stdout_has "not the middle of its edge"
# A six-node mesh refined: its corners, the middles left unused.
expect 0 "refine a six-node mesh" -- "$ridt" mesh "$dir/marked6.ele" -o "$dir/marked6r.ele" --switches rq30a2o2
expect 0 "check it" -- "$ridt" check "$dir/marked6r.node" "$dir/marked6r.ele" --edges "$dir/marked6r.edge" --min-angle 30 --max-area 2
expect 2 "mesh o3 refused" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/q3.ele" --switches po3
expect 2 "six-node triangles are not drawn" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/m6.svg" --second-order
# Points alone (.node, Triangle's input without -p): their convex hull, Delaunay, and meshed to
# the bounds asked; the output's .node is never the input's.
printf '5 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n5 3 4\n' >"$dir/pts5.node"
expect 0 "mesh of a .node" -- "$ridt" mesh "$dir/pts5.node" -o "$dir/pts5m.ele"
expect 0 "triangulate the .node" -- "$ridt" triangulate "$dir/pts5.node" -o "$dir/pts5t.ele"
cmp -s "$dir/pts5m.ele" "$dir/pts5t.ele" && pass || fail "the mesh of points alone is not their Delaunay triangulation"
expect 0 "quality mesh of a .node" -- "$ridt" mesh "$dir/pts5.node" -o "$dir/pts5q.ele" --switches q30a5
expect 0 "check it" -- "$ridt" check "$dir/pts5q.node" "$dir/pts5q.ele" --min-angle 30 --max-area 5
expect 2 "mesh over its input .node" -- "$ridt" mesh "$dir/pts5.node" -o "$dir/pts5.ele"
printf '0 2 0 0\n' >"$dir/none.node"
expect 2 "mesh of no points" -- "$ridt" mesh "$dir/none.node" -o "$dir/none_m.ele"
stderr_has "no points"
expect 2 "mesh angle out of range" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/q3.ele" --switches pq40
stderr_has "34"; absent "$dir/q3.ele"; absent "$dir/q3.node"
expect 2 "mesh unknown switch" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/q3.ele" --switches pu
stderr_has "'u'"; absent "$dir/q3.ele"
# Triangle's -S: at most N points added by refinement (then a warning), S0 none at all.
expect 0 "mesh with a Steiner limit" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/s.ele" --switches pq30a0.01S10
stderr_has "stopped after 10 points"
[ "$(head -1 "$dir/s.node")" = "18 2 0 1" ] && pass || fail "S10: not the 8 points and 10 added"
expect 0 "the limited mesh is sound" -- "$ridt" check "$dir/s.node" "$dir/s.ele" --poly "$dir/sq.poly" --edges "$dir/s.edge"
expect 0 "mesh --max-steiner" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/s2.ele" --quality 30 --max-area 0.01 --max-steiner 10
cmp -s "$dir/s.ele" "$dir/s2.ele" && cmp -s "$dir/s.node" "$dir/s2.node" && pass || fail "--max-steiner 10 is not S10"
expect 0 "mesh S0" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/s0.ele" --switches pq30a0.01S0
[ "$(head -1 "$dir/s0.node")" = "8 2 0 1" ] && pass || fail "S0 added points"
expect 2 "mesh S with no number" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/q3.ele" --switches pq30S
stderr_has "whole number"; absent "$dir/q3.ele"
# YY: no point on any segment, the one inside the square too (Y keeps only the boundary whole).
printf '6 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n5 2 3\n6 8 6\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n0\n' >"$dir/cut.poly"
expect 0 "mesh YY" -- "$ridt" mesh "$dir/cut.poly" -o "$dir/yy.ele" --switches pq25a1YYC
stderr_has "consistency check: valid"
[ "$(head -1 "$dir/yy.edge")" = "5 1" ] && pass || fail "YY: a segment split"
[ "$(head -1 "$dir/yy.node" | cut -d' ' -f1)" -gt 50 ] && pass || fail "YY: nothing refined"
expect 0 "mesh --no-segment-steiner" -- "$ridt" mesh "$dir/cut.poly" -o "$dir/yy2.ele" --quality 25 --max-area 1 --no-segment-steiner
cmp -s "$dir/yy.ele" "$dir/yy2.ele" && pass || fail "--no-segment-steiner is not YY"
expect 0 "mesh Y" -- "$ridt" mesh "$dir/cut.poly" -o "$dir/y1.ele" --switches pq25a1Y
[ "$(head -1 "$dir/y1.edge" | cut -d' ' -f1)" -gt 5 ] && pass || fail "Y: the inner segment kept whole"
expect 2 "mesh YYD" -- "$ridt" mesh "$dir/cut.poly" -o "$dir/q3.ele" --switches pq30YYD
stderr_has "conforming"; absent "$dir/q3.ele"
expect 0 "mesh conforming" -- "$ridt" mesh "$dir/l.poly" -o "$dir/d.ele" --switches pcD
expect 0 "the conforming mesh is Delaunay" -- "$ridt" check "$dir/d.node" "$dir/d.ele"
# Triangle's -r: a mesh refined, from its .ele and .node, its .edge's segments kept (OUT.edge: the
# holed square's inner segments too), each triangle to its own bound from its .area (-a, no
# number): the first triangle's, tight, the rest none. ridt check validates it against the
# first mesh's segments and the global bound asked.
expect 0 "refine a mesh (-r)" -- "$ridt" mesh "$dir/q.ele" -o "$dir/r.ele" --switches rq30a1
[ "$(head -1 "$dir/r.node" | cut -d' ' -f1)" -gt "$(head -1 "$dir/q.node" | cut -d' ' -f1)" ] && pass || fail "-r added no points"
expect 0 "check the refined mesh" -- "$ridt" check "$dir/r.node" "$dir/r.ele" --poly "$dir/sq.poly" --edges "$dir/r.edge" --min-angle 30 --max-area 1
qn=$(head -1 "$dir/q.ele" | cut -d' ' -f1)
{ echo "$qn"; for i in $(seq 1 "$qn"); do echo "$i 0.01"; done; } >"$dir/q.area"
expect 0 "refine with an .area file" -- "$ridt" mesh "$dir/q.ele" -o "$dir/ra.ele" --switches rq30a
expect 0 "every triangle to its bound" -- "$ridt" check "$dir/ra.node" "$dir/ra.ele" --poly "$dir/sq.poly" --edges "$dir/ra.edge" --min-angle 30 --max-area 0.01
{ echo "$qn"; echo "1 0.01"; for i in $(seq 2 "$qn"); do echo "$i -1"; done; } >"$dir/q.area"
expect 0 "refine one triangle of the .area" -- "$ridt" mesh "$dir/q.ele" -o "$dir/rb.ele" --switches rq30a
rb=$(head -1 "$dir/rb.ele" | cut -d' ' -f1); ra=$(head -1 "$dir/ra.ele" | cut -d' ' -f1)
[ "$rb" -gt "$qn" ] && [ "$rb" -lt "$ra" ] && pass || fail "one triangle's bound: $rb triangles (from $qn; all bounded: $ra)"
expect 0 "check it" -- "$ridt" check "$dir/rb.node" "$dir/rb.ele" --poly "$dir/sq.poly" --edges "$dir/rb.edge" --min-angle 30
{ cat "$dir/sq.poly"; printf '1\n1 1 1 3.5 0\n'; } >"$dir/sqr.poly"
expect 0 "a mesh with attributes" -- "$ridt" mesh "$dir/sqr.poly" -o "$dir/qa.ele" --switches pq30a2A
expect 0 "refined, its attributes carried" -- "$ridt" mesh "$dir/qa.ele" -o "$dir/rqa.ele" --switches rq30a1
[ "$(head -1 "$dir/rqa.ele" | cut -d' ' -f3)" = 1 ] && pass || fail "-r dropped the .ele's attributes"
cp "$dir/sq.poly" "$dir/q.poly"
expect 2 "-rp reads the .poly beside the mesh" -- "$ridt" mesh "$dir/q.ele" -o "$dir/rc.ele" --switches rpq30
stderr_has "vertices; the mesh has"; absent "$dir/rc.ele"
printf '2\n1 0.01\n' >"$dir/q.area"
expect 2 "an .area of the wrong size" -- "$ridt" mesh "$dir/q.ele" -o "$dir/rbad.ele" --switches rqa
stderr_has "the mesh has"; absent "$dir/rbad.ele"
printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n' >"$dir/cw.node"
printf '1 3 0\n1 1 3 2\n' >"$dir/cw.ele"
expect 2 "refine a clockwise triangle" -- "$ridt" mesh "$dir/cw.ele" -o "$dir/rc.ele"
stderr_has "clockwise"; absent "$dir/rc.ele"
printf '4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n' >"$dir/fold.node"
printf '2 3 0\n1 1 2 3\n2 1 2 4\n' >"$dir/fold.ele"
expect 2 "refine a folded mesh" -- "$ridt" mesh "$dir/fold.ele" -o "$dir/rc.ele"
stderr_has "overlap"; absent "$dir/rc.ele"
# A small triangle inside a large one: no vertex shared, no edge crossed, covered twice.
printf '6 2 0 0\n1 0 0\n2 10 0\n3 0 10\n4 1 1\n5 2 1\n6 1 2\n' >"$dir/nest.node"
printf '2 3 0\n1 1 2 3\n2 4 5 6\n' >"$dir/nest.ele"
expect 2 "refine a mesh with a piece inside another" -- "$ridt" mesh "$dir/nest.ele" -o "$dir/rc.ele"
stderr_has "covers the area about"; absent "$dir/rc.ele"
expect 2 "-r of a .poly" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/rd.ele" --switches rq
stderr_has "give its .ele"
# Triangle's switches for the files: e (every edge in .edge: 16 for the holed square's 8
# triangles), B (no marker columns), j (a vertex of no triangle left out: the one in the hole),
# N and E (no .node, no .ele), P (no .poly: none is written anyway), C (the mesh checked, the
# verdict on stderr).
printf '9 2 0 1\n1 0 0 1\n2 10 0 1\n3 10 10 1\n4 0 10 1\n5 4 4 1\n6 6 4 1\n7 6 6 1\n8 4 6 1\n9 5 5 0\n8 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n1\n1 5.5 5.5\n' >"$dir/hp.poly"
expect 0 "mesh -pe" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/he.ele" --switches pe
[ "$(head -1 "$dir/he.edge")" = "16 1" ] && pass || fail "e: not every edge in .edge"
[ "$(awk 'NR > 1 && $4 == 0' "$dir/he.edge" | wc -l)" = 8 ] && pass || fail "e: the 8 edges inside not marked 0"
[ "$(head -1 "$dir/he.node")" = "9 2 0 1" ] && pass || fail "without j the vertex in the hole is kept"
expect 0 "mesh -pBjPC" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hb.ele" --switches pBjPC
stderr_has "consistency check: valid"
[ "$(head -1 "$dir/hb.node")" = "8 2 0 0" ] && pass || fail "B, j: .node not 8 vertices without markers"
[ "$(head -1 "$dir/hb.edge")" = "8 0" ] && pass || fail "B: .edge has markers"
[ "$(awk 'NR > 1 {print NF}' "$dir/hb.edge" | sort -u)" = 3 ] && pass || fail "B: .edge lines have markers"
expect 0 "check the mesh without the jettisoned vertex" -- "$ridt" check "$dir/hb.node" "$dir/hb.ele" --edges "$dir/hb.edge"
# 'e' after a number is the next switch (Triangle's numbers have no exponent but one with digits).
expect 0 "mesh -pq30e" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hq.ele" --switches pq30e
expect 0 "mesh -pqa2e" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hq2.ele" --switches pqa2e
expect 0 "mesh -pq30a1e-1" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hq3.ele" --switches pq30a1e-1
expect 0 "check the area read with its exponent" -- "$ridt" check "$dir/hq3.node" "$dir/hq3.ele" --edges "$dir/hq3.edge" --max-area 0.1
expect 1 "and not a larger one" -- "$ridt" check "$dir/hq3.node" "$dir/hq3.ele" --edges "$dir/hq3.edge" --max-area 0.05
[ "$(head -1 "$dir/hq.edge" | cut -d' ' -f1)" -gt "$(grep -c . "$dir/hq.ele")" ] && pass || fail "q30e: not every edge"
# A mesh written with e refined again: its .edge lists every edge, and only those with a
# nonzero marker (here the boundary) are kept, so the rest can flip and refine freely.
expect 0 "refine a mesh whose .edge lists every edge" -- "$ridt" mesh "$dir/hq.ele" -o "$dir/hqr.ele" --switches rq30a1
expect 0 "check it" -- "$ridt" check "$dir/hqr.node" "$dir/hqr.ele" --edges "$dir/hqr.edge" --min-angle 30 --max-area 1
[ "$(head -1 "$dir/hqr.edge" | cut -d' ' -f1)" -lt "$(head -1 "$dir/hq.edge" | cut -d' ' -f1)" ] && pass || fail "every edge of the .edge kept as a segment"
expect 2 "file switches with a drawing" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hd.svg" --switches pj
stderr_has "not drawn"
expect 2 "v with a drawing" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hd.svg" --switches pv
stderr_has "not drawn"
# j with six-node triangles and numbering from 0: every node kept (all are used), indices from 0.
expect 0 "mesh -pjzo2" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hj6.ele" --switches pjzo2
[ "$(head -1 "$dir/hj6.ele")" = "8 6 0" ] && [ "$(sed -n 2p "$dir/hj6.node" | cut -d' ' -f1)" = 0 ] && pass || fail "j, z, o2"
[ "$(head -1 "$dir/hj6.node" | cut -d' ' -f1)" = 24 ] && pass || fail "j, o2: not 8 corners and 16 middles"
expect 0 "mesh -pNE" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hn.ele" --switches pNEq30
absent "$dir/hn.ele"; absent "$dir/hn.node"
[ -s "$dir/hn.edge" ] && pass || fail "N, E: no .edge either"
# g (.off for a viewer, 0-based, its header counting the edges) and v (the dual: a vertex at each
# triangle's circumcentre, an edge across each inner edge, a ray across each boundary edge).
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n' >"$dir/sq4.node"
expect 0 "mesh -vg" -- "$ridt" mesh "$dir/sq4.node" -o "$dir/sv.ele" --switches vg
[ "$(cat "$dir/sv.v.node")" = "$(printf '2 2 0 0\n1 0.5 0.5\n2 0.5 0.5')" ] && pass || fail "v: .v.node not the two circumcentres"
[ "$(head -1 "$dir/sv.v.edge")" = "5 0" ] && [ "$(awk 'NR > 1 && $3 == -1' "$dir/sv.v.edge" | wc -l)" = 4 ] && pass || fail "v: not 1 edge and 4 rays"
[ "$(awk 'NR > 1 && $3 == -1 {print $4, $5}' "$dir/sv.v.edge" | sort | tr '\n' ,)" = "-1 0,0 -1,0 1,1 0," ] && pass || fail "v: the rays are not the sides' outward normals"
[ "$(head -2 "$dir/sv.off" | tr '\n' ,)" = "OFF,4 2 5," ] && [ "$(tail -1 "$dir/sv.off" | cut -d' ' -f1)" = 3 ] && pass || fail "g: .off header or faces"
expect 0 "mesh -pjgvz" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hg.ele" --switches pjgvz
[ "$(sed -n 2p "$dir/hg.off" | cut -d' ' -f1,2)" = "$(head -1 "$dir/hg.node" | cut -d' ' -f1) $(head -1 "$dir/hg.ele" | cut -d' ' -f1)" ] && pass || fail "g with j: .off not the mesh's vertices and triangles"
[ "$(head -1 "$dir/hg.v.node" | cut -d' ' -f1)" = "$(head -1 "$dir/hg.ele" | cut -d' ' -f1)" ] && pass || fail "v: not a vertex a triangle"
[ "$(awk 'NR > 1 && $3 == -1' "$dir/hg.v.edge" | wc -l)" = 8 ] && pass || fail "v: not a ray across each of the 8 boundary edges (outer and hole)"
[ "$(sed -n 2p "$dir/hg.v.edge" | cut -d' ' -f1)" = 0 ] && pass || fail "v with z: not numbered from 0"
# The vertices' attributes at the circumcentres, from each triangle's linear function of its
# corners': an attribute 2x + 3y + 1 comes out 2x + 3y + 1 at every centre, those outside their
# triangle too (quality meshing off: long thin triangles whose centres lie far outside).
printf '6 2 1 0\n1 0 0 1\n2 4 0 9\n3 4 1 12\n4 0 1 4\n5 2 0.1 5.3\n6 1 0.95 5.85\n' >"$dir/lin.node"
expect 0 "mesh -v with attributes" -- "$ridt" mesh "$dir/lin.node" -o "$dir/linv.ele" --switches v
[ "$(head -1 "$dir/linv.v.node" | cut -d' ' -f2,3)" = "2 1" ] && pass || fail "v: .v.node has no attribute column"
awk 'NR > 1 { d = $4 - (2 * $2 + 3 * $3 + 1); if (d < 0) d = -d; if (d > 1e-9 * (1 + ($2 < 0 ? -$2 : $2) + ($3 < 0 ? -$3 : $3))) bad = 1 }
     END { exit bad }' "$dir/linv.v.node" && pass || fail "v: an attribute at a circumcentre is not the linear one"
[ "$(awk 'NR > 1 && ($2 < 0 || $2 > 4 || $3 < 0 || $3 > 1)' "$dir/linv.v.node" | wc -l)" -gt 0 ] && pass || fail "v: no centre outside the points' box (nothing extrapolated)"
# A sliver whose circumcentre lies beyond the largest double: refused, nothing written.
printf '3 2 1 0\n1 0 0 1\n2 1e200 0 2\n3 5e199 1e-100 3\n' >"$dir/far.node"
expect 2 "mesh -v of a sliver whose centre overflows" -- "$ridt" mesh "$dir/far.node" -o "$dir/farv.ele" --switches v
stderr_has "not finite"; absent "$dir/farv.ele"; absent "$dir/farv.v.node"
mkdir "$dir/hx.v.edge"  # a directory where the dual's edges go: nothing at all is written
expect 2 "mesh -pv over a directory" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hx.ele" --switches pv
absent "$dir/hx.ele"; absent "$dir/hx.node"; absent "$dir/hx.v.node"
expect 2 "switch u" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hs.ele" --switches pu
stderr_has "Quality::unsuitable"; absent "$dir/hs.ele"
expect 2 "switch s" -- "$ridt" mesh "$dir/hp.poly" -o "$dir/hs.ele" --switches ps
stderr_has "unsupported switch 's'"; absent "$dir/hs.ele"
expect 0 "mesh to .svg" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/m.svg" --switches pq30
[ "$(grep -c 'stroke="#c22"' "$dir/m.svg")" -ge 1 ] && pass || fail "the drawing has no segments apart"
expect 2 "mesh to .off" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/m.off"
absent "$dir/m.off"
# An output that is an input is refused before anything is written: a .poly of no vertices reads
# them from the .node beside it, which -o box.ele would overwrite.
mkdir "$dir/own"
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n' >"$dir/own/box.node"
printf '0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$dir/own/box.poly"
cp "$dir/own/box.node" "$dir/own/box.node.orig"
expect 2 "mesh over its own .node" -- "$ridt" mesh "$dir/own/box.poly" -o "$dir/own/box.ele"
stderr_has "is the input"; absent "$dir/own/box.ele"; absent "$dir/own/box.edge"
cmp -s "$dir/own/box.node" "$dir/own/box.node.orig" && pass || fail "mesh overwrote its input .node"
expect 0 "mesh beside its .node" -- "$ridt" mesh "$dir/own/box.poly" -o "$dir/own/out.ele"
expect 2 "triangulate over its input" -- "$ridt" triangulate "$dir/own/box.node" -o "$dir/own/box.node"
ln -s box.node "$dir/own/alias.node"
expect 2 "triangulate through a link to its input" -- "$ridt" triangulate "$dir/own/alias.node" -o "$dir/own/box.node"
cmp -s "$dir/own/box.node" "$dir/own/box.node.orig" && pass || fail "triangulate overwrote its input"
# A mesh that cannot be written removes only what it made: a directory in the way of one of its
# files is an input error, found before any file is written; an unrelated .neigh stays.
echo "not mine" >"$dir/own/e2.neigh"
mkdir "$dir/own/e2.edge"
expect 2 "mesh with a directory as .edge" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/own/e2.ele"
stderr_has "e2.edge: it is a directory"; absent "$dir/own/e2.ele"; absent "$dir/own/e2.node"
[ -d "$dir/own/e2.edge" ] && [ "$(cat "$dir/own/e2.neigh")" = "not mine" ] && pass || fail "mesh removed what it did not make"
mkdir -p "$dir/own/e3.edge/inside"
expect 2 "mesh with a full directory as .edge" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/own/e3.ele" --neighbours
[ -d "$dir/own/e3.edge/inside" ] && pass || fail "mesh emptied a directory"
absent "$dir/own/e3.ele"; absent "$dir/own/e3.neigh"
mkdir "$dir/own/empty.ele"
expect 2 "mesh onto a directory .ele" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/own/empty.ele"
[ -d "$dir/own/empty.ele" ] && pass || fail "mesh removed the directory empty.ele"
absent "$dir/own/empty.node"
[ -z "$(ls "$dir/own" | grep tmp)" ] && pass || fail "a temporary file was left: $(ls "$dir/own")"
# Text formatted on threads (runs of 32768 lines side by side) is the file one thread writes.
awk 'BEGIN { n = 70000; print n, 2, 0, 0
  for (i = 0; i < n; i++) { a = 6.283185307179586 * i / n; r = 1 + 0.2 * sin(37 * a)
    printf "%d %.17g %.17g\n", i, r * cos(a), r * sin(a) }
  print n, 0; for (i = 0; i < n; i++) print i, i, (i + 1) % n; print 0 }' >"$dir/big.poly"
for t in 1 3; do
  expect 0 "mesh of 70000 vertices, $t threads" -- "$ridt" mesh "$dir/big.poly" -o "$dir/big$t.ele" --threads "$t"
done
for ext in ele node edge; do
  cmp -s "$dir/big1.$ext" "$dir/big3.$ext" && pass || fail "mesh's .$ext differs on 3 threads"
done
[ "$(head -1 "$dir/big1.node")" = "70000 2 0 1" ] && pass || fail "big1.node's header"
expect 0 "generate 100000 .node" -- "$ridt" generate -n 100000 --seed 5 -o "$dir/big.node"
expect 0 "generate 100000 .txt" -- "$ridt" generate -n 100000 --seed 5 -o "$dir/big.txt"
expect 0 "generate 100000 .bin" -- "$ridt" generate -n 100000 --seed 5 -o "$dir/big.bin"
for ext in node txt bin; do
  expect 0 "triangulate big.$ext" -- "$ridt" triangulate "$dir/big.$ext" -o "$dir/big.$ext.ele" --threads 1
done
cmp -s "$dir/big.bin.ele" "$dir/big.node.ele" && pass || fail "a threaded .node reads back other points"
cmp -s "$dir/big.bin.ele" "$dir/big.txt.ele" && pass || fail "a threaded text file reads back other points"

# Memory is planned: a run over --memory-limit is refused before it starts, with both numbers.
expect 2 "memory limit" -- "$ridt" triangulate "$dir/uniform.bin" --method serial --memory-limit 1M -o "$dir/mem.ele"
stderr_has "needs about"; stderr_has "is available"; absent "$dir/mem.ele"
expect 0 "memory limit that fits" -- "$ridt" triangulate "$dir/uniform.bin" --method serial --memory-limit 1G --stats
stdout_has '"memory_estimate": '
expect 2 "memory limit not a size" -- "$ridt" triangulate "$dir/uniform.bin" --memory-limit 12Q
stderr_has "not a size"

# Terrain: a table with a header to a TIN and a DEM; GDAL reads every output back, and the DEM
# equals gdal_grid's linear grid (the same Delaunay triangles, at the same cell centres).
"$ridt" generate --dist uniform -n 3000 --seed 5 -o "$dir/t.txt"
awk 'BEGIN { print "Easting,Northing,Elevation" } { printf "%s,%s,%.17g\n", 1000 * $1, 1000 * $2, 100 + 20 * sin(5 * $1) + 30 * $2 }' \
  "$dir/t.txt" >"$dir/t.csv"
expect 0 "tin to .ply" -- "$ridt" tin "$dir/t.csv" -o "$dir/t.ply" --stats
stdout_has "^points 3000$"
expect 0 "tin to .gpkg" -- "$ridt" tin "$dir/t.csv" -o "$dir/t.gpkg"
ntri=$(head -c 400 "$dir/t.ply" | grep -a "element face" | cut -d' ' -f3)
ogrinfo -so "$dir/t.gpkg" tin 2>/dev/null | grep -q "Feature Count: $ntri" && pass || fail "the GeoPackage TIN lacks triangles"
expect 0 "tin to .shp" -- "$ridt" tin "$dir/t.csv" -o "$dir/t.shp"
[ -s "$dir/t.shp" ] && [ -s "$dir/t.dbf" ] && [ -s "$dir/t.shx" ] && pass || fail "the Shapefile is not whole"
expect 0 "dem to .tif" -- "$ridt" dem "$dir/t.csv" -o "$dir/t.tif" --resolution 10 --hillshade "$dir/t.png"
gdalinfo "$dir/t.tif" 2>/dev/null | grep -q "Size is 100, 100" && pass || fail "the DEM is not 100 by 100"
[ "$(head -c 8 "$dir/t.png" | od -An -c | tr -d ' ')" = "211PNG\r\n032\n" ] && pass || fail "the hillshade is not a PNG"
printf '<OGRVRTDataSource><OGRVRTLayer name="t"><SrcDataSource>%s</SrcDataSource><GeometryType>wkbPoint</GeometryType><GeometryField encoding="PointFromColumns" x="Easting" y="Northing"/></OGRVRTLayer></OGRVRTDataSource>\n' \
  "$dir/t.csv" >"$dir/t.vrt"
gdal_grid -q -a linear:radius=0:nodata=nan -zfield Elevation -txe 0 1000 -tye 1000 0 -outsize 100 100 -ot Float64 \
  -l t "$dir/t.vrt" "$dir/g.tif" >/dev/null 2>&1 && pass || fail "gdal_grid failed"
/usr/bin/python3 - "$dir/t.tif" "$dir/g.tif" <<'PY' && pass || fail "the DEM differs from gdal_grid's linear grid"
import sys
import numpy as np
from osgeo import gdal
a = gdal.Open(sys.argv[1]).ReadAsArray()
b = gdal.Open(sys.argv[2]).ReadAsArray()
both = np.isfinite(a) & np.isfinite(b)
assert both.sum() > 0.9 * a.size, both.sum()
assert np.abs(a[both] - b[both]).max() <= 1e-9 * np.abs(b[both]).max(), np.abs(a[both] - b[both]).max()
PY
expect 0 "dem nearest, float32, an extent" -- "$ridt" dem "$dir/t.csv" -o "$dir/n.tif" --resolution 25 --method nearest --type float32 --extent 0,0,500,500
gdalinfo "$dir/n.tif" 2>/dev/null | grep -q "Type=Float32" && pass || fail "--type float32 ignored"
expect 2 "dem without a resolution" -- "$ridt" dem "$dir/t.csv" -o "$dir/x.tif"
absent "$dir/x.tif"
expect 2 "dem to an unknown format" -- "$ridt" dem "$dir/t.csv" -o "$dir/x.jpg" --resolution 10
stderr_has "unknown DEM extension"; absent "$dir/x.jpg"
stderr_has "(use .png, .tif, .tiff or .img)"
expect 2 "a TIN of an unknown format" -- "$ridt" tin "$dir/t.csv" -o "$dir/x.stl"
stderr_has "unknown TIN extension '.stl' (use .ply, .obj, .json, .gpkg"; absent "$dir/x.stl"
expect 2 "LAZ" -- "$ridt" tin "$dir/t.laz" -o "$dir/x.ply"
stderr_has "laszip"
# The registry of formats: every role, each format read or written by the role's command.
expect 0 "formats" -- "$ridt" formats
stdout_has "^terrain in (tin, dem)"; stdout_has "^  .gpkg .shp .geojson"
expect 0 "formats --markdown" -- "$ridt" formats --markdown
stdout_has "^| DEM out (dem) | \`.png\` |"
printf 'a,b\n1,2\n' >"$dir/noz.csv"
expect 2 "a table without z" -- "$ridt" dem "$dir/noz.csv" -o "$dir/x.tif" --resolution 1
stderr_has "no z column"; absent "$dir/x.tif"
printf 'LASF' >"$dir/x.laz"
expect 2 "LAZ" -- "$ridt" tin "$dir/x.laz" -o "$dir/x.ply"
stderr_has "laszip"; absent "$dir/x.ply"
expect 2 "unknown returns" -- "$ridt" tin "$dir/t.csv" -o "$dir/x.ply" --returns second
stderr_has "first, last or single"

# A table's first line is a header only where its coordinate fields are not numbers: a first row
# with a word in a fourth column is a row; a row wider than the first line is refused by line.
printf '0 0 1 99 junk\n10 0 2 98 a\n0 10 3 97 b\n' >"$dir/words.txt"
expect 0 "a table whose rows end in words" -- "$ridt" tin "$dir/words.txt" -o "$dir/words.ply" --stats
stdout_has "^points 3$"
printf '0 0 1\n10 0 2 5\n0 10 3\n' >"$dir/ragged.txt"
expect 2 "a ragged table" -- "$ridt" tin "$dir/ragged.txt" -o "$dir/ragged.ply"
stderr_has "ragged.txt:2: expected 3 fields, as line 1 has, got 4"; absent "$dir/ragged.ply"
printf '0,0,height\n10,0,2\n0,10,3\n' >"$dir/half.csv"
expect 2 "a first line half header" -- "$ridt" tin "$dir/half.csv" -o "$dir/half.ply"
stderr_has "half.csv:1: field 3"

# Outputs that are not regular files: a symbolic link's target is written and the link kept, a
# FIFO and /dev/stdout are written in place, in order (no temporary file, no rename).
expect 0 "generate to a new file" -- "$ridt" generate -n 5 -o "$dir/real.txt"
ln -s real.txt "$dir/link.txt"
expect 0 "generate through a link" -- "$ridt" generate -n 7 -o "$dir/link.txt"
[ -L "$dir/link.txt" ] && pass || fail "the link was replaced"
[ "$(wc -l <"$dir/real.txt")" -eq 7 ] && pass || fail "the link's target was not written"
ln -s made.txt "$dir/dangling.txt"
expect 0 "generate through a dangling link" -- "$ridt" generate -n 3 -o "$dir/dangling.txt"
[ -L "$dir/dangling.txt" ] && [ "$(wc -l <"$dir/made.txt")" -eq 3 ] && pass || fail "a dangling link's target was not made"
mkfifo "$dir/fifo"
timeout 30 cat "$dir/fifo" >"$dir/fifo.out" &
reader=$!
expect 0 "generate into a FIFO" -- timeout 20 "$ridt" generate -n 6 -o "$dir/fifo"
wait "$reader"
[ -p "$dir/fifo" ] && pass || fail "the FIFO was replaced"
[ "$(wc -l <"$dir/fifo.out")" -eq 6 ] && pass || fail "the FIFO's reader got $(wc -l <"$dir/fifo.out") lines"
# A triangulation into a FIFO: the reader gets the bytes the same run writes to a file (a .bin,
# written as the triangles are sorted where it is a file, comes after the sort here).
through_fifo() {
  mkfifo "$dir/fifo.$1"
  timeout 30 cat "$dir/fifo.$1" >"$dir/fifo.$1.out" &
  local reader=$!
  expect 0 "triangulate .$1 into a FIFO" -- timeout 20 "$ridt" triangulate "$dir/uniform.txt" -o "$dir/fifo.$1"
  wait "$reader"
  expect 0 "triangulate to .$1" -- "$ridt" triangulate "$dir/uniform.txt" -o "$dir/plain.$1"
  cmp -s "$dir/fifo.$1.out" "$dir/plain.$1" && pass || fail "the FIFO's .$1 differs"
}
through_fifo ele
through_fifo bin
[ "$(timeout 20 "$ridt" generate -n 5 -o /dev/stdout | wc -l)" -eq 5 ] && pass || fail "-o /dev/stdout printed nothing"
expect 0 "generate to /dev/null" -- "$ridt" generate -n 10 -o /dev/null
if [ -c /dev/null ]; then pass; else
  fail "/dev/null is no longer a character device"
  if [ "$(id -u)" -eq 0 ]; then rm -f /dev/null; mknod -m 666 /dev/null c 1 3; fi
fi
mkdir "$dir/adir.txt"
expect 2 "an output that is a directory" -- "$ridt" generate -n 5 -o "$dir/adir.txt"
stderr_has "is a directory"

# Options that a run would ignore or misread are refused by name (exit 2), nothing written.
for bad in "--max-area nan" "--max-area -1" "--min-angle nan" "--min-angle -5" "--max-area inf"; do
  # shellcheck disable=SC2086
  expect 2 "check $bad" -- "$ridt" check "$dir/q.node" "$dir/q.ele" $bad
  stderr_has "${bad%% *}"
done
expect 2 "mesh --quality nan" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/o1.ele" --quality nan
stderr_has "minimum angle"; absent "$dir/o1.ele"
expect 2 "mesh --switches a1e-400" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/o2.ele" --switches pa1e-400
stderr_has "out of range"; absent "$dir/o2.ele"
expect 2 "mesh --switches a0" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/o2.ele" --switches pa0
stderr_has "positive"
expect 2 "mesh --neighbours to .svg" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/o3.svg" --neighbours
stderr_has "^ridt: error: --neighbours"; absent "$dir/o3.svg"
expect 2 "mesh --attributes to .svg" -- "$ridt" mesh "$dir/sq.poly" -o "$dir/o3.svg" --attributes
stderr_has "^ridt: error: --attributes"; absent "$dir/o3.svg"
for opt in "--seed 5" "--k 3" "--paper-locking"; do
  # shellcheck disable=SC2086
  expect 2 "out-of-core with $opt" -- "$ridt" triangulate "$dir/uniform.bin" -o "$dir/o4.parts" --out-of-core $opt
  stderr_has "${opt%% *}"; absent "$dir/o4.parts"
done
expect 2 "--column-points without --out-of-core" -- "$ridt" triangulate "$dir/uniform.bin" --column-points 9
stderr_has "column-points"
for opt in "--class 2" "--returns first" "--withheld"; do
  # shellcheck disable=SC2086
  expect 2 "tin from a table with $opt" -- "$ridt" tin "$dir/words.txt" -o "$dir/o5.ply" $opt
  stderr_has "^ridt: error: ${opt%% *} is for LAS input"; absent "$dir/o5.ply"
done
expect 2 "dem --hillshade .tif" -- "$ridt" dem "$dir/words.txt" -o "$dir/o6.png" --resolution 1 --hillshade "$dir/o7.tif"
stderr_has "hillshade"; absent "$dir/o6.png"; absent "$dir/o7.tif"
expect 0 "dem --hillshade .png" -- "$ridt" dem "$dir/words.txt" -o "$dir/o6.png" --resolution 1 --hillshade "$dir/o7.png"
cmp -s "$dir/o6.png" "$dir/o7.png" && pass || fail "the hillshade is not the .png DEM's hillshade"

# A point output's extension names its format; one the tool has no point writer for is refused.
expect 0 "generate .csv" -- "$ridt" generate -n 20 --seed 3 -o "$dir/g.csv"
[ "$(head -1 "$dir/g.csv" | tr -cd , | wc -c)" -eq 1 ] && pass || fail "generate's .csv is not x,y"
expect 0 "triangulate the .csv" -- "$ridt" triangulate "$dir/g.csv" -o "$dir/gcsv.ele"
expect 0 "generate .ply" -- "$ridt" generate -n 20 -o "$dir/g.ply"
head -1 "$dir/g.ply" | grep -q '^ply$' && pass || fail "generate's .ply is not PLY"
for ext in ele off svg; do
  expect 2 "generate .$ext" -- "$ridt" generate -n 20 -o "$dir/g.$ext"
  stderr_has "unknown point output extension '.$ext'"; absent "$dir/g.$ext"
done

# Points on a line: nearest still answers, linear and natural are refused rather than all NaN.
printf '0 0\n1 1\n2 2\n3 3\n' >"$dir/iline.txt"
printf '10\n11\n12\n13\n' >"$dir/iline.v"
printf '2.9 2.2\n-5 -5\n10 0\n' >"$dir/iline.q"
expect 0 "nearest on collinear points" -- "$ridt" interpolate "$dir/iline.txt" "$dir/iline.v" "$dir/iline.q" -o "$dir/iline.csv" --method nearest
[ "$(tail -n +2 "$dir/iline.csv" | cut -d, -f3 | tr '\n' ' ')" = "13 10 13 " ] && pass || fail "nearest on a line: $(cat "$dir/iline.csv")"
for m in linear natural; do
  expect 2 "$m on collinear points" -- "$ridt" interpolate "$dir/iline.txt" "$dir/iline.v" --grid 4,4 -o "$dir/iline_$m.csv" --method $m
  stderr_has "no triangle"; absent "$dir/iline_$m.csv"
done

# Memory is checked before it is taken (--memory-limit stands for a small machine).
expect 2 "generate past the memory limit" -- "$ridt" generate -n 1000000 -o "$dir/m1.txt" --memory-limit 1M
stderr_has "generating 1000000 points needs about"; absent "$dir/m1.txt"
expect 0 "generate within the memory limit" -- "$ridt" generate -n 1000 -o "$dir/m1.txt" --memory-limit 1M
expect 2 "interpolate's grid past the memory limit" -- "$ridt" interpolate "$dir/iline.txt" "$dir/iline.v" --grid 1000,1000 -o "$dir/m2.csv" --method nearest --memory-limit 10M
stderr_has "interpolating on 1000 by 1000 nodes needs about"; absent "$dir/m2.csv"

# No NaN or infinity is written: points 1e-310 apart draw a finite viewBox, and a Voronoi
# diagram whose vertices do not fit in a double is written finite or refused, leaving no file.
python3 -c "
import random
random.seed(3)
for _ in range(200): print(repr(random.random() * 1e-310), repr(random.random() * 1e-310))" >"$dir/tiny.txt"
expect 0 "a drawing of points 1e-310 apart" -- "$ridt" triangulate "$dir/tiny.txt" -o "$dir/tiny.svg"
grep -q 'viewBox="-20 -20 [0-9.]* [0-9.]*"' "$dir/tiny.svg" && pass || fail "tiny.svg's viewBox: $(grep -o 'viewBox="[^"]*"' "$dir/tiny.svg")"
python3 -c "
import random
random.seed(3)
for _ in range(200): print(repr(random.random() * 1e150), repr(random.random() * 1e150))" >"$dir/huge.txt"
for ext in json off svg; do  # the circumcentres are finite at any scale
  expect 0 "voronoi of points near 1e150 to .$ext" -- "$ridt" voronoi "$dir/huge.txt" -o "$dir/huge.$ext"
  ! grep -qi 'nan\|inf' "$dir/huge.$ext" && pass || fail "voronoi .$ext wrote a number that is not finite"
done

# GDAL's outputs too: a link's target is written and the link kept; a FIFO gets the file's bytes.
touch "$dir/dem_real.tif"
ln -s dem_real.tif "$dir/dem_link.tif"
expect 0 "dem through a link" -- "$ridt" dem "$dir/t.csv" -o "$dir/dem_link.tif" --resolution 50
[ -L "$dir/dem_link.tif" ] && gdalinfo "$dir/dem_real.tif" 2>/dev/null | grep -q "Size is 20, 20" && pass || fail "dem through a link"
mkfifo "$dir/tin_fifo.geojson"
timeout 30 cat "$dir/tin_fifo.geojson" >"$dir/tin_fifo.out" &
reader=$!
expect 0 "tin into a FIFO" -- timeout 20 "$ridt" tin "$dir/t.csv" -o "$dir/tin_fifo.geojson"
wait "$reader"
grep -q '"FeatureCollection"' "$dir/tin_fifo.out" && [ -p "$dir/tin_fifo.geojson" ] && pass || fail "tin into a FIFO"

# ridt sphere: longitudes and latitudes (a grid: its rows are circles, its poles shared by a
# column each) and x y z; the triangles, the cells and their areas; copies and bad input.
/usr/bin/python3 -c "
for lat in range(-80, 90, 20):
  for lon in range(0, 360, 30): print(lon, lat)
print(0, 90); print(0, -90); print(30, 20)" >"$dir/lonlat.txt"
expect 0 "sphere of longitudes and latitudes" -- "$ridt" sphere "$dir/lonlat.txt" -o "$dir/sphere.off" \
  --voronoi "$dir/cells.off" --areas "$dir/areas.txt" --check
stderr_has "valid: the convex hull of 110 points, 216 triangles"
stderr_has "1 duplicate point dropped"
[ "$(sed -n 2p "$dir/sphere.off")" = "111 216 0" ] && pass || fail "sphere .off header"
[ "$(sed -n 2p "$dir/cells.off")" = "216 110 0" ] && pass || fail "sphere cells .off header"
/usr/bin/python3 -c "
import math, sys
a = [float(x) for x in open(sys.argv[1])]
assert len(a) == 111 and a[110] == 0 and abs(sum(a) - 4 * math.pi) < 1e-12, sum(a)" "$dir/areas.txt" \
  && pass || fail "sphere areas: one a point, the copy's 0, summing to 4 pi"
/usr/bin/python3 -c "
import random
random.seed(3)
for _ in range(2000):
  x, y, z = (random.gauss(0, 1) for _ in range(3)); r = (x * x + y * y + z * z) ** 0.5
  print(5 + 2 * x / r, -1 + 2 * y / r, 2 * z / r)" >"$dir/xyz.txt"
expect 0 "sphere of x y z, text triangles" -- "$ridt" sphere "$dir/xyz.txt" -o "$dir/xyz.tri" --check \
  --areas "$dir/xyz_areas.txt" --center 5,-1,0 --threads 2
[ "$(wc -l <"$dir/xyz.tri")" -eq 3996 ] && pass || fail "sphere: 2n - 4 triangles"
/usr/bin/python3 -c "
import math, sys
a = [float(x) for x in open(sys.argv[1])]
assert abs(sum(a) - 16 * math.pi) < 1e-9, sum(a)" "$dir/xyz_areas.txt" && pass || fail "sphere areas sum to 4 pi r^2"
expect 2 "sphere: coplanar points" -- "$ridt" sphere <(printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n') -o "$dir/flat.off"
absent "$dir/flat.off"
expect 2 "sphere: a latitude past 90" -- "$ridt" sphere <(printf '0 0\n10 95\n') -o "$dir/lat.off"
stderr_has "beyond 90"
expect 2 "sphere: mixed columns" -- "$ridt" sphere <(printf '0 0\n1 2 3\n') -o "$dir/mixed.off"
stderr_has "2: 3 numbers"
expect 2 "sphere: not a number" -- "$ridt" sphere <(printf '0 0\n1 x\n') -o "$dir/nan.off"
expect 2 "sphere: nan" -- "$ridt" sphere <(printf '0 0 1\nnan 0 1\n') -o "$dir/nan.off"
expect 2 "sphere: fewer than four" -- "$ridt" sphere <(printf '0 0\n90 0\n0 90\n') -o "$dir/few.off"
absent "$dir/few.off"

# ridt regular: weighted points as x y w rows and as a .node's first attribute; the power
# diagram; hidden points and copies; bad input.
/usr/bin/python3 -c "
import random
random.seed(5)
with open('$dir/weighted.txt', 'w') as f:
    for i in range(1500):
        f.write(f'{random.random()} {random.random()} {random.random() * 0.003}\\n')
    f.write('0.25 0.75 0.001\\n0.25 0.75 0.001\\n')
"
expect 0 "regular of x y w rows" -- "$ridt" regular "$dir/weighted.txt" -o "$dir/regular.ele" --power "$dir/power.svg" \
  --hidden "$dir/hidden.txt" --check --threads 2
stderr_has "exactly regular"
stderr_has "1 duplicate point dropped"
[ -s "$dir/power.svg" ] && pass || fail "regular: the power diagram written"
/usr/bin/python3 -c "
import sys
tris = [list(map(int, l.split()[1:])) for l in list(open(sys.argv[1]))[1:] if l.strip() and not l.startswith('#')]
hidden = [int(l) for l in open(sys.argv[2])]
used = {v for t in tris for v in t}
assert hidden and not used & set(hidden), 'hidden points are no vertices'
assert len(used) + len(hidden) + 1 == 1502, (len(used), len(hidden))
" "$dir/regular.ele" "$dir/hidden.txt" && pass || fail "regular: every point a vertex, hidden or a copy"
printf '4 2 1 0\n1 1 1 0\n2 0 0 20\n3 4 0 0\n4 0 4 0\n' >"$dir/weighted.node"
expect 0 "regular of a .node's first attribute" -- "$ridt" regular "$dir/weighted.node" -o "$dir/node.ele" \
  --hidden "$dir/node_hidden.txt" --check
[ "$(cat "$dir/node_hidden.txt")" = "1" ] && pass || fail "regular: the .node's point 1 hidden by point 2's weight"
expect 2 "regular: collinear" -- "$ridt" regular <(printf '0 0 0\n1 1 0\n2 2 1\n') -o "$dir/col.ele"
stderr_has "collinear"
absent "$dir/col.ele"
expect 2 "regular: two columns" -- "$ridt" regular <(printf '0 0\n1 0\n0 1\n') -o "$dir/two.ele"
expect 2 "regular: a weight that is not finite" -- "$ridt" regular <(printf '0 0 0\n1 0 inf\n0 1 0\n') -o "$dir/inf.ele"
expect 2 "regular: a .node without attributes" -- "$ridt" regular <(printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n') -o "$dir/na.ele"
# The same from files (read mapped, not through a pipe): the line or the size named, nothing
# written; rows of float64, a last line without its newline, and CRLF lines read.
printf '0 0 0\n1 0 0\n0 1\n1 1 0\n' >"$dir/w_short.txt"
expect 2 "regular: a short row in a file" -- "$ridt" regular "$dir/w_short.txt" -o "$dir/w_short.ele"
stderr_has "w_short.txt:3: expected 3 values, got 2"
absent "$dir/w_short.ele"
printf '0 0 0\n1 0 x\n0 1 0.1\n' >"$dir/w_word.txt"
expect 2 "regular: a word in a file" -- "$ridt" regular "$dir/w_word.txt" -o "$dir/w_word.ele"
stderr_has 'w_word.txt:2: value "x" is not a number'
: >"$dir/w_empty.txt"
expect 2 "regular: an empty file" -- "$ridt" regular "$dir/w_empty.txt" -o "$dir/w_empty.ele"
absent "$dir/w_empty.ele"
/usr/bin/python3 -c "
import struct, sys
open(sys.argv[1], 'wb').write(struct.pack('<12d', 0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, -9))
open(sys.argv[2], 'wb').write(struct.pack('<8d', 0, 0, 0, 1, 0, 0, 0, 1))
" "$dir/w_rows.bin" "$dir/w_odd.bin"
expect 0 "regular of rows of float64" -- "$ridt" regular "$dir/w_rows.bin" -o "$dir/w_rows.ele" --check
stderr_has "3 vertices of 4 points (1 hidden), exactly regular"
expect 2 "regular: float64 rows cut short" -- "$ridt" regular "$dir/w_odd.bin" -o "$dir/w_odd.ele"
stderr_has "size 64 bytes is not a multiple of 24"
absent "$dir/w_odd.ele"
printf '0 0 0\r\n1 0 0\r\n0 1 0.1' >"$dir/w_crlf.txt"
expect 0 "regular: CRLF lines, the last without its end" -- "$ridt" regular "$dir/w_crlf.txt" -o "$dir/w_crlf.ele" --check
stderr_has "exactly regular"

# ridt periodic: points on the torus of a domain; triangles with offsets, neighbours, cells
# whose areas add up to the domain's; points outside refused, nothing written.
/usr/bin/python3 -c "
import random
random.seed(8)
with open('$dir/torus.txt', 'w') as f:
    for i in range(2000):
        f.write(f'{2 + 3 * random.random()} {-1 + 0.5 * random.random()}\\n')
    f.write('2 -1\\n2 -1\\n')
"
expect 0 "periodic on a domain" -- "$ridt" periodic "$dir/torus.txt" --domain 2,-1,5,-0.5 -o "$dir/torus_tri.txt" \
  --neighbors "$dir/torus_nb.txt" --cells "$dir/torus_cells.txt" --check --threads 2
stderr_has "the periodic Delaunay triangulation of 2001 distinct points"
stderr_has "1 duplicate point dropped"
/usr/bin/python3 -c "
import sys
tris = [list(map(int, l.split())) for l in open(sys.argv[1])]
nbs = [list(map(int, l.split())) for l in open(sys.argv[2])]
cells = [list(map(float, l.split())) for l in open(sys.argv[3])]
assert len(tris) == 4002 and len(nbs) == 4002 and len(cells) == 2002, (len(tris), len(nbs), len(cells))
assert all(len(t) == 9 and t[3] == 0 and t[4] == 0 for t in tris)
area = 0
for c in cells:
    xs, ys = c[0::2], c[1::2]
    area += sum(xs[i] * ys[(i + 1) % len(xs)] - xs[(i + 1) % len(xs)] * ys[i] for i in range(len(xs))) / 2
assert abs(area - 1.5) < 1e-9, area
assert cells[2001] == []
" "$dir/torus_tri.txt" "$dir/torus_nb.txt" "$dir/torus_cells.txt" && pass || fail "periodic: 2n triangles, cells tile the domain"
expect 2 "periodic: a point outside the domain" -- "$ridt" periodic <(printf '0.5 0.5\n1 0.5\n') -o "$dir/out.txt"
stderr_has "outside the domain"
absent "$dir/out.txt"
expect 2 "periodic: a domain of three numbers" -- "$ridt" periodic "$dir/torus.txt" --domain 0,0,1 -o "$dir/out.txt"
absent "$dir/out.txt"

echo "cli: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
