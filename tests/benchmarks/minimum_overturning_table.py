#!/usr/bin/python3
"""The slender block's minimum overturning amplitudes, Housner's restitution against a measured one:
a markdown table.

Not a test: runs the four spectra of a block of alpha = 0.25 rad, R = 1 m (Housner's rocking block,
400 amplitudes from 0.9 to 6 at omega_p / p = 1, 2, 3, the refinement on with its defaults):
configs/slender_block_sine_spectrum.json and configs/slender_block_cosine_spectrum.json (every
rocking impact keeps Housner's 1 - 1.5 sin^2 alpha = 0.9082 of the angular velocity) and
configs/slender_block_sine_measured_r_spectrum.json and
configs/slender_block_cosine_measured_r_spectrum.json (r = 0.873, ElGawady et al.'s measured over
predicted coefficient for concrete blocks times Housner's; docs/validation.md says how it is
chosen). For each pulse and frequency it prints the minimum overturning amplitude a_p / (g tan
alpha) without the refinement (the map's lowest onset, bisected) and with it, for both restitutions.
A minimum the refinement did not find to its tolerance is printed with its state
(/minimum_overturning/state, docs/spectra.md).

    /usr/bin/python3 tests/benchmarks/minimum_overturning_table.py --blockfrag build/mpi_driver/blockfrag [--markdown]

--markdown prints under the table the line docs/validation.md shows under it
(tests/benchmarks/markdown_stamp.py). The spectra write into a temporary folder, removed at the end.
"""

import argparse
import concurrent.futures
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

from markdown_stamp import Stamp

SOURCE = Path(__file__).resolve().parents[2]
PULSES = (("one-sine", "sine"), ("one-cosine", "cosine"))
RESTITUTIONS = (("Housner's r", ""), ("measured r", "_measured_r"))
FOUND = 1  # /minimum_overturning/state: found to the tolerance


def config(pulse, restitution):
    return SOURCE / "configs" / f"slender_block_{pulse}{restitution}_spectrum.json"


def minima(blockfrag, spec, folder):
    """(frequency ratios, the map's lowest onsets, the refined minima, their states) of one spectrum."""
    output = Path(folder) / (spec.stem + ".h5")
    result = subprocess.run([str(blockfrag), "spectrum", str(spec), "--output", str(output)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, timeout=1200)
    if result.returncode != 0:
        raise RuntimeError(f"{spec.name}: blockfrag exited with {result.returncode}:\n{result.stderr[-2000:]}")
    with h5py.File(output, "r") as f:
        group = f["/minimum_overturning"]
        return tuple(np.asarray(group[key][()]) for key in
                     ("frequency_ratio", "map_amplitude_ratio", "amplitude_ratio", "state"))


def rocking_restitution(spec):
    """The spec's r: its number, or Housner's 1 - 1.5 sin^2 alpha where it sets none."""
    r = spec["contact"].get("rocking_restitution", "housner")
    return 1.0 - 1.5 * math.sin(spec["block"]["alpha"]) ** 2 if r == "housner" else r


def refined_cell(value, state):
    return f"{value:.6f}" if state == FOUND else f"{value:.6f} (state {int(state)})"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--blockfrag", default=str(SOURCE / "build" / "mpi_driver" / "blockfrag"))
    parser.add_argument("--markdown", action="store_true", help="print the stamp line under the table")
    args = parser.parse_args()
    blockfrag = Path(args.blockfrag).resolve()
    stamp = Stamp(blockfrag) if args.markdown else None
    specs = {label: json.loads(config("sine", suffix).read_text()) for label, suffix in RESTITUTIONS}
    cases = [(pulse, suffix) for _, pulse in PULSES for _, suffix in RESTITUTIONS]
    with tempfile.TemporaryDirectory(prefix="blockfrag_minimum_overturning_") as folder:
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            spectra = dict(zip(cases, pool.map(lambda c: minima(blockfrag, config(*c), folder), cases)))
    header = ["pulse", "omega_p / p"]
    for label, _ in RESTITUTIONS:
        header += [f"{label} = {rocking_restitution(specs[label]):.4g}: map's lowest onset", f"{label}: refined"]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for pulse_label, pulse in PULSES:
        frequencies = spectra[(pulse, RESTITUTIONS[0][1])][0]
        for i, frequency in enumerate(frequencies):
            row = [pulse_label, f"{frequency:g}"]
            for _, suffix in RESTITUTIONS:
                _, onset, refined, state = spectra[(pulse, suffix)]
                row += [f"{onset[i]:.6f}", refined_cell(refined[i], state[i])]
            print("| " + " | ".join(row) + " |")
    if stamp:
        print()
        print(stamp.line())
    return 0


if __name__ == "__main__":
    sys.exit(main())
