#!/usr/bin/python3
"""Plot where a site's risk comes from: the risk.json of `blockfrag risk` (docs/risk.md) in three
panels over the intensity measure, one x axis (log):

1. the hazard curve: the annual rate of exceeding each intensity (log);
2. the fragility of each limit state: its lognormal fit as a line, the observed points as
   markers (of the first study; several weighted studies show the first's);
3. the integrand, where the risk comes from: each hazard bin's part of the fitted lambda divided
   by the bin's width in ln im (per unit of ln im, so that bins of any width compare), as steps,
   with the study's level range shaded in every panel.

    /usr/bin/python3 postproc/plots/plot_risk.py risk.json -o risk.png [--title TEXT]
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_support  # noqa: E402  (beside this script; it chooses matplotlib's backend before pyplot)
from plot_support import InputError  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Okabe & Ito's palette, as plot_fragility.py's limit states.
COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442")
HAZARD_COLOUR = "#000000"
LEVELS_SHADE = "#eeeeee"


def read_report(path):
    try:
        with open(path, encoding="utf-8") as handle:
            report = json.load(handle)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as error:
        raise InputError(f"{path}: not a risk.json ({error})") from None
    if not isinstance(report, dict) or report.get("blockfrag_risk") != 1:
        raise InputError(f"{path}: not a blockfrag risk.json (no \"blockfrag_risk\": 1)")
    try:
        hazard = report["hazard"]
        im = np.asarray(hazard["im"], dtype=float)
        rate = np.asarray(hazard["annual_rate"], dtype=float)
        states = report["limit_states"]
        first = report["studies"][0]["limit_states"]
    except (KeyError, IndexError, TypeError, ValueError) as error:
        raise InputError(f"{path}: a risk.json without {error}") from None
    if im.ndim != 1 or len(im) < 2 or im.shape != rate.shape or np.any(im <= 0):
        raise InputError(f"{path}: /hazard/im and /hazard/annual_rate are not one curve")
    check_limit_states(path, states, first, len(im) - 1)
    return report, im, rate, states, first


def check_limit_states(path, states, first, bins):
    """What draw() reads of each limit state, so that a damaged file is one line naming the JSON
    path, not a traceback halfway through the figure."""
    def fail(where, rule):
        raise InputError(f"{path}: {where}: {rule}")

    def numbers(value, where, count=None):
        try:
            array = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            fail(where, "not a list of numbers")
        if array.ndim != 1 or (count is not None and len(array) != count):
            fail(where, f"not a list of {count} numbers" if count is not None else "not a list of numbers")
        return array

    if not isinstance(states, list) or not isinstance(first, list):
        fail("/limit_states", "not a list of limit states")
    for k, state in enumerate(states):
        where = f"/limit_states/{k}"
        if not isinstance(state, dict) or not isinstance(state.get("name"), str):
            fail(where, "not a limit state with a name")
        for estimate in ("fit", "points"):
            value = state.get(estimate)
            if value is None:
                continue
            if not isinstance(value, dict) or not isinstance(value.get("lambda"), (int, float)):
                fail(f"{where}/{estimate}", "not an estimate with a lambda")
            numbers(value.get("bin_lambda"), f"{where}/{estimate}/bin_lambda", bins)
    for k, state in enumerate(first):
        where = f"/studies/0/limit_states/{k}"
        if not isinstance(state, dict) or not isinstance(state.get("name"), str):
            fail(where, "not a limit state with a name")
        for key in ("median", "beta"):
            if state.get(key) is not None and not isinstance(state[key], (int, float)):
                fail(f"{where}/{key}", "not a number")
        if state.get("levels"):
            levels = numbers(state["levels"], f"{where}/levels")
            numbers(state.get("probability"), f"{where}/probability", len(levels))


def lognormal(x, median, beta):
    return np.array([0.5 * math.erfc(-math.log(v / median) / (beta * math.sqrt(2))) for v in x])


def integrand(im, bins):
    """Each bin's lambda per unit of ln im, as a step over the bin."""
    widths = np.log(im[1:] / im[:-1])
    return np.asarray(bins, dtype=float) / widths


def draw(report, im, rate, states, first, title):
    figure, (top, middle, bottom) = plt.subplots(3, 1, figsize=(8, 10), sharex=True,
                                                 gridspec_kw={"height_ratios": [1, 1, 1]})
    units = report["studies"][0].get("im_units", "")
    imt = report["hazard"].get("imt", "IM")
    positive = rate > 0
    top.loglog(im[positive], rate[positive], color=HAZARD_COLOUR, marker=".", label="hazard")
    top.set_ylabel("annual rate of exceedance")
    site = report["hazard"].get("site") or os.path.basename(report["hazard"].get("file", ""))
    top.set_title(title or f"risk at {site}")
    levels = [s["levels"] for s in first if s.get("levels")]
    if levels:
        low, high = min(min(v) for v in levels), max(max(v) for v in levels)
        for axes in (top, middle, bottom):
            axes.axvspan(low, high, color=LEVELS_SHADE, zorder=0)
    x = np.geomspace(im[0], im[-1], 400)
    for k, state in enumerate(states):
        colour = COLOURS[k % len(COLOURS)]
        detail = next((s for s in first if s["name"] == state["name"]), None)
        estimate = state["fit"] or state["points"]
        lam = estimate["lambda"] if estimate else float("nan")
        label = f"{state['name']}: lambda {lam:.3g} /yr"
        fitted = bool(detail and detail.get("median") and detail.get("beta"))
        if fitted:
            middle.plot(x, lognormal(x, detail["median"], detail["beta"]), color=colour,
                        label=label)
        if detail and detail.get("levels"):
            middle.plot(detail["levels"], detail["probability"], linestyle="none", marker="o",
                        color=colour, markersize=4,
                        label=None if fitted else label + " (points, no fit)")
        if estimate:
            steps = integrand(im, estimate["bin_lambda"])
            bottom.stairs(steps, im, color=colour, label=state["name"])
    middle.set_ylabel("P(limit state | im)")
    middle.set_ylim(-0.02, 1.02)
    middle.legend(fontsize=8, loc="upper left")
    bottom.set_yscale("log")
    # Four decades under the largest step: where the risk comes from, not the bins it does not.
    tallest = max((max(integrand(im, (s["fit"] or s["points"])["bin_lambda"]), default=0)
                   for s in states if s["fit"] or s["points"]), default=0)
    if tallest > 0:
        bottom.set_ylim(tallest * 1e-4, tallest * 2)
    bottom.set_ylabel("d lambda / d ln im (per year)")
    bottom.set_xlabel(f"{imt} ({units})" if units else imt)
    bottom.set_xscale("log")
    figure.tight_layout()
    return figure


def main(argv=None):
    parser = plot_support.parser(__doc__)
    parser.add_argument("risk_json", help="the risk.json of blockfrag risk")
    plot_support.add_output(parser, required=True)
    plot_support.add_title(parser, default="risk at the hazard file's site")
    args = parser.parse_args(argv)
    return plot_support.run(lambda: plot(args))


def plot(args):
    report, im, rate, states, first = read_report(args.risk_json)
    figure = draw(report, im, rate, states, first, args.title)
    plot_support.save_figure(figure, args.output, dpi=120)


if __name__ == "__main__":
    sys.exit(main())
