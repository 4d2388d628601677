#!/usr/bin/python3
"""Compare two studies' fragility curves on one figure: one panel per limit state both have.

Reads two study outputs as plot_fragility.py does (their /fragility groups) and draws, for each limit
state in both, the first study's points and fitted lognormal in one colour and the second's in
another, with their 95 % intervals; a state without a fit in a study shows its points alone. The
two studies must measure intensity the same way (the same im_name).

    /usr/bin/python3 postproc/plots/plot_fragility_pair.py a.h5 b.h5 -o a_vs_b.png \\
        [--labels "type A" "type B"] [--title TEXT]
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_support  # noqa: E402  (beside this script; it chooses matplotlib's backend before pyplot)
from plot_support import InputError  # noqa: E402
from plot_fragility import axis_label, has_fit, lognormal_cdf, read_study  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

COLOURS = ("tab:blue", "tab:red")


def shared_states(first, second):
    """The limit states both studies have, in the first study's order."""
    names = {s["name"] for s in second["states"]}
    return [s["name"] for s in first["states"] if s["name"] in names]


def state_named(study, name):
    return next(s for s in study["states"] if s["name"] == name)


def fit_text(state):
    if not has_fit(state):
        return "no fit"
    return f"median {state['median']:.3g}, beta {state['beta']:.2f}"


def plot(studies, labels, title, output):
    if studies[0]["im_name"] != studies[1]["im_name"]:
        raise InputError(f"the studies measure intensity differently ({studies[0]['im_name']!r} "
                         f"and {studies[1]['im_name']!r})")
    names = shared_states(*studies)
    if not names:
        raise InputError("the two studies have no limit state in common")
    columns = min(3, len(names))
    rows = math.ceil(len(names) / columns)
    figure, axes = plt.subplots(rows, columns, figsize=(4.6 * columns, 3.8 * rows), squeeze=False)
    top = max(max(s["im"].max() for s in study["states"]) for study in studies)
    grid = np.linspace(top / 400, top * 1.05, 400)
    for axis, name in zip(axes.flat, names):
        for study, label, colour in zip(studies, labels, COLOURS):
            state = state_named(study, name)
            has_trials = state["trials"] > 0
            im = state["im"][has_trials]
            p = state["probability"][has_trials]
            error = np.clip([p - state["ci_low"][has_trials], state["ci_high"][has_trials] - p], 0.0, None)
            axis.errorbar(im, p, yerr=error, fmt="o", ms=4, color=colour, capsize=2)
            if has_fit(state):
                axis.plot(grid, lognormal_cdf(grid, state["median"], state["beta"]), color=colour,
                          label=f"{label}: {fit_text(state)}")
            else:
                axis.plot([], [], "o", color=colour, label=f"{label}: {fit_text(state)}")
        axis.set_title(name.replace("_", " "))
        axis.set_xlim(0, top * 1.05)
        axis.set_ylim(-0.02, 1.02)
        axis.set_xlabel(axis_label(studies[0]))
        axis.set_ylabel("P(exceed)")
        axis.grid(alpha=0.3)
        axis.legend(fontsize=7, loc="upper left")
    for axis in list(axes.flat)[len(names):]:
        axis.set_visible(False)
    figure.suptitle(title)
    figure.tight_layout()
    plot_support.save_figure(figure, output, dpi=110)


def main(argv=None):
    parser = plot_support.parser(__doc__)
    parser.add_argument("first", help="first study's HDF5 output")
    parser.add_argument("second", help="second study's HDF5 output")
    plot_support.add_output(parser, required=True)
    parser.add_argument("--labels", nargs=2, metavar=("FIRST", "SECOND"),
                        help="legend names of the two studies (default: their file names)")
    parser.add_argument("--title", help="figure title")
    args = parser.parse_args(argv)
    labels = args.labels or [os.path.basename(args.first), os.path.basename(args.second)]

    def work():
        studies = [read_study(args.first), read_study(args.second)]
        plot(studies, labels, args.title or f"{labels[0]} against {labels[1]}", args.output)

    return plot_support.run(work)


if __name__ == "__main__":
    sys.exit(main())
