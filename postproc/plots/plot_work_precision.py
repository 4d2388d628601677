#!/usr/bin/python3
"""The work-precision diagram of a `blockfrag accuracy` HDF5 file.

Error in max |theta| (the largest over the suite's scenes) against the median time per scene,
log-log, one line per method, each point labelled with its dt or tolerance. Errors of zero are drawn
at the plot's floor; settings with a failed scene (infinite error) are left out and listed in the
legend.

    /usr/bin/python3 postproc/plots/plot_work_precision.py accuracy.h5 work_precision.png \\
        [--title TEXT] [--error median]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_support  # noqa: E402  (beside this script; it chooses matplotlib's backend before pyplot)
from plot_support import InputError, text  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"rk4": "s", "adaptive": "o", "gsl_rkf45": "^", "gsl_rk8pd": "D"}
HINT = "a blockfrag accuracy output"


def read_summary(path, statistic):
    with plot_support.open_hdf5(path) as f:
        if not plot_support.has_group(f, "summary"):
            raise InputError(f"{path} has no /summary group (is it {HINT}?)")

        def column(name):
            return list(plot_support.dataset(f, path, name, None, hint=HINT).ravel())

        labels = plot_support.attribute(f["summary"], path, "labels", text).split("\n")
        methods = plot_support.attribute(f["summary"], path, "methods", text).split("\n")
        errors = column(f"/summary/{statistic}_error_max_abs_theta")
        seconds = column("/summary/median_seconds")
        parameters = column("/summary/parameter")
        failures = column("/summary/failures")
        if not len(labels) == len(methods) == len(errors) == len(seconds) == len(parameters) == len(failures):
            raise InputError(f"{path}: /summary's labels, methods and datasets differ in length")
        check_errors = plot_support.dataset(f, path, "/scenes/check_error_max_abs_theta", hint=HINT)
        check = float(check_errors.max()) if check_errors.size else 0.0
        method = plot_support.attribute(f, path, "reference_method", text)
        tolerance = plot_support.attribute(f, path, "reference_tolerance", float)
        reference = f"{method} tol={tolerance:.0e}"
    return labels, methods, errors, seconds, parameters, failures, check, reference


def main(argv=None):
    parser = plot_support.parser(__doc__)
    parser.add_argument("input", help="the HDF5 output of blockfrag accuracy")
    parser.add_argument("output", help="PNG file to write")
    parser.add_argument("--title", default="Work-precision on the accuracy suite", help="figure title")
    parser.add_argument("--error", choices=["max", "median"], default="max",
                        help="which error over the scenes to plot (default: max)")
    args = parser.parse_args(argv)
    return plot_support.run(lambda: plot(args))


def plot(args):
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
    plot_support.save_figure(fig, args.output, dpi=120)


if __name__ == "__main__":
    sys.exit(main())
