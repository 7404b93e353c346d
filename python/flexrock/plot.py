# SPDX-License-Identifier: BSD-3-Clause
"""``python3 -m flexrock.plot FILE [-o OUT.png|.svg|.pdf] [--kind ...]``: what ``flexrock plot`` runs.

FILE is a run's time-history CSV (its summary JSON and event log are read when next to it; a body
of revolution run in 3D gets its own figure, the tilt's orbit and the contact's path), a
spectrum CSV, a sweep CSV (its fragility: fit, band and observed fractions; with ``--kind ida``
its IDA curves) or an output of ``flexrock fragility`` (the fit CSV or the curve CSV); the kind is
told by the header. Exit codes
as the command line's: 0 ok, 1 the figure could not be made or written, 2 bad input. Rows that
are not whole, or nan where a figure needs a number, are drawn around with a warning.
"""

from __future__ import annotations

import argparse
import os
import sys
import warnings

_FORMATS = (".png", ".svg", ".pdf")


def _error(message: str, code: int) -> int:
    print(f"flexrock: error: {message}", file=sys.stderr)
    return code


def _kind_of(path: str) -> str:
    with open(path, newline="") as f:
        header = f.readline().strip().split(",")
    if "time_s" in header and "theta_rad" in header:
        return "response"
    if {"time_s", "mode", "tilt_rad", "tilt_azimuth_deg", "contact_angle_deg"} <= set(header):
        return "rim"  # a body of revolution run in 3D
    if "overturned" in header and "pga_m_per_s2" in header:
        return "fragility"  # a sweep CSV
    if {"theta", "beta", "samples"} <= set(header) or {"probability", "lower", "upper"} <= set(header):
        return "fragility"
    return "spectrum"


# columns a figure needs as numbers, by kind: nan there is drawn as a gap, with a warning
_NEEDED = {
    "response": ("time_s", "theta_rad"),
    "loop": ("theta_rad", "reaction_y_N", "resultant_m"),
    "rim": ("time_s", "tilt_rad", "tilt_azimuth_deg", "contact_angle_deg"),
    "spectrum": ("a_p_over_g_tan_alpha", "omega_p_over_p"),
}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        prog="flexrock plot",
        description="Plot a run's time history (response figure or moment-rotation loop), an "
        "overturning spectrum, or a fragility (from a sweep CSV or a flexrock fragility output) "
        "as PNG, SVG or PDF.",
    )
    parser.add_argument("file", metavar="CSV", help="time-history, spectrum, sweep or fragility CSV")
    parser.add_argument(
        "-o",
        "--output",
        help="output file, .png, .svg or .pdf (default: FILE with .png, or .loop.png for --kind "
        "loop, .fragility.png for a sweep)",
    )
    parser.add_argument(
        "--kind",
        choices=["auto", "response", "loop", "rim", "spectrum", "fragility", "ida"],
        default="auto",
        help="figure: auto (by the header), response, loop (moment vs theta), rim (a body of "
        "revolution run in 3D: tilt orbit and contact path), spectrum, fragility, "
        "ida (a sweep's response against its intensity measure, one curve per record)",
    )
    parser.add_argument(
        "--tlim",
        "--xlim",
        nargs=2,
        type=float,
        metavar=("T0", "T1"),
        default=None,
        help="a time history's window [s] (response, loop and rim figures)",
    )
    parser.add_argument(
        "--measure",
        default="max_theta_over_alpha",
        help="the response of an ida figure: max_theta_over_alpha (default), max_theta_rad, "
        "max_uplift_m, max_impulse_N_s, max_friction_demand, energy_lost_J",
    )
    parser.add_argument(
        "--im",
        default=None,
        help="intensity measure of a sweep's fragility (default pga_g): as flexrock fragility --im; "
        "a fit or curve CSV of flexrock fragility records its own",
    )
    parser.add_argument("--body", default="", help="a fragility's body only (default: each)")
    parser.add_argument(
        "--state",
        default=None,
        help="a fragility's damage state only (overturned, theta:0.5, ...): of a fit or curve CSV "
        "of flexrock fragility --state, or the state a sweep is fitted for",
    )
    parser.add_argument("--dpi", type=int, default=110, help="PNG resolution (default 110)")
    args = parser.parse_args(argv)

    try:
        import matplotlib

        matplotlib.use("Agg")  # a file, never a window
        from matplotlib.figure import Figure

        from . import _csv, plots
    except ImportError as e:
        return _error(
            f"flexrock plot needs matplotlib and numpy for /usr/bin/python3 ({e}); "
            "install python3-matplotlib (scripts/install-deps.sh --python)",
            1,
        )

    try:
        from .studies import FragilityWarning
    except ImportError:
        # the compiled module is not built (scripts/quickstart.sh builds the command only): a time
        # history's figures need numpy and matplotlib alone; the fragility's say so when asked
        FragilityWarning = _csv.CsvWarning

    if not os.path.isfile(args.file):
        return _error(f"{args.file}: no such file", 2)
    try:
        kind = _kind_of(args.file) if args.kind == "auto" else args.kind
    except (OSError, UnicodeDecodeError) as e:
        return _error(f"{args.file}: cannot read: {e}", 2)
    if args.tlim is not None:
        if kind not in ("response", "loop", "rim"):
            return _error(f"--tlim applies to a time history (response, loop or rim figure), not a {kind} figure", 2)
        if not args.tlim[0] < args.tlim[1]:
            return _error(f"--tlim {args.tlim[0]:g} {args.tlim[1]:g}: expected T0 < T1", 2)
    stem = args.file[:-4] if args.file.endswith(".csv") else args.file
    suffix = {"loop": ".loop.png", "fragility": ".fragility.png", "ida": ".ida.png"}.get(kind, ".png")
    out = args.output or (stem + suffix)
    if os.path.splitext(out)[1].lower() not in _FORMATS:
        return _error(f"{out}: expected an output name ending in .png, .svg or .pdf", 2)
    fig = Figure(layout="constrained")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", _csv.CsvWarning)
        warnings.simplefilter("always", FragilityWarning)
        try:
            if kind == "response":
                # a support's and the restraints' panels, when the history has them, make it taller
                with open(args.file, newline="") as f:
                    header = f.readline().strip().split(",")
                extra = ("support_u_m" in header) + any(h.startswith("restraint_force_N_") for h in header)
                fig.set_size_inches(9, 11 + 1.8 * extra)
                plots.response_figure(args.file, xlim=args.tlim, fig=fig)
            elif kind == "rim":
                fig.set_size_inches(11, 8)
                plots.rim_figure(args.file, xlim=args.tlim, fig=fig)
            elif kind == "loop":
                fig.set_size_inches(6, 5)
                plots.moment_rotation_loop(args.file, tlim=args.tlim, fig=fig)
            elif kind == "ida":
                fig.set_size_inches(6, 4.5)
                plots.ida_curves(args.file, im=args.im or "pga_g", measure=args.measure, body=args.body, fig=fig)
            elif kind == "spectrum":
                fig.set_size_inches(7, 5)
                plots.spectrum_map(args.file, fig=fig)
            else:
                fig.set_size_inches(6, 4.5)
                plots.fragility_curve(args.file, im=args.im, body=args.body, state=args.state, fig=fig)
            if kind in _NEEDED:
                with open(args.file, newline="") as f:
                    import csv

                    cols = _csv.columns(list(csv.reader(f)), args.file)
                _csv.warn_nan(cols, _NEEDED[kind], args.file)
        except ImportError as e:
            return _error(f"a {kind} figure needs flexrock's compiled module, which is not built or "
                          f"not importable ({e}): build the target _flexrock (scripts/test.sh "
                          "builds everything)", 1)
        except (ValueError, KeyError, IndexError) as e:
            detail = f"missing column {e}" if isinstance(e, KeyError) else str(e)
            if not detail.startswith(args.file):
                detail = f"{args.file}: {detail}"
            return _error(detail, 2)
    shown = (_csv.CsvWarning, FragilityWarning)
    for message in dict.fromkeys(str(w.message) for w in caught if issubclass(w.category, shown)):
        print(f"flexrock: warning: {message}", file=sys.stderr)
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
