# SPDX-License-Identifier: BSD-3-Clause
"""``python3 -m flexrock.plot FILE [-o OUT.png|OUT.svg] [--kind ...]``: what ``flexrock plot`` runs.

FILE is a run's time-history CSV (its summary JSON and event log are read when next to it) or a
spectrum CSV; the kind is told by the header. Exit codes as the command line's: 0 ok, 1 the
figure could not be made or written, 2 bad input.
"""

from __future__ import annotations

import argparse
import os
import sys


def _error(message: str, code: int) -> int:
    print(f"flexrock: error: {message}", file=sys.stderr)
    return code


def _kind_of(path: str) -> str:
    with open(path, newline="") as f:
        header = f.readline().strip().split(",")
    if "time_s" in header and "theta_rad" in header:
        return "response"
    return "spectrum"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        prog="flexrock plot",
        description="Plot a run's time history (response figure or moment-rotation loop) or an "
        "overturning spectrum, as PNG or SVG.",
    )
    parser.add_argument("file", metavar="RESULT_OR_SPECTRUM", help="time-history CSV or spectrum CSV")
    parser.add_argument(
        "-o",
        "--output",
        help="output file, .png or .svg (default: FILE with .png, or .loop.png for --kind loop)",
    )
    parser.add_argument(
        "--kind",
        choices=["auto", "response", "loop", "spectrum"],
        default="auto",
        help="figure: auto (by the header), response, loop (moment vs theta), spectrum",
    )
    parser.add_argument("--dpi", type=int, default=110, help="PNG resolution (default 110)")
    args = parser.parse_args(argv)

    try:
        from . import plots
    except ImportError as e:
        return _error(
            f"flexrock plot needs matplotlib and numpy for /usr/bin/python3 ({e}); "
            "install python3-matplotlib (scripts/install-deps.sh --python)",
            1,
        )

    if not os.path.isfile(args.file):
        return _error(f"{args.file}: no such file", 2)
    try:
        kind = _kind_of(args.file) if args.kind == "auto" else args.kind
    except (OSError, UnicodeDecodeError) as e:
        return _error(f"{args.file}: cannot read: {e}", 2)
    stem = args.file[:-4] if args.file.endswith(".csv") else args.file
    out = args.output or (stem + (".loop.png" if kind == "loop" else ".png"))
    if os.path.splitext(out)[1].lower() not in (".png", ".svg"):
        return _error(f"{out}: expected an output name ending in .png or .svg", 2)
    try:
        if kind == "response":
            fig = plots.response_figure(args.file)
        elif kind == "loop":
            fig = plots.moment_rotation_loop(args.file)
        else:
            fig = plots.spectrum_map(args.file)
    except (ValueError, KeyError) as e:
        detail = f"missing column {e}" if isinstance(e, KeyError) else str(e)
        return _error(f"{args.file}: {detail}", 2)
    # write to a temporary name, then rename: no half-written figure
    tmp = f"{out}.tmp.{os.getpid()}{os.path.splitext(out)[1]}"
    try:
        plots.save(fig, tmp, dpi=args.dpi)
        os.replace(tmp, out)
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        return _error(f"could not write {out}: {e}", 1)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
