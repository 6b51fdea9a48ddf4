#!/usr/bin/env bash
# `ridt triangulate --out-of-core` end to end: with a memory limit small enough to cut each set
# into many strips, every distribution, degenerate sets, huge and tiny scales and the
# robustness fixtures give exactly the in-memory triangles; the parts pass `ridt check`; bad
# input and a limit too small give a message, exit status 2 and no output.
#   tests/out_of_core_test.sh RIDT FIXTURES_DIR
set -u
ridt=$1 fixtures=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
. "$(dirname "$0")/shell_helpers.sh"

for d in uniform normal grid clusters; do
  "$ridt" generate --dist "$d" -n 30000 --seed 5 -o "$dir/$d.bin" || fail "generate $d"
done
"$ridt" generate --dist uniform -n 200000 --seed 2 -o "$dir/large.bin" || fail "generate large"
/usr/bin/python3 "$(dirname "$0")/point_sets.py" "$dir" "$fixtures" || fail "making the degenerate sets"

# The triangles of the parts named by an index, each from its smallest index, sorted, against
# the in-memory file (already in that order).
same() {
  /usr/bin/python3 - "$1" "$2" <<'EOF'
import os, struct, sys
def triangles(path):
    if path.endswith(".bin"):
        data = open(path, "rb").read()
        out = []
        for k in range(0, len(data), 12):
            t = list(struct.unpack_from("<3I", data, k))
            i = t.index(min(t))
            out.append(tuple(t[i:] + t[:i]))
        return out
    lines = open(path).read().split("\n")[1:]
    out = []
    for line in lines:
        f = line.split()
        if len(f) >= 4:
            t = [int(v) for v in f[1:4]]
            k = t.index(min(t))
            out.append(tuple(t[k:] + t[:k]))
    return out
index, single = sys.argv[1], sys.argv[2]
names = open(index).read().split("\n")[1:]
got = sorted(t for n in names if n for t in triangles(os.path.join(os.path.dirname(index), n)))
want = triangles(single)
sys.exit(0 if got == want else 1)
EOF
}

sets=$(cd "$dir" && ls *.bin | sed 's/\.bin$//')
for s in $sets; do
  in="$dir/$s.bin"
  "$ridt" triangulate "$in" -o "$dir/$s.single.ele" 2>/dev/null
  [ -s "$dir/$s.single.ele" ] && pass || { fail "$s: no in-memory output"; continue; }
  # Columns of some hundred points: most sets in several strips.
  columns=$(($(stat -c %s "$in") / 16 / 120))
  if "$ridt" triangulate "$in" -o "$dir/$s.parts" --out-of-core --memory-limit 50M --threads 2 \
    --column-points $((columns > 20 ? columns : 20)) --stats >"$dir/stats" 2>"$dir/err"; then
    same "$dir/$s.parts" "$dir/$s.single.ele" && pass || fail "$s: not the in-memory triangles"
    "$ridt" check "$in" "$dir/$s.parts" >"$dir/out" 2>&1 && grep -q "^valid" "$dir/out" && pass ||
      { fail "$s: ridt check"; cat "$dir/out"; }
    ls "$dir" | grep -q "$s.*tmp" && fail "$s: left a temporary file" || pass
  else
    fail "$s: exit status $?"; cat "$dir/err"
  fi
done
# The large set runs in many strips, each loading little more than its own columns.
"$ridt" triangulate "$dir/large.bin" -o "$dir/l.parts" --out-of-core --memory-limit 42M --threads 1 --stats >"$dir/stats"
/usr/bin/python3 - "$dir/stats" <<'EOF' && pass || { fail "large: strips"; cat "$dir/stats"; }
import json, sys
s = json.load(open(sys.argv[1]))
assert s["strips"] >= 8 and s["points"] == 200000, s
assert s["loaded"] <= 4 * s["points"], s
EOF

# SIGTERM once the first part is written: the tool ends by that signal and leaves no part, no
# temporary file and no index (the parts stand only together, named by the index).
mkdir -p "$dir/term"
terminate_once "$dir/term/k.0-of-*.bin" -- \
  "$ridt" triangulate "$dir/large.bin" -o "$dir/term/k.parts" --out-of-core --memory-limit 42M --threads 1
[ "$seen" = 1 ] && pass || fail "SIGTERM: no part appeared"
[ "$term_rc" = 143 ] && pass || fail "SIGTERM: exit $term_rc, wanted 143"
[ -z "$(ls -A "$dir/term")" ] && pass || fail "SIGTERM left $(ls "$dir/term")"

# The check of parts reads them in passes: damaged parts are refused (exit status 1), whether a
# triangle is missing or a part is named twice.
"$ridt" triangulate "$dir/large.bin" -o "$dir/d.parts" --out-of-core --memory-limit 42M --threads 1 >/dev/null
part=$(sed -n 2p "$dir/d.parts")
head -c -12 "$dir/$part" >"$dir/short.bin"
{ echo "ridt parts $(($(wc -l <"$dir/d.parts") - 1))"; tail -n +2 "$dir/d.parts" | sed "s|^$part\$|short.bin|"; } >"$dir/short.parts"
{ echo "ridt parts $(wc -l <"$dir/d.parts")"; tail -n +2 "$dir/d.parts"; echo "$part"; } >"$dir/twice.parts"
"$ridt" check "$dir/large.bin" "$dir/d.parts" | grep -q "^valid" && pass || fail "check of whole parts"
for damaged in short twice; do
  "$ridt" check "$dir/large.bin" "$dir/$damaged.parts" >"$dir/out" 2>&1
  got=$?
  [ "$got" -eq 1 ] && grep -q "^invalid" "$dir/out" && pass || { fail "check of $damaged parts: exit $got"; cat "$dir/out"; }
done

# Bad input and usage: a message, exit status 2, nothing written.
expect_bad() {
  local what=$1 message=$2; shift 2
  "$ridt" triangulate "$@" >"$dir/out" 2>"$dir/err"
  local got=$?
  [ "$got" -eq 2 ] && pass || fail "$what: exit $got"
  grep -q -- "$message" "$dir/err" && pass || { fail "$what: stderr lacks '$message'"; cat "$dir/err"; }
  ls "$dir" | grep -q "^bad" && { fail "$what: left $(ls "$dir" | grep '^bad')"; rm -f "$dir"/bad*; } || pass
}
head -c 17 "$dir/uniform.bin" >"$dir/odd.bin"
/usr/bin/python3 -c "import struct,sys; sys.stdout.buffer.write(struct.pack('<6d', 0, 0, 1, float('nan'), 0, 1))" >"$dir/nan.bin"
expect_bad "missing file" "cannot read" "$dir/nothing.bin" -o "$dir/bad.parts" --out-of-core
expect_bad "odd size" "not a multiple of 16" "$dir/odd.bin" -o "$dir/bad.parts" --out-of-core
expect_bad "NaN" "point 1 has a NaN" "$dir/nan.bin" -o "$dir/bad.parts" --out-of-core
expect_bad "no index" "OUT.parts" "$dir/uniform.bin" -o "$dir/bad.ele" --out-of-core
expect_bad "no output" "needs an output" "$dir/uniform.bin" --out-of-core
expect_bad "text input" "reads .bin" "$dir/normal.bin.txt" -o "$dir/bad.parts" --out-of-core
expect_bad "tiny limit" "memory limit of at least" "$dir/uniform.bin" -o "$dir/bad.parts" --out-of-core --memory-limit 8M
expect_bad "method" "takes no --method" "$dir/uniform.bin" -o "$dir/bad.parts" --out-of-core --method optimistic
expect_bad "unwritable" "cannot write" "$dir/uniform.bin" -o "$dir/no/such/dir/bad.parts" --out-of-core

echo "out-of-core: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
