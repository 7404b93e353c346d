#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""One run on a record: a marble statue (rigid block 0.4 m x 1.8 m, 800 kg) under El Centro 1940
N-S, as examples/cases/museum_statue.toml but scripted. Prints the outcome and saves the response
figure and the moment-rotation loop.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/run_record.py -o build/example
"""

import argparse
import pathlib

import flexrock as fr
from flexrock import plots

HERE = pathlib.Path(__file__).resolve().parent
RECORD = HERE.parents[2] / "shared" / "data" / "elcentro_1940_ns.dat"  # beside the repository

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("-o", "--output-dir", default=".", help="where the figures go")
parser.add_argument("--record", default=str(RECORD), help="single-column record in g, dt 0.02 s")
parser.add_argument("--scale", type=float, default=1.0, help="factor on the record")
parser.add_argument("--t-end", type=float, default=-1.0, help="[s] stop early (< 0: whole record)")
args = parser.parse_args()

# the body: a uniform rigid block from its dimensions
body = fr.Body(fr.rigid_block(width=0.4, height=1.8, mass=800.0))
print(f"alpha = {body.alpha1:.3f}, static uplift at {9.80665 * body.alpha1:.2f} m/s^2, "
      f"p = {body.rocking_frequency:.2f} rad/s")

# the record: values in g every 0.02 s, converted to m/s^2
motion = fr.motion_from_file(args.record, "single_column", dt=0.02, units="g", scale=args.scale)

# the run: a time history every 10 ms (the GIL is released: threads may run several at once)
result = fr.simulate(body, motion, name="museum statue", body_type="rigid_block",
                     t_end=args.t_end, output_dt=0.01)
s = result.summary()  # the same keys as `flexrock run`'s summary JSON
print(f"outcome: {s['outcome']['status']}, peak tilt {s['peaks']['max_theta_rad']:.4f} rad, "
      f"{s['peaks']['impacts']} impacts, energy lost {s['energy']['energy_lost_J']:.1f} J")

# the time histories are numpy arrays
theta = result.history.theta
print(f"{len(theta)} samples; largest |theta|/alpha = {abs(theta).max() / body.tipping_angle(1):.3f}")

out = pathlib.Path(args.output_dir)
out.mkdir(parents=True, exist_ok=True)
print("wrote", plots.save(plots.response_figure(result), out / "statue_response.png"))
print("wrote", plots.save(plots.moment_rotation_loop(result), out / "statue_loop.svg"))
