#!/usr/bin/python3
"""Plot the fragility curves of a blockfrag study: empirical points with intervals, lognormal fits.

Reads the study's HDF5 output: per limit state a group /fragility/<name> with datasets im, trials,
exceedances, probability, ci_low, ci_high and attributes median, beta, log_likelihood (NaN when the
fit does not exist) and, when present, fit_status, type, threshold, interval; /fragility's
attributes im_name and im_units label the intensity axis.

    /usr/bin/python3 postproc/plots/plot_fragility.py results.h5 -o fragility.png
    /usr/bin/python3 postproc/plots/plot_fragility.py results.h5 --summary
"""

import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402  (the backend must be chosen before pyplot, and h5py is grouped here)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

DATASETS = ("im", "trials", "exceedances", "probability", "ci_low", "ci_high")

# Okabe & Ito's palette: distinguishable with the common colour-vision deficiencies and in grey.
COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442")
MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*")


class InputError(Exception):
    """A problem with the input file, reported as one line without a traceback."""


def text(value):
    """An attribute as str: h5py gives str for variable-length strings, bytes for fixed-length ones."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, np.ndarray) and value.shape == ():
        return text(value[()])
    return str(value)


def number(attrs, name):
    try:
        return float(attrs[name])
    except (KeyError, TypeError, ValueError):
        return math.nan


def read_study(path):
    if not os.path.exists(path):
        raise InputError(f"cannot open {path}: no such file")
    try:
        file = h5py.File(path, "r")
    except OSError as error:
        raise InputError(f"cannot open {path}: not a readable HDF5 file ({error})") from error
    with file:
        if "fragility" not in file or not isinstance(file["fragility"], h5py.Group):
            raise InputError(f"{path} has no /fragility group (is it a blockfrag study output?)")
        group = file["fragility"]
        im_name = text(group.attrs["im_name"]) if "im_name" in group.attrs else ""
        im_units = text(group.attrs["im_units"]) if "im_units" in group.attrs else ""
        im_label = text(group.attrs["im_label"]) if "im_label" in group.attrs else ""
        states = []
        for name, state in group.items():
            if not isinstance(state, h5py.Group):
                continue
            missing = [d for d in DATASETS if d not in state]
            if missing:
                raise InputError(f"{path}: /fragility/{name} lacks dataset(s) {', '.join(missing)}")
            columns = {d: np.asarray(state[d][...], dtype=float).ravel() for d in DATASETS}
            sizes = {len(c) for c in columns.values()}
            if len(sizes) != 1:
                raise InputError(f"{path}: /fragility/{name}: datasets {', '.join(DATASETS)} differ in length")
            attrs = state.attrs
            states.append({
                "name": name,
                **columns,
                "median": number(attrs, "median"),
                "beta": number(attrs, "beta"),
                "log_likelihood": number(attrs, "log_likelihood"),
                "fit_status": text(attrs["fit_status"]) if "fit_status" in attrs else "",
                "type": text(attrs["type"]) if "type" in attrs else "",
                "threshold": number(attrs, "threshold"),
                "interval": text(attrs["interval"]) if "interval" in attrs else "",
                "median_low": number(attrs, "median_low"),
                "median_high": number(attrs, "median_high"),
            })
    if not states:
        raise InputError(f"{path}: /fragility holds no limit state")
    return {"im_name": im_name, "im_units": im_units, "im_label": im_label, "states": states}


def has_fit(state):
    return math.isfinite(state["median"]) and math.isfinite(state["beta"]) and state["median"] > 0 and state["beta"] > 0


def describe(state):
    """The limit state in words, from its type and threshold when the file gives them."""
    kind, threshold = state["type"], state["threshold"]
    if kind == "overturning":
        return "overturning"
    if kind == "max_rotation" and math.isfinite(threshold):
        return f"max |θ|/α > {threshold:g}"
    if kind == "residual_slide" and math.isfinite(threshold):
        return f"residual slide > {threshold:g} m"
    return kind


def axis_label(study):
    name = study["im_label"] or (study["im_name"].replace("_", " ") if study["im_name"] else "intensity")
    units = study["im_units"]
    return f"{name} [{units}]" if units and units != "1" else name


def lognormal_cdf(x, median, beta):
    return np.array([0.5 * math.erfc(-math.log(v / median) / (beta * math.sqrt(2.0))) for v in x])


def plot(study, title, output):
    states = study["states"]
    columns = 1 if len(states) == 1 else 2
    legend_rows = math.ceil(len(states) / columns)
    fig, ax = plt.subplots(figsize=(8.0, 5.4 + 0.42 * legend_rows))
    units = study["im_units"]
    levels = np.concatenate([s["im"][np.isfinite(s["im"]) & (s["im"] > 0)] for s in states])
    if levels.size == 0:
        raise InputError("no limit state has an intensity level to plot")
    im_max, im_min = float(levels.max()), float(levels.min())
    x = np.linspace(im_max * 1e-3, im_max * 1.08, 400)
    # Spread the error bars of different limit states sideways so that they do not hide each other.
    spacing = (im_max - im_min) / max(1, max(len(s["im"]) for s in states) - 1) if im_max > im_min else im_max
    dodge = 0.06 * spacing
    handles = []

    for k, state in enumerate(states):
        colour, marker = COLOURS[k % len(COLOURS)], MARKERS[k % len(MARKERS)]
        description = describe(state)
        label = state["name"] + (f" ({description})" if description and description != state["name"] else "")
        if has_fit(state):
            label += f"\n  fit: median {state['median']:.3g}{' ' + units if units else ''}, β = {state['beta']:.2f}"
            ax.plot(x, lognormal_cdf(x, state["median"], state["beta"]), color=colour, linewidth=1.8, zorder=2)
        else:
            reason = state["fit_status"] or "not available"
            label += f"\n  no lognormal fit: {reason.replace('_', ' ')}"
            low, high = state["median_low"], state["median_high"]
            if math.isfinite(low) and math.isfinite(high) and high > 0:
                where = f"{low:.3g}" if low == high else f"{low:.3g} and {high:.3g}"
                label += f" (median {'at' if low == high else 'between'} {where}{' ' + units if units else ''})"
        shown = np.isfinite(state["probability"]) & (state["trials"] > 0)
        p = state["probability"][shown]
        low = np.clip(p - state["ci_low"][shown], 0.0, None)
        high = np.clip(state["ci_high"][shown] - p, 0.0, None)
        offset = (k - 0.5 * (len(states) - 1)) * dodge
        ax.errorbar(state["im"][shown] + offset, p, yerr=np.vstack((low, high)), fmt=marker, color=colour,
                    markersize=5.5, markerfacecolor="white", markeredgewidth=1.4, elinewidth=1.0, capsize=3,
                    zorder=3)
        handles.append(Line2D([], [], color=colour, marker=marker, markerfacecolor="white", markeredgewidth=1.4,
                              linewidth=1.8, linestyle="-" if has_fit(state) else "none", label=label))

    ax.set_xlim(0.0, im_max * 1.08)
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel(axis_label(study))
    ax.set_ylabel("probability of exceedance")
    ax.grid(True, color="0.88", linewidth=0.6)
    ax.set_axisbelow(True)
    # Below the axes, where it can hide no data point.
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=columns, fontsize=8.5,
              frameon=False, labelspacing=0.9, columnspacing=2.0)
    ax.set_title(title, fontsize=12)

    intervals = {s["interval"] for s in states if s["interval"]}
    interval = intervals.pop() if len(intervals) == 1 else "confidence"
    trials = {int(t) for s in states for t in s["trials"] if t > 0}
    per_level = f"; {trials.pop()} trials per level" if len(trials) == 1 else ""
    fig.text(0.01, 0.01, f"Markers: observed fraction exceeding, bars: {interval} interval{per_level}. "
             "Lines: lognormal fit by maximum likelihood.", fontsize=7.5, color="0.35")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(output, dpi=150)
    plt.close(fig)


def summary(study):
    units = study["im_units"]
    lines = []
    for state in study["states"]:
        description = describe(state)
        lines.append(f"limit state {state['name']}" + (f" ({description})" if description else ""))
        if has_fit(state):
            lines.append(f"  lognormal fit: median = {state['median']:.6g}{' ' + units if units else ''}, "
                         f"beta = {state['beta']:.6g}, log-likelihood = {state['log_likelihood']:.6g}")
        else:
            bracket = ""
            if math.isfinite(state["median_low"]) and math.isfinite(state["median_high"]):
                bracket = f"; the median lies in [{state['median_low']:.6g}, {state['median_high']:.6g}]"
            lines.append(f"  lognormal fit: none ({state['fit_status'] or 'median/beta are NaN'}){bracket}")
        interval = f" ({state['interval']})" if state["interval"] else ""
        lines.append(f"  {'im':>10} {'trials':>8} {'exceed':>8} {'probability':>12} {'ci_low':>9} {'ci_high':>9}"
                     + interval)
        for row in zip(*(state[d] for d in DATASETS)):
            im, n, z, p, low, high = row

            def cell(v, width, digits=4):
                return f"{v:>{width}.{digits}f}" if math.isfinite(v) else f"{'-':>{width}}"

            lines.append(f"  {im:>10.4g} {int(n):>8d} {int(z):>8d} {cell(p, 12)} {cell(low, 9)} {cell(high, 9)}")
        lines.append("")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", help="study output HDF5 file")
    parser.add_argument("-o", "--output", help="PNG file to write")
    parser.add_argument("--summary", action="store_true", help="print the table of each limit state")
    parser.add_argument("--title", help="figure title (default: from the file name)")
    args = parser.parse_args(argv)
    if not args.output and not args.summary:
        parser.error("nothing to do: give -o OUT.png, --summary or both")
    name = os.path.basename(sys.argv[0])
    try:
        study = read_study(args.results)
        if args.summary:
            print(summary(study))
        if args.output:
            plot(study, args.title or f"Fragility curves: {os.path.basename(args.results)}", args.output)
    except InputError as error:
        print(f"{name}: error: {error}", file=sys.stderr)
        return 1
    except OSError as error:
        print(f"{name}: error: cannot write {args.output}: {error.strerror or error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
