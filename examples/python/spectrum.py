#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""An overturning spectrum: a rigid block under one-sine pulses over a grid of normalised
amplitude a_p/(g tan alpha) x frequency omega_p/p, with the minimum overturning amplitude of
every frequency refined by bisection. Writes the spectrum CSV (the layout of `flexrock spectrum`)
and the map.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/spectrum.py -o build/example
"""

import argparse
import pathlib

import numpy as np

import flexrock as fr
from flexrock import plots

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("-o", "--output-dir", default=".", help="where the CSV and the map go")
parser.add_argument("--amplitudes", type=int, default=24, help="grid rows")
parser.add_argument("--frequencies", type=int, default=16, help="grid columns")
parser.add_argument("--threads", type=int, default=0, help="0: every core")
args = parser.parse_args()

# a slender block (alpha = atan(0.25/1.5) = 0.165 rad), 1.5 m half-height
body = fr.Body(fr.rigid_block(width=0.5, height=3.0, mass=1000.0))

# normalised grid: a_p/(g tan alpha) from 1 (static uplift) to 6, omega_p/p from 1 to 10
amplitudes = np.linspace(1.05, 6.0, args.amplitudes)
frequencies = np.linspace(1.0, 10.0, args.frequencies)
result = fr.spectrum(body, amplitudes, frequencies, pulse="one_sine", threads=args.threads,
                     bisection_tolerance=1e-2)

for b in result.boundary:
    if b.kind.name == "found":
        print(f"omega_p/p = {b.frequency:5.2f}: overturns from a_p/(g tan alpha) = "
              f"{b.overturning:.3f} ({b.mode.name})")

out = pathlib.Path(args.output_dir)
out.mkdir(parents=True, exist_ok=True)
csv, boundary = fr.write_spectrum(result, out / "block_spectrum.csv", g=body.g)
print("wrote", csv, boundary)
print("wrote", plots.save(plots.spectrum_map(csv, title="one-sine pulse, alpha = 0.165"),
                          out / "block_spectrum.png"))
