#!/usr/bin/env python3
"""Checks the layout the code keeps to: no source file over 500 lines and no function over 60
(the tests aside), nothing outside src/ and the tests including from src/ (the tools, the
Python module, the benchmarks and the fuzz targets include only include/ridt/ and their own
folders), and every
C++ file as clang-format (14, .clang-format) lays it out. Prints each
breach and exits 1; with --list N, prints the N longest functions too.

    python3 scripts/layout.py [--list N]
"""
from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FOLDERS = ("src", "include", "tools", "python/src", "python/ridt", "python/scipy_suite", "bench", "scripts",
           "fuzz")
MAX_FILE, MAX_FUNCTION = 500, 60
CONTAINER = re.compile(r"\b(namespace|class|struct|union|enum)\b(\s+alignas\([^)]*\))?[^()]*$|extern\s+\"C\"\s*$")


def strip(text: str) -> str:
    """The C++ text with comments, strings and characters blanked, lines kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        m = re.match(r'R"([^(]*)\(', text[i:i + 40])
        if m:
            j = text.find(")" + m.group(1) + '"', i)
            j = n if j < 0 else j + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        if c in "\"'" and not (c == "'" and i > 0 and text[i - 1].isalnum()):  # 1'000 digit separators
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (j - i - 1) + (c if j < n else ""))
            i = j + 1
            continue
        out.append(c)
        i = i + 1
    return "".join(out)


def cpp_functions(path: Path):
    """(name, first line, lines) of each function body outside another function."""
    text = strip(path.read_text())
    found, header_start, i, depth_stack = [], 0, 0, []
    while i < len(text):
        c = text[i]
        if c in ";}":
            if c == "}" and depth_stack:
                depth_stack.pop()
            header_start = i + 1
        elif c == "{":
            header = text[header_start:i]
            if CONTAINER.search(" ".join(header.split())) or "(" not in header:
                if "(" not in header and not CONTAINER.search(" ".join(header.split())):
                    i = matching(text, i)  # an initializer
                    header_start = i + 1
                else:
                    depth_stack.append(i)
                    header_start = i + 1
            else:
                end = matching(text, i)
                first = text.count("\n", 0, header_start + len(header) - len(header.lstrip()))
                last = text.count("\n", 0, end)
                name = re.findall(r"([~\w:]+)\s*\(", header)
                found.append((name[0] if name else "?", first + 1, last - first + 1))
                i, header_start = end, end + 1
        i += 1
    return found


def matching(text: str, i: int) -> int:
    depth = 0
    for j in range(i, len(text)):
        if text[j] == "{":
            depth += 1
        elif text[j] == "}":
            depth -= 1
            if depth == 0:
                return j
    return len(text) - 1


def python_functions(path: Path):
    tree = ast.parse(path.read_text())
    return [(node.name, node.lineno, node.end_lineno - node.lineno + 1) for node in ast.walk(tree)
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))]


def src_includes() -> list:
    """`file:line: includes src/...` for each include of a library source outside src/ and the tests."""
    found = []
    for folder in ("tools", "python/src", "bench", "fuzz"):
        for p in sorted((ROOT / folder).rglob("*")):
            if p.suffix not in (".cpp", ".hpp") or not p.is_file():
                continue
            for number, line in enumerate(p.read_text().splitlines(), 1):
                m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
                if m and (ROOT / "src" / m.group(1)).is_file() and not (p.parent / m.group(1)).is_file():
                    found.append(f"{p.relative_to(ROOT)}:{number}: includes src/{m.group(1)}")
    return found


def unformatted() -> list:
    """The C++ files that clang-format would change."""
    import shutil
    import subprocess
    tool = shutil.which("clang-format-14") or shutil.which("clang-format")
    if tool is None:
        return ["clang-format not found (apt-get install clang-format-14)"]
    files = [str(p) for f in FOLDERS + ("tests",) for p in sorted((ROOT / f).rglob("*"))
             if p.suffix in (".cpp", ".hpp") and p.is_file()]
    found = []
    for k in range(0, len(files), 50):
        r = subprocess.run([tool, "--dry-run", "--Werror", *files[k:k + 50]], capture_output=True, text=True)
        found += sorted({line.split(":")[0] + ": not laid out as .clang-format says (clang-format -i FILE)"
                         for line in r.stderr.splitlines() if "error:" in line})
    return [str(Path(f).relative_to(ROOT)) if f.startswith(str(ROOT)) else f for f in found]


def main() -> int:
    listing = int(sys.argv[sys.argv.index("--list") + 1]) if "--list" in sys.argv else 0
    files = sorted(p for f in FOLDERS for p in (ROOT / f).rglob("*")
                   if p.suffix in (".cpp", ".hpp", ".py") and p.is_file())
    over, functions = [], []
    for p in files:
        rel = p.relative_to(ROOT)
        lines = p.read_text().count("\n")
        if lines > MAX_FILE:
            over.append(f"{rel}: {lines} lines (at most {MAX_FILE})")
        for name, line, length in (python_functions(p) if p.suffix == ".py" else cpp_functions(p)):
            functions.append((length, f"{rel}:{line} {name}"))
            if length > MAX_FUNCTION:
                over.append(f"{rel}:{line}: {name} is {length} lines (at most {MAX_FUNCTION})")
    for length, where in sorted(functions, reverse=True)[:listing]:
        print(f"{length:5d}  {where}")
    print(f"{len(files)} files, {len(functions)} functions; longest file "
          f"{max(p.read_text().count(chr(10)) for p in files)} lines, longest function {max(functions)[0]} lines")
    over += src_includes()
    over += unformatted()
    for line in over:
        print(line)
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
