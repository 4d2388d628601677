#!/usr/bin/env python3
"""The work-precision diagram of a `blockfrag accuracy` HDF5 file.

Error in max |theta| (the largest over the suite's scenes) against the median time per scene,
log-log, one line per method, each point labelled with its dt or tolerance. Errors of zero are drawn
at the plot's floor; settings with a failed scene (infinite error) are left out and listed in the
legend.

    plot_work_precision.py accuracy.h5 work_precision.png [--title TEXT] [--error median]
"""
import argparse
import math
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"rk4": "s", "adaptive": "o", "gsl_rkf45": "^", "gsl_rk8pd": "D"}


def read_summary(path, statistic):
    with h5py.File(path, "r") as f:
        summary = f["summary"]
        labels = summary.attrs["labels"].split("\n")
        methods = summary.attrs["methods"].split("\n")
        errors = list(summary[f"{statistic}_error_max_abs_theta"][...])
        seconds = list(summary["median_seconds"][...])
        parameters = list(summary["parameter"][...])
        failures = list(summary["failures"][...])
        check_errors = f["scenes/check_error_max_abs_theta"][...]
        check = float(check_errors.max()) if check_errors.size else 0.0
        reference = f"{f.attrs['reference_method']} tol={f.attrs['reference_tolerance']:.0e}"
    return labels, methods, errors, seconds, parameters, failures, check, reference


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--title", default="Work-precision on the accuracy suite")
    parser.add_argument("--error", choices=["max", "median"], default="max",
                        help="which error over the scenes to plot (default: max)")
    args = parser.parse_args(argv)

    labels, methods, errors, seconds, parameters, failures, check, reference = read_summary(args.input, args.error)
    finite = [e for e in errors if math.isfinite(e) and e > 0]
    floor = min(finite + [check if check > 0 else 1e-15]) / 3 if finite else 1e-15

    fig, ax = plt.subplots(figsize=(8, 5.5))
    for method in dict.fromkeys(methods):
        rows = [i for i, m in enumerate(methods) if m == method and failures[i] == 0 and math.isfinite(errors[i])]
        left_out = [labels[i] for i, m in enumerate(methods) if m == method and i not in rows]
        rows.sort(key=lambda i: parameters[i], reverse=True)
        xs = [seconds[i] * 1e3 for i in rows]
        ys = [max(errors[i], floor) for i in rows]
        name = method + (f" (failed: {', '.join(left_out)})" if left_out else "")
        ax.plot(xs, ys, marker=MARKERS.get(method, "x"), label=name)
        # Label a point only when it stands apart from the last labelled one: loose tolerances often
        # cost and give the same, and their labels would print on top of each other.
        last = None
        for i, x, y in zip(rows, xs, ys):
            if last and abs(math.log10(x / last[0])) < 0.08 and abs(math.log10(y / last[1])) < 0.25:
                continue
            ax.annotate(f"{parameters[i]:g}", (x, y), textcoords="offset points", xytext=(4, 3), fontsize=7)
            last = (x, y)
    if check > 0:
        ax.axhline(check, color="grey", linestyle=":", label=f"reference check (gsl_rk8pd vs {reference})")
    ax.axhline(1e-6, color="red", linestyle="--", linewidth=0.8, label="target 1e-6 rad")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("median time per scene (ms)")
    ax.set_ylabel(f"{args.error} error in max |theta| over the suite (rad)")
    ax.set_title(args.title)
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
