#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The impact laws on ordinary flexible bodies: does a flat-based flexible body rock from edge to
edge, and what does the choice of law change?

The six bodies of tools/validation/contact_grid.py (oscillators on slabs at 1, 2 and 5 Hz, the
example tank, a cabinet cantilever, a transformer on its skid) under El Centro 1940 NS and Kobe
1995 Nishi-Akashi 090 at scales 0.25 ... 3, each run under every impact law of the engine
(`paper`, `rigid_body`, `restitution` with the body's own Housner ratio taken as measured, i.e.
`restitution_ratio` = the rigid twin's theta_dot+/theta_dot-). Per body and law: runs that
uplifted, ordinary impacts (rocking goes on about the other edge), both-edges stops
(`rocking_ended`), chatter cut-offs, landings, fallbacks of `rigid_body`, overturned runs, the
largest max |theta|/theta_c, the impact loss, and the median CPU time of a run.

    PYTHONPATH=build/release/python /usr/bin/python3 tools/validation/impact_laws.py \
        [--md FILE] [--bodies NAME,...] [--records NAME,...] [--scales 0.5,1]
"""

import argparse
import collections
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import contact_grid as grid  # noqa: E402  (the bodies and records, one definition)

import flexrock as fr  # noqa: E402

LAWS = [name for name in fr.ImpactLaw.__members__]


def housner_ratio(body, landing):
    """theta_dot+/theta_dot- of the body taken rigid (its zeta^2 and tipping distances)."""
    p = body.params
    z2, a1, a2 = p.zeta2, p.b1 / p.height, p.b2 / p.height
    a = a1 if landing == 1 else a2
    return max(0.0, (1 + z2 - a1 * a2) / (1 + z2 + a * a))


def options(law, body):
    o = fr.SimulationOptions()
    o.output_dt = 0.0
    o.impact_law = fr.ImpactLaw.__members__[law]
    if law == "restitution":
        o.restitution_ratio_edge1 = housner_ratio(body, 1)
        o.restitution_ratio_edge2 = housner_ratio(body, 2)
    return o


def run(params, record, scale, law):
    body = fr.Body(params)
    m = grid.motion(record, scale)
    o = options(law, body)
    t0 = time.process_time()
    raw = fr.simulate(body, m, options=o).raw
    cpu = time.process_time() - t0
    ev = collections.Counter(grid.name_of(e.kind) for e in raw.events)
    x = raw.extremes
    return dict(uplifted=x.first_uplift_time >= 0.0, impacts=ev.get("impact", 0),
                stops=ev.get("rocking_ended", 0), chatter=ev.get("chatter_cutoff", 0),
                landings=ev.get("landing", 0), fallbacks=x.impact_law_fallbacks,
                overturned=grid.name_of(raw.status) == "overturned",
                stopped=grid.name_of(raw.status) == "stopped", theta=grid.theta_ratio(body, raw),
                loss=raw.energy.impact_loss + raw.energy.chatter_loss, cpu=cpu,
                force=x.max_impact_force, gained=raw.impact_gained_energy)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--md", help="also write the table as a markdown fragment")
    ap.add_argument("--bodies", help="comma-separated subset of: " + ",".join(grid.bodies()))
    ap.add_argument("--records", help="comma-separated subset of: elcentro,kobe")
    ap.add_argument("--scales", help="comma-separated scales (default 0.25,0.5,1,1.5,2,2.5,3)")
    a = ap.parse_args(argv)
    bodies = grid.bodies()
    names = grid.parse_list(a.bodies) if a.bodies else list(bodies)
    records = grid.parse_list(a.records) if a.records else ["elcentro", "kobe"]
    scales = grid.parse_list(a.scales, float) if a.scales else grid.SCALES
    header = ["body", "law", "runs", "uplifted", "impacts", "both-edges stops", "chatter cut-offs",
              "landings", "fallbacks", "overturned", "stopped", "max θ/θc", "impact loss [J]",
              "median CPU [ms]"]
    rows = []
    totals = {law: collections.Counter() for law in LAWS}
    for name in names:
        params, _ = bodies[name]
        for law in LAWS:
            rs = [run(params, rec, s, law) for rec in records for s in scales]
            c = collections.Counter()
            for r in rs:
                for k in ("uplifted", "impacts", "stops", "chatter", "landings", "fallbacks",
                          "overturned", "stopped"):
                    c[k] += int(r[k])
            totals[law].update(c)
            totals[law]["runs"] += len(rs)
            rows.append([name, law, str(len(rs)), str(c["uplifted"]), str(c["impacts"]),
                         str(c["stops"]), str(c["chatter"]), str(c["landings"]),
                         str(c["fallbacks"]), str(c["overturned"]), str(c["stopped"]),
                         f"{max(r['theta'] for r in rs):.3f}",
                         f"{sum(r['loss'] for r in rs):.4g}",
                         f"{1e3 * statistics.median(r['cpu'] for r in rs):.3g}"])
            print(grid.text_table(header, rows[-1:]).splitlines()[-1], flush=True)
    lines = []
    for law in LAWS:
        t = totals[law]
        share = t["impacts"] / max(1, t["impacts"] + t["stops"] + t["chatter"])
        lines.append(f"{law}: {t['runs']} runs, {t['uplifted']} uplifted, {t['impacts']} ordinary "
                     f"impacts, {t['stops']} both-edges stops, {t['chatter']} chatter cut-offs "
                     f"(ordinary share {share:.1%}), {t['overturned']} overturned, "
                     f"{t['fallbacks']} fallbacks, {t['stopped']} stopped")
    print(grid.text_table(header, rows))
    print("\n".join(lines))
    if a.md:
        Path(a.md).write_text(section(header, rows, lines, totals))
    return 0


def section(header, rows, lines, totals):
    """docs/validation.md section 9, as make_report.py includes it."""
    p, r = totals["paper"], totals["rigid_body"]
    impacts_r = r["impacts"] + r["stops"] + r["chatter"]
    return "\n".join([
        "## 9. Impact laws on ordinary flexible bodies",
        "",
        "The six bodies of section 7.1 under El Centro 1940 NS and Kobe 1995 at scales 0.25 ... 3,"
        " each under the three impact laws of docs/theory.md §21 (`restitution` with each body's"
        " own Housner ratio taken as the measured one). Impacts: ordinary impacts (rocking goes on"
        " about the other edge); both-edges stops (`rocking_ended`); chatter cut-offs; landings"
        " after a flight; fallbacks: impacts at which `rigid_body` would have added energy and the"
        " paper's law took over (`impact_law_fallback`). Regenerated by",
        "",
        "    PYTHONPATH=build/release/python /usr/bin/python3 tools/validation/impact_laws.py \\",
        "        --md docs/validation/impact_laws.md",
        "",
        grid.md_table(header, rows),
        "",
        "\n".join(f"- {x}" for x in lines),
        "",
        f"Under the paper's law none of the {p['runs']} runs has an ordinary impact: every landing of"
        " these flat-based flexible bodies is a both-edges stop (section 4.4 shows the same for a"
        " stiff oscillator). Under `rigid_body` the bodies rock from edge to edge"
        f" ({r['impacts']} ordinary impacts), but {r['fallbacks']} of its {impacts_r} impacts"
        " would have added energy and took the paper's law: these bodies' modes (1-50 Hz) are"
        " slower than a 2 ms contact, the paper's regime, not the rigid one (`flexrock params`"
        " names `paper` the closest law for each of them; the cabinet's 50 Hz mode is in"
        " between). `restitution` with the rigid twin's Housner ratio had to take the elastic"
        f" ratio at {totals['restitution']['fallbacks']} impacts, where the deformed body's"
        " S_post/S_pre made the given ratio add energy. The laws give different peaks and"
        " overturning counts on the same runs, so the choice matters; the compliant contact that"
        " would decide between them for a given contact stiffness is not built yet, and the"
        " default stays `paper`, the law whose premise (a contact much shorter than the modal"
        " periods) these bodies meet. The median CPU times are those of one run on a shared"
        " 2-core machine, measured in this script: they are a rough comparison, not a benchmark.",
        "",
    ])


if __name__ == "__main__":
    sys.exit(main())
