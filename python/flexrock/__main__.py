# SPDX-License-Identifier: BSD-3-Clause
"""``python -m flexrock`` and the ``flexrock`` command of a pip install: the flexrock command line.

Both run the C++ program installed with the package (``flexrock/_bin/flexrock``), with this
interpreter for ``flexrock plot`` (so that it finds this package, numpy and matplotlib). In a CMake
build tree (``PYTHONPATH=build/release/python``) the build's own program is run instead.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import NoReturn, Optional, Sequence


def _program() -> Path:
    override = os.environ.get("FLEXROCK_CLI")
    if override:
        return Path(override)
    here = Path(__file__).resolve().parent
    candidates = (
        here / "_bin" / "flexrock",  # installed by pip
        here.parent.parent / "apps" / "flexrock",  # a CMake build: <build>/python/flexrock
    )
    for candidate in candidates:
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return candidate
    sys.stderr.write(
        f"flexrock: error: the flexrock program is not installed with the package in {here} "
        f"(looked for {', '.join(str(c) for c in candidates)}); reinstall with `pip install .` "
        f"or set FLEXROCK_CLI to the program\n")
    sys.exit(1)


def main(argv: Optional[Sequence[str]] = None) -> NoReturn:
    """Runs the command line with ``argv`` (default: this process's arguments); never returns."""
    program = _program()
    args = list(sys.argv[1:] if argv is None else argv)
    # `flexrock plot` runs this interpreter, which sees this package
    os.environ.setdefault("FLEXROCK_PYTHON", sys.executable)
    sys.stdout.flush()
    sys.stderr.flush()
    os.execv(program, [str(program), *args])


if __name__ == "__main__":
    main()
