#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Flexible bodies under the two shared records: does every run reach the end of the record?

Six ordinary flexible bodies (oscillators on slabs at 1, 2 and 5 Hz, the example tank, a 2.2 m
cabinet cantilever, a transformer on its base) under El Centro 1940 NS and Kobe 1995
Nishi-Akashi 090 at scales 0.25 ... 3, with the engine's default options. One line a run (status,
study outcome, time reached, uplift, max |theta|/theta_c, impacts, the counts of every event
kind) and the totals: how many runs uplifted, how many ended before the end of the record, by
status.

Statuses, outcomes and event kinds are read by name from the module, so kinds added later (a
flight mode, lift-off and landing events, ...) appear as columns of their own without a change
here.

    PYTHONPATH=build/release/python /usr/bin/python3 tools/validation/contact_grid.py \
        [--md FILE] [--rigid] [--bodies NAME,...] [--records NAME,...] [--scales 0.5,1]
"""

import argparse
import collections
import math
import sys
from pathlib import Path

import flexrock as fr

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT.parent / "shared" / "data"
SCALES = [0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]


def bodies():
    """name -> (BodyParameters, description). Realistic equipment and small structures."""
    out = {}
    # a 800 kg top mass on a lateral spring 2 m above a 400 kg slab 1 m wide (the example study
    # body, examples/studies/oscillator_on_slab.toml), tuned to 1, 2 and 5 Hz
    for f in (1.0, 2.0, 5.0):
        out[f"oscillator_{f:g}hz"] = (
            fr.oscillator_on_slab(top_mass=800.0, frequency_hz=f, base_mass=400.0, height=2.0,
                                  base_width=1.0, damping_ratio=0.02),
            f"oscillator on slab, {f:g} Hz, 800 kg at 2 m on a 400 kg slab 1 m wide, 2 %")
    # the water tank of examples/cases/flexible_tank.toml
    tank, _ = fr.load_body(str(ROOT / "examples" / "cases" / "flexible_tank.toml"))
    out["tank"] = (tank, "examples/cases/flexible_tank.toml: cantilever 6 m x 2 m, 2 modes")
    # a 2.2 m steel cabinet (0.6 m deep, 400 kg with its contents) as a uniform cantilever on a
    # 50 kg plinth: EI chosen for a fixed-base first mode of about 8 Hz
    out["cabinet"] = (
        fr.uniform_cantilever(height=2.2, width=0.6, mass_per_length=180.0,
                              bending_stiffness=8.6e5, modes=2, base_mass=50.0,
                              damping_ratio=0.03),
        "cabinet cantilever 2.2 m x 0.6 m, 396 kg + 50 kg plinth, 2 modes (8 Hz, 50 Hz), 3 %")
    # a distribution transformer on its skid: core, tank and bushings lumped at 1.4 m over a
    # 1.2 m wide skid, 3 Hz on its anchorage-free mounting
    out["transformer"] = (
        fr.oscillator_on_slab(top_mass=6000.0, frequency_hz=3.0, base_mass=2000.0, height=1.4,
                              base_width=1.2, damping_ratio=0.03),
        "transformer on skid, 3 Hz, 6 t at 1.4 m on a 2 t skid 1.2 m wide, 3 %")
    return out


def records():
    """name -> (path, format, keyword arguments of motion_from_file)."""
    return {
        "elcentro": (DATA / "elcentro_1940_ns.dat", "single_column", {"dt": 0.02, "units": "g"}),
        "kobe": (DATA / "kobe_1995_nishi_akashi_090.AT2", "at2", {}),
    }


def motion(record, scale):
    path, fmt, kw = records()[record]
    return fr.motion_from_file(str(path), fmt, scale=scale, **kw)


def name_of(x):
    """The lower-case name of an enum value of the module (or its text)."""
    return getattr(x, "name", str(x))


def theta_ratio(body, raw):
    x = raw.extremes
    return max(x.max_theta_edge1 / body.tipping_angle(1), x.max_theta_edge2 / body.tipping_angle(2))


def outcome_of(body, raw):
    try:
        return name_of(fr.summarize(body, raw).outcome)
    except Exception as e:  # noqa: BLE001 - a tool: report, do not stop the table
        return f"?({e})"


def run_one(params, record, scale, options=None):
    """Simulates one cell; returns a dict of plain values (robust to fields added later)."""
    body = fr.Body(params)
    m = motion(record, scale)
    o = options if options is not None else fr.SimulationOptions()
    o.output_dt = 0.0
    raw = fr.simulate(body, m, options=o).raw
    events = collections.Counter(name_of(e.kind) for e in raw.events)
    x = raw.extremes
    status = name_of(raw.status)
    side = x.overturn_edge if status == "overturned" else 0
    return {
        "record": record,
        "scale": scale,
        "status": status,
        "outcome": outcome_of(body, raw),
        "t_end": raw.t_end,
        "duration": m.duration,
        "early": raw.t_end < m.duration - 1e-9,
        "uplifted": x.first_uplift_time >= 0.0,
        "theta_ratio": theta_ratio(body, raw),
        "impacts": x.impacts,
        "events": events,
        "side": side,
        "chatter_loss": getattr(raw.energy, "chatter_loss", float("nan")),
        "message": raw.message,
        "final_theta": raw.final_theta,
    }


# event kinds shown in fixed columns; every other kind seen gets a column after them
FIXED_EVENTS = ["rocking_ended", "chatter_cutoff"]
SKIP_EVENTS = {"peak"}  # one per half cycle: noise in a table


def event_columns(rows):
    seen = []
    for r in rows:
        for k in r["events"]:
            if k not in seen and k not in FIXED_EVENTS and k not in SKIP_EVENTS:
                seen.append(k)
    return FIXED_EVENTS + sorted(seen)


def table_rows(rows):
    cols = event_columns(rows)
    header = ["body", "record", "scale", "status", "outcome", "t_end [s]", "of [s]", "uplifted",
              "max θ/θc", "impacts"] + cols
    out = []
    for r in rows:
        out.append([r["body"], r["record"], f"{r['scale']:g}", r["status"], r["outcome"],
                    f"{r['t_end']:.3f}", f"{r['duration']:.2f}", "yes" if r["uplifted"] else "no",
                    f"{r['theta_ratio']:.3f}", str(r["impacts"])]
                   + [str(r["events"].get(c, 0)) for c in cols])
    return header, out


def totals(rows):
    up = [r for r in rows if r["uplifted"]]
    early = collections.Counter(r["status"] for r in rows if r["early"])
    early_up = collections.Counter(r["status"] for r in up if r["early"])
    statuses = collections.Counter(r["status"] for r in rows)
    outcomes = collections.Counter(r["outcome"] for r in rows)
    # runs that ended before the end of the record without overturning: no answer
    no_answer = [r for r in rows if r["early"] and r["status"] not in ("overturned",)]
    lines = [
        f"runs: {len(rows)}",
        f"uplifted: {len(up)}",
        "statuses: " + ", ".join(f"{k} {v}" for k, v in sorted(statuses.items())),
        "outcomes: " + ", ".join(f"{k} {v}" for k, v in sorted(outcomes.items())),
        f"ended before the end of the record: {sum(early.values())}"
        + (" (" + ", ".join(f"{k} {v}" for k, v in sorted(early.items())) + ")" if early else ""),
        f"  of those that uplifted: {sum(early_up.values())}"
        + (" (" + ", ".join(f"{k} {v}" for k, v in sorted(early_up.items())) + ")"
           if early_up else ""),
        f"ended early without overturning (no answer): {len(no_answer)}",
    ]
    if no_answer:
        th = [r["theta_ratio"] for r in no_answer]
        te = [r["t_end"] for r in no_answer]
        lines.append(f"  max θ/θc of those {min(th):.3g}..{max(th):.3g}, t_end {min(te):.3g}..{max(te):.3g} s")
    cut = sum(r["events"].get("chatter_cutoff", 0) for r in rows)
    lines.append(f"chatter cut-offs: {cut} in {sum(1 for r in rows if r['events'].get('chatter_cutoff', 0))} runs")
    return lines


def text_table(header, rows):
    w = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(header)]
    line = lambda cells: "  ".join(c.rjust(w[i]) if i >= 2 else c.ljust(w[i]) for i, c in enumerate(cells))
    return "\n".join([line(header), line(["-" * x for x in w])] + [line(r) for r in rows])


def md_table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out)


def parse_list(text, conv=str):
    return [conv(x) for x in text.split(",") if x.strip()]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--md", help="also write the table and totals as a markdown fragment")
    ap.add_argument("--rigid", action="store_true", help="the rigid twins of the bodies (modes removed)")
    ap.add_argument("--bodies", help="comma-separated subset of: " + ",".join(bodies()))
    ap.add_argument("--records", help="comma-separated subset of: elcentro,kobe")
    ap.add_argument("--scales", help="comma-separated scales (default 0.25,0.5,1,1.5,2,2.5,3)")
    ap.add_argument("--messages", action="store_true", help="print the message of every run that did not complete")
    a = ap.parse_args(argv)

    all_bodies = bodies()
    names = parse_list(a.bodies) if a.bodies else list(all_bodies)
    for n in names:
        if n not in all_bodies:
            ap.error(f"--bodies: unknown body {n!r}; expected one of {', '.join(all_bodies)}")
    recs = parse_list(a.records) if a.records else list(records())
    for n in recs:
        if n not in records():
            ap.error(f"--records: unknown record {n!r}; expected elcentro or kobe")
    scales = parse_list(a.scales, float) if a.scales else SCALES

    print("bodies:")
    rows = []
    for n in names:
        params, desc = all_bodies[n]
        if a.rigid:
            params = fr.BodyParameters.rigid(params.mass, params.height, params.b1, params.b2, params.zeta2)
            desc += " (rigid twin)"
        b = fr.Body(params)
        freqs = ", ".join(f"{w / (2 * math.pi):.3g}" for w in b.natural_frequencies) or "rigid"
        print(f"  {n}: {desc}; pinned-base modes [Hz] {freqs}; theta_c {b.tipping_angle(1):.4f}/"
              f"{b.tipping_angle(2):.4f} rad, p {b.rocking_frequency:.3f} rad/s")
        for rec in recs:
            for s in scales:
                r = run_one(params, rec, s)
                r["body"] = n
                rows.append(r)
    header, cells = table_rows(rows)
    print()
    print(text_table(header, cells))
    if a.messages:
        print()
        for r in rows:
            if r["status"] != "completed":
                print(f"{r['body']} {r['record']} x{r['scale']:g}: {r['status']}: {r['message']}")
    tot = totals(rows)
    print()
    print("\n".join(tot))
    if a.md:
        text = md_table(header, cells) + "\n\n" + "\n".join(f"- {t.strip()}" for t in tot) + "\n"
        Path(a.md).write_text(text)
        print(f"\nwrote {a.md}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
