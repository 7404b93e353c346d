#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Adds or checks the SPDX licence line that starts every source file.

Source files are C++ (`//` comment), Python, shell and CMake (`#` comment); the line is the first
line of the file, or the second after a shebang (or after a Python encoding line).

    tools/spdx.py            add the line where it is missing (tracked and new, unignored files)
    tools/spdx.py --check    list the files without it and exit 1 (CI); changes nothing
"""
import argparse
import re
import subprocess
import sys
from pathlib import Path

LICENSE = "BSD-3-Clause"
CPP_SUFFIXES = (".cpp", ".hpp", ".cc", ".cxx", ".h", ".hh", ".cpp.in", ".hpp.in", ".h.in")
HASH_SUFFIXES = (".py", ".pyi", ".sh", ".cmake", ".cmake.in")
CODING = re.compile(r"^#.*coding[:=]")


def comment_prefix(path: Path, first_line: str):
    """The comment leader for a source file, or None for a file that is not source."""
    name = path.name
    if name.endswith(CPP_SUFFIXES):
        return "//"
    if name == "CMakeLists.txt" or name.endswith(HASH_SUFFIXES):
        return "#"
    # scripts without a suffix (.ci/run): known by their shebang
    if first_line.startswith("#!") and re.search(r"\b(ba)?sh\b|python", first_line):
        return "#"
    return None


def header_index(lines):
    """Where the SPDX line belongs: after a shebang and a Python encoding line."""
    i = 0
    if i < len(lines) and lines[i].startswith("#!"):
        i += 1
    if i < len(lines) and CODING.match(lines[i]):
        i += 1
    return i


def repo_files(root: Path, include_untracked: bool):
    args = ["git", "-C", str(root), "ls-files", "-z", "--cached"]
    if include_untracked:
        args += ["--others", "--exclude-standard"]
    out = subprocess.run(args, check=True, capture_output=True).stdout
    return sorted({root / p for p in out.decode().split("\0") if p})


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="report files without the SPDX line and exit 1; change nothing")
    parser.add_argument("files", nargs="*", type=Path,
                        help="files to treat (default: the repository's source files)")
    args = parser.parse_args()
    root = Path(__file__).resolve().parent.parent
    # CI checks what is committed; adding also covers files not yet added to git
    files = args.files or repo_files(root, include_untracked=not args.check)

    missing, fixed = [], []
    for path in files:
        if not path.is_file() or path.is_symlink():
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue  # binary data, not source
        lines = text.splitlines(keepends=True)
        prefix = comment_prefix(path, lines[0] if lines else "")
        if prefix is None:
            continue
        wanted = f"{prefix} SPDX-License-Identifier: {LICENSE}"
        i = header_index(lines)
        if i < len(lines) and lines[i].rstrip("\r\n") == wanted:
            continue
        if i < len(lines) and "SPDX-License-Identifier" in lines[i]:
            # another licence or a malformed line: a person must decide, never overwritten
            print(f"{path}:{i + 1}: unexpected SPDX line {lines[i].strip()!r}, "
                  f"expected {wanted!r}", file=sys.stderr)
            missing.append((path, wanted))
            continue
        if args.check:
            missing.append((path, wanted))
            continue
        lines.insert(i, wanted + "\n")
        path.write_text("".join(lines), encoding="utf-8")
        fixed.append(path)

    for path in fixed:
        print(f"added SPDX line: {path.relative_to(root) if path.is_absolute() else path}")
    if missing:
        for path, wanted in missing:
            rel = path.relative_to(root) if path.is_absolute() else path
            print(f"{rel}: the first line (after a shebang) must be '{wanted}' "
                  f"(tools/spdx.py adds it)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
