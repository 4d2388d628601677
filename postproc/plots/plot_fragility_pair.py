#!/usr/bin/python3
"""Compare two studies' fragility curves on one figure: one panel per limit state both have, or per kind.

Reads two study outputs as plot_fragility.py does (their /fragility groups) and draws, for each limit
state in both, the first study's points and fitted lognormal in one colour and the second's in
another, with their 95 % intervals; a state without a fit in a study shows its points alone. The
two studies must measure intensity the same way (the same im_name).

With --kinds, one panel per kind of limit state instead, in the order given, each holding every
limit state of that kind in either study (told apart by line style, thresholds in ascending order):
  dislocation      residual_slide limit states (a residual slide past a threshold)
  loss             overturning limit states (the block is lost: overturned or fallen off its seat)
  post_earthquake  post_earthquake_unstable limit states (standing, but unsafe under full uplift)
  rocking          max_rotation limit states (a peak rotation past a fraction of alpha)
A study without a limit state of a panel's kind (a dry study has no post_earthquake one) is named
in that panel's legend as having none; a kind neither study has is an error (exit code 2).

    /usr/bin/python3 postproc/plots/plot_fragility_pair.py a.h5 b.h5 -o a_vs_b.png \\
        [--labels "type A" "type B"] [--title TEXT] \\
        [--kinds dislocation loss post_earthquake rocking]
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
# Several limit states of one kind in a panel (2, 10 and 50 cm) differ in line style and marker.
LINE_STYLES = ("-", "--", ":", "-.")
MARKERS = ("o", "s", "^", "D")

# --kinds: each kind's limit-state type (the `type` attribute blockfrag writes) and panel title.
KINDS = {
    "dislocation": ("residual_slide", "dislocation (residual slide)"),
    "loss": ("overturning", "loss (overturned or fell off its seat)"),
    "post_earthquake": ("post_earthquake_unstable", "post-earthquake unstable (full uplift)"),
    "rocking": ("max_rotation", "rocking (peak rotation)"),
}


def shared_states(first, second):
    """The limit states both studies have, in the first study's order."""
    names = {s["name"] for s in second["states"]}
    return [s["name"] for s in first["states"] if s["name"] in names]


def state_named(study, name):
    return next(s for s in study["states"] if s["name"] == name)


def states_of_type(study, state_type):
    """The study's limit states of one type, by ascending threshold."""
    found = [s for s in study["states"] if s["type"] == state_type]
    return sorted(found, key=lambda s: s["threshold"] if math.isfinite(s["threshold"]) else 0.0)


def fit_text(state):
    if state["fit_status"] == "no_exceedances":
        return "none exceeded, no fit"
    if not has_fit(state):
        return "no fit"
    return f"median {state['median']:.3g}, beta {state['beta']:.2f}"


def panels_by_state(studies):
    """One panel per limit state both studies have: (title, per study its one state)."""
    names = shared_states(*studies)
    if not names:
        raise InputError("the two studies have no limit state in common")
    return [(name.replace("_", " "), [[state_named(study, name)] for study in studies]) for name in names]


def panels_by_kind(studies, kinds):
    """One panel per kind: (title, per study its states of that kind, maybe none)."""
    panels = []
    for kind in kinds:
        state_type, title = KINDS[kind]
        per_study = [states_of_type(study, state_type) for study in studies]
        if not any(per_study):
            raise InputError(f"neither study has a {kind} limit state (type {state_type})")
        panels.append((title, per_study))
    return panels


def draw_state(axis, grid, state, label, colour, style):
    line, marker = style
    has_trials = state["trials"] > 0
    im = state["im"][has_trials]
    p = state["probability"][has_trials]
    error = np.clip([p - state["ci_low"][has_trials], state["ci_high"][has_trials] - p], 0.0, None)
    axis.errorbar(im, p, yerr=error, fmt=marker, ms=4, color=colour, capsize=2)
    if has_fit(state):
        axis.plot(grid, lognormal_cdf(grid, state["median"], state["beta"]), color=colour, linestyle=line,
                  marker=marker, markevery=[], label=f"{label}: {fit_text(state)}")
    else:
        axis.plot([], [], marker, color=colour, label=f"{label}: {fit_text(state)}")


def plot(studies, labels, title, output, kinds=None):
    if studies[0]["im_name"] != studies[1]["im_name"]:
        raise InputError(f"the studies measure intensity differently ({studies[0]['im_name']!r} "
                         f"and {studies[1]['im_name']!r})")
    panels = panels_by_kind(studies, kinds) if kinds else panels_by_state(studies)
    columns = min(3, len(panels))
    rows = math.ceil(len(panels) / columns)
    height = 4.6 if kinds else 3.8
    figure, axes = plt.subplots(rows, columns, figsize=(4.6 * columns, height * rows), squeeze=False)
    drawn = [s for _, per_study in panels for states in per_study for s in states]
    top = max(s["im"].max() for s in drawn)
    grid = np.linspace(top / 400, top * 1.05, 400)
    for axis, (panel_title, per_study) in zip(axes.flat, panels):
        for states, label, colour in zip(per_study, labels, COLOURS):
            if not states:
                axis.plot([], [], " ", label=f"{label}: no such limit state")
            for state, style in zip(states, zip(LINE_STYLES, MARKERS)):
                name = f"{label}, {state['name'].replace('_', ' ')}" if kinds else label
                draw_state(axis, grid, state, name, colour, style)
        axis.set_title(panel_title)
        axis.set_xlim(0, top * 1.05)
        axis.set_ylim(-0.02, 1.02)
        axis.set_xlabel(axis_label(studies[0]))
        axis.set_ylabel("P(exceed)")
        axis.grid(alpha=0.3)
        if kinds:
            axis.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2))
        else:
            axis.legend(fontsize=7, loc="upper left")
    for axis in list(axes.flat)[len(panels):]:
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
    parser.add_argument("--kinds", nargs="+", choices=list(KINDS),
                        help="one panel per kind of limit state, in this order "
                        "(default: one panel per limit state both studies have)")
    args = parser.parse_args(argv)
    labels = args.labels or [os.path.basename(args.first), os.path.basename(args.second)]

    def work():
        studies = [read_study(args.first), read_study(args.second)]
        plot(studies, labels, args.title or f"{labels[0]} against {labels[1]}", args.output, args.kinds)

    return plot_support.run(work)


if __name__ == "__main__":
    sys.exit(main())
