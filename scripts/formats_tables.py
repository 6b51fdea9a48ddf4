#!/usr/bin/env python3
"""The tables of file formats in README.md and docs/cli.md, as the registry makes them.

    scripts/formats_tables.py RIDT          rewrite them from `RIDT formats`
    scripts/formats_tables.py RIDT --check  fail (exit 1) where either differs

Each table sits between `<!-- ridt formats ARGS -->` and `<!-- end -->`, ARGS the flags the
table is made with.
"""
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
BLOCK = re.compile(r"(<!-- ridt formats (?P<args>[-a-z ]*) -->\n)(?P<table>.*?)(<!-- end -->)", re.S)


def main():
    if len(sys.argv) < 2 or sys.argv[1].startswith("-"):
        sys.exit(__doc__)
    ridt, check = sys.argv[1], "--check" in sys.argv[2:]
    stale = []
    for name in ("README.md", "docs/cli.md"):
        path = ROOT / name
        text = path.read_text()

        def table(m):
            made = subprocess.run([ridt, "formats", *m["args"].split()], check=True, capture_output=True,
                                  text=True).stdout
            if made != m["table"]:
                stale.append(f"{name}: the table of `ridt formats {m['args']}`")
            return m.group(1) + made + m.group(4)

        new, count = BLOCK.subn(table, text)
        if count == 0:
            stale.append(f"{name}: no table of formats (<!-- ridt formats ... --> ... <!-- end -->)")
        elif not check and new != text:
            path.write_text(new)
    if check and stale:
        print("\n".join(stale) + "\nnot as the registry says; run scripts/formats_tables.py build/ridt", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
