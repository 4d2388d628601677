#!/usr/bin/python3
"""Adaptive stripes against a uniform grid of stripes, on the example study's inputs.

Not a test: prints a markdown table of the samples each design needs for the same width of the
fitted overturning median's 95 % interval, and the medians they find, next to a large uniform
run's (the truth). With --figure, draws where the samples went.

    /usr/bin/python3 tests/benchmarks/adaptive_stripes.py --blockfrag build/mpi_driver/blockfrag \\
        [--ranks 2] [--truth-samples-per-level 25000] [--figure docs/adaptive_stripes.png] [--quick] \\
        [--markdown]

- uniform: configs/example_study.json's inputs over each range of --ranges (10 levels from the
  range's low to its high end: the example's own 0.2 to 2.0 g, and 0.1 to 5.0 g, a range taken
  without knowing where the curve rises) with n samples a level, n = 250, 500, ..., 4000 (--quick:
  250, 500); its median's relative interval width w(n) is the target the adaptive run must reach;
- adaptive: the same inputs and seed, a first batch of 3 levels (the range's ends and their
  middle) of 250 samples, then batches of two levels of 250 placed by the design, until its width is <= w(n);
  once with the default, D-optimal pair (where the fit is 0.128 and 0.872) and once with the
  pair at 0.3 and 0.7;
- truth: the uniform grid at --truth-samples-per-level a level (the example study itself at
  25,000): its fitted median, and where its empirical probability crosses 0.5.

The ratio is uniform samples / adaptive samples for the same width. Each run writes into a fresh
temporary folder, removed at the end. --markdown prints under the table the line
docs/performance.md shows under it: the version that computed it and this command
(tests/benchmarks/markdown_stamp.py).
"""

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

from math import erf, log, sqrt

import h5py
import numpy as np

from markdown_stamp import Stamp

SOURCE = Path(__file__).resolve().parents[2]
ADAPTIVE_SAMPLES_PER_LEVEL = 250
PAIR_PROBABILITIES = (0.128, 0.3)


def base_study():
    study = json.loads((SOURCE / "configs" / "example_study.json").read_text())
    study["limit_states"] = [{"name": "overturn", "type": "overturning"}]
    study["bootstrap_resamples"] = 0
    study["checkpoint_interval_s"] = 600
    return study


def run(args, folder, name, study):
    config = folder / f"{name}.json"
    output = folder / f"{name}.h5"
    config.write_text(json.dumps(study))
    command = [args.blockfrag, "run", str(config), "--output", str(output)]
    if args.ranks > 1:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-n", str(args.ranks)] + command
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.exit(f"{name}: blockfrag exited with {result.returncode}:\n{result.stderr}")
    with h5py.File(output, "r") as f:
        group = f["fragility/overturn"]
        found = {
            "samples": int(f.attrs["total_samples"]),
            "median": float(group.attrs["median"]),
            "beta": float(group.attrs["beta"]),
            "width": relative_width(group.attrs["median"], group.attrs["median_se"]),
            "im": group["im"][()],
            "trials": group["trials"][()],
            "probability": group["probability"][()],
        }
        if "adaptive" in f:
            found["level_batch"] = f["adaptive/level_batch"][()]
            found["stop_reason"] = f["adaptive"].attrs["stop_reason"]
    output.unlink()
    return found


def relative_width(median, median_se):
    s = median_se / median
    return float(np.exp(1.96 * s) - np.exp(-1.96 * s))


def crossing(im, probability, p):
    """The smallest intensity where the empirical curve, linear between levels, reaches p."""
    order = np.argsort(im)
    im, probability = im[order], probability[order]
    above = np.nonzero(probability >= p)[0]
    if len(above) == 0 or above[0] == 0:
        return float("nan")
    k = above[0]
    t = (p - probability[k - 1]) / (probability[k] - probability[k - 1])
    return float(im[k - 1] + t * (im[k] - im[k - 1]))


def draw(path, truth, uniform, adaptive, span):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 6.5), sharex=True,
                                      gridspec_kw={"height_ratios": [1.2, 1]})
    top.plot(truth["im"], truth["probability"], "k.-", label="truth (uniform, "
             f"{truth['samples']:,} samples)")
    x = np.geomspace(0.1, 5.0, 300)
    for found, style, label in ((uniform, "C0--", "uniform"), (adaptive, "C3-", "adaptive")):
        beta = found["beta"]
        top.plot(x, [0.5 * (1 + erf(log(v / found["median"]) / (beta * sqrt(2)))) for v in x],
                 style, label=f"{label} fit, {found['samples']:,} samples, median "
                 f"{found['median']:.3f} g")
    top.axhline(0.5, color="0.7", lw=0.8)
    top.set_ylabel("P(overturn)")
    top.set_ylim(0, 1)
    top.legend(fontsize=8, loc="upper left")
    top.set_title(f"Where the samples went over {span} g, for the same width of the median's "
                  "95 % interval", fontsize=10)
    width = 0.025
    bottom.bar(uniform["im"] - width / 2, uniform["trials"], width, color="C0", label="uniform")
    levels, counts = np.unique(np.round(adaptive["im"], 3), return_counts=True)
    bottom.bar(levels + width / 2, counts * ADAPTIVE_SAMPLES_PER_LEVEL, width, color="C3",
               label="adaptive")
    bottom.set_xlabel("PGA (g)")
    bottom.set_ylabel("samples at the level")
    bottom.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--blockfrag", default=str(SOURCE / "build" / "mpi_driver" / "blockfrag"))
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--truth-samples-per-level", type=int, default=25000)
    parser.add_argument("--ranges", default="0.2:2.0,0.1:5.0",
                        help="comma-separated LOW:HIGH ranges of PGA (g)")
    parser.add_argument("--figure", type=Path)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--markdown", action="store_true", help="the stamp line under the table")
    args = parser.parse_args()
    stamp = Stamp(args.blockfrag, note="--quick: n = 250 and 500 only" if args.quick else "") if args.markdown else None
    sizes = [250, 500] if args.quick else [250, 500, 1000, 2000, 4000]
    ranges = [tuple(float(v) for v in span.split(":")) for span in args.ranges.split(",")]

    with tempfile.TemporaryDirectory(prefix="blockfrag_adaptive_") as temporary:
        folder = Path(temporary)
        truth_study = base_study()
        truth_study["samples_per_level"] = args.truth_samples_per_level
        truth = run(args, folder, "truth", truth_study)
        truth_crossing = crossing(truth["im"], truth["probability"], 0.5)
        rows = [row for low, high in ranges for n in sizes
                for row in compare(args, folder, low, high, n)]

    print(f"truth: uniform grid, {truth['samples']:,} samples: fitted median {truth['median']:.4f} g, "
          f"empirical P = 0.5 at {truth_crossing:.4f} g\n")
    print("| range (g) | target width | uniform samples | uniform median | pair p "
          "| adaptive samples | adaptive median | adaptive width | samples ratio | adaptive stop |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for span, pair, uniform, adaptive in rows:
        print(f"| {span} | {uniform['width']:.4f} | {uniform['samples']:,} "
              f"| {uniform['median']:.4f} | {pair} | {adaptive['samples']:,} "
              f"| {adaptive['median']:.4f} | {adaptive['width']:.4f} "
              f"| {uniform['samples'] / adaptive['samples']:.2f} | {adaptive['stop_reason']} |")
    if stamp:
        print()
        print(stamp.line())
    if args.figure:
        span, _, uniform, adaptive = [row for row in rows if row[1] == PAIR_PROBABILITIES[0]][-1]
        draw(args.figure, truth, uniform, adaptive, span)
        print(f"\nfigure: {args.figure}")


def compare(args, folder, low, high, n):
    """The uniform grid over [low, high] at n a level, and the adaptive runs to its width."""
    study = base_study()
    study["samples_per_level"] = n
    study["intensity_measure"] = {"type": "pga", "from": low, "to": high, "count": 10}
    uniform = run(args, folder, f"uniform{n}", study)
    rows = []
    for pair in PAIR_PROBABILITIES:
        adaptive_study = base_study()
        adaptive_study["intensity_measure"] = {"type": "pga", "levels": [low, (low + high) / 2, high]}
        adaptive_study["samples_per_level"] = ADAPTIVE_SAMPLES_PER_LEVEL
        adaptive_study["design"] = {"adaptive": {
            "limit_state": "overturn", "target_relative_width": uniform["width"],
            "pair_probability": pair, "max_samples": 20 * uniform["samples"]}}
        adaptive = run(args, folder, f"adaptive{n}_{pair}", adaptive_study)
        rows.append((f"{low:g}-{high:g}", pair, uniform, adaptive))
    return rows


if __name__ == "__main__":
    main()
