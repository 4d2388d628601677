#!/usr/bin/python3
"""Plot the fragility curves of a blockfrag study: empirical points with intervals, lognormal fits.

Reads the study's HDF5 output: per limit state a group /fragility/<name> with datasets im, trials,
exceedances, probability, ci_low, ci_high and attributes median, beta, log_likelihood (NaN when the
fit does not exist) and, when present, fit_status, type, threshold, interval; /fragility's
attributes im_name, im_units and im_label label the intensity axis. When the file has them, each
limit state's pointwise 95 % bootstrap band of the fitted curve (datasets band_im, band_low,
band_high) is shaded in the curve's colour, its goodness of fit (attributes deviance, gof_p_value,
gof_dof) and its bootstrap intervals (median_ci, beta_ci) are in its legend entry and the summary,
the limit states are listed by severity (severity_rank, lower = less severe, or /fragility's
severity_order) and a curve that crosses another inside the levels says so (crosses, or
/fragility's crossing_pairs "a,b;c,d").

    /usr/bin/python3 postproc/plots/plot_fragility.py results.h5 -o fragility.png
    /usr/bin/python3 postproc/plots/plot_fragility.py results.h5 --summary
"""

import math
import os
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_support  # noqa: E402  (beside this script; it chooses matplotlib's backend before pyplot)
from plot_support import InputError, text  # noqa: E402
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

DATASETS = ("im", "trials", "exceedances", "probability", "ci_low", "ci_high")
BAND = ("band_im", "band_low", "band_high")
# The bootstrap band: the curve's colour at this opacity over white, so that bands may overlap.
BAND_ALPHA = 0.2
# A lognormal whose goodness-of-fit p-value is below this is reported as rejected.
REJECT_AT = 0.05

# Okabe & Ito's palette: distinguishable with the common colour-vision deficiencies and in grey.
COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442")
MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*")


def number(attrs, name):
    try:
        return float(attrs[name])
    except (KeyError, TypeError, ValueError):
        return math.nan


def integer(attrs, name):
    """An integer attribute, or None when absent or not an integer."""
    try:
        value = attrs[name]
        return int(value) if float(value) == int(value) else None
    except (KeyError, TypeError, ValueError, OverflowError):
        return None


def pair(attrs, name):
    """A 2-element attribute (an interval) as a tuple of floats, or None."""
    try:
        values = np.asarray(attrs[name], dtype=float).ravel()
    except (KeyError, TypeError, ValueError):
        return None
    return (float(values[0]), float(values[1])) if values.size == 2 and np.all(np.isfinite(values)) else None


def read_band(path, name, state):
    """The bootstrap band (im, low, high) when the group has it, None when it has none of it."""
    present = [d for d in BAND if d in state]
    if not present:
        return None
    if len(present) != len(BAND):
        missing = [d for d in BAND if d not in state]
        raise InputError(f"{path}: /fragility/{name} has {', '.join(present)} but lacks {', '.join(missing)}")
    im, low, high = (np.asarray(state[d][...], dtype=float).ravel() for d in BAND)
    if not len(im) == len(low) == len(high):
        raise InputError(f"{path}: /fragility/{name}: datasets {', '.join(BAND)} differ in length")
    keep = np.isfinite(im) & np.isfinite(low) & np.isfinite(high)
    return (im[keep], low[keep], high[keep]) if keep.any() else None


def read_study(path):
    with plot_support.open_hdf5(path) as file:
        if not plot_support.has_group(file, "fragility"):
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
                "band": read_band(path, name, state),
                "median_ci": pair(attrs, "median_ci"),
                "beta_ci": pair(attrs, "beta_ci"),
                "deviance": number(attrs, "deviance"),
                "gof_p_value": number(attrs, "gof_p_value"),
                "gof_dof": integer(attrs, "gof_dof"),
                "max_misfit": number(attrs, "max_misfit"),
                "severity_rank": integer(attrs, "severity_rank"),
                "crosses": [c.strip() for c in text(attrs["crosses"]).split(",") if c.strip()]
                if "crosses" in attrs else [],
            })
        severity_order = [n.strip() for n in text(group.attrs["severity_order"]).split(",") if n.strip()] \
            if "severity_order" in group.attrs else []
        # Crossings may also come as /fragility's crossing_pairs, "a,b;c,d".
        if "crossing_pairs" in group.attrs:
            for crossing in text(group.attrs["crossing_pairs"]).split(";"):
                names = [n.strip() for n in crossing.split(",") if n.strip()]
                for state in states:
                    if state["name"] in names and len(names) == 2:
                        other = names[1] if names[0] == state["name"] else names[0]
                        if other not in state["crosses"]:
                            state["crosses"].append(other)
        scaling = text(group.attrs["scaling"]) if "scaling" in group.attrs else ""
    if not states:
        raise InputError(f"{path}: /fragility holds no limit state")
    by_severity = order_by_severity(states, severity_order)
    return {"im_name": im_name, "im_units": im_units, "im_label": im_label, "scaling": scaling,
            "states": by_severity or states, "by_severity": by_severity is not None}


def order_by_severity(states, severity_order):
    """The limit states from least to most severe (severity_rank, else /fragility's severity_order),
    or None when the file does not rank them all."""
    if all(s["severity_rank"] is not None for s in states):
        return sorted(states, key=lambda s: (s["severity_rank"], s["name"]))
    names = [s["name"] for s in states]
    if severity_order and sorted(severity_order) == sorted(names):
        return sorted(states, key=lambda s: severity_order.index(s["name"]))
    return None


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
    if kind == "post_earthquake_unstable" and math.isfinite(threshold):
        return f"post-earthquake safety factor < {threshold:g}"
    return kind


def axis_label(study):
    name = study["im_label"] or (study["im_name"].replace("_", " ") if study["im_name"] else "intensity")
    units = study["im_units"]
    return f"{name} [{units}]" if units and units != "1" else name


def lognormal_cdf(x, median, beta):
    return np.array([0.5 * math.erfc(-math.log(v / median) / (beta * math.sqrt(2.0))) for v in x])


def misfit(state):
    """The largest |observed - fitted| probability over the levels with trials (the file's own
    max_misfit when it has one), NaN without a fit."""
    if math.isfinite(state["max_misfit"]):
        return state["max_misfit"]
    if not has_fit(state):
        return math.nan
    shown = np.isfinite(state["probability"]) & (state["trials"] > 0) & (state["im"] > 0)
    if not shown.any():
        return math.nan
    fitted = lognormal_cdf(state["im"][shown], state["median"], state["beta"])
    return float(np.max(np.abs(state["probability"][shown] - fitted)))


def p_text(p):
    return "0 (below double precision)" if p == 0 else f"{p:.2g}"


def rejected(state):
    return math.isfinite(state["gof_p_value"]) and state["gof_p_value"] < REJECT_AT


def goodness_lines(state):
    """The legend's goodness-of-fit lines: "deviance D, p = P" and, when p < 0.05, the rejection
    and how far the points leave the curve."""
    if not math.isfinite(state["deviance"]):
        return []
    deviance = state["deviance"]
    line = f"deviance {deviance:.3g}" if abs(deviance) < 10 else f"deviance {deviance:.1f}"
    if math.isfinite(state["gof_p_value"]):
        line += f", p = {p_text(state['gof_p_value'])}"
    lines = [line]
    if rejected(state):
        gap = misfit(state)
        lines.append("lognormal rejected at 5 %" + (f": points up to {gap:.2f} off it" if math.isfinite(gap) else ""))
    return lines


def interval_text(interval, digits):
    return f" ({interval[0]:.{digits}}–{interval[1]:.{digits}})" if interval else ""


def legend_label(state, units):
    description = describe(state)
    lines = [state["name"] + (f" ({description})" if description and description != state["name"] else "")]
    if has_fit(state):
        lines.append(f"fit: median {state['median']:.3g}{' ' + units if units else ''}"
                     f"{interval_text(state['median_ci'], '3g')}, β = {state['beta']:.2f}"
                     f"{interval_text(state['beta_ci'], '2f')}")
        lines += goodness_lines(state)
    else:
        reason = state["fit_status"] or "not available"
        line = f"no lognormal fit: {reason.replace('_', ' ')}"
        low, high = state["median_low"], state["median_high"]
        if math.isfinite(low) and math.isfinite(high) and high > 0:
            where = f"{low:.3g}" if low == high else f"{low:.3g} and {high:.3g}"
            line += f" (median {'at' if low == high else 'between'} {where}{' ' + units if units else ''})"
        lines.append(line)
    if state["crosses"]:
        lines.append(f"crosses: {', '.join(state['crosses'])}")
    return "\n  ".join(lines)


def is_cloud(study):
    return study["scaling"].startswith("none")


def plot(study, title, output):
    states = study["states"]
    units = study["im_units"]
    labels = [legend_label(state, units) for state in states]
    columns = 1 if len(states) == 1 else 2
    # The legend sits below the axes and fills its columns first: as tall as its tallest column.
    per_column = math.ceil(len(labels) / columns)
    column_lines = [sum(label.count("\n") + 1 for label in labels[c * per_column:(c + 1) * per_column])
                    for c in range(columns)]
    fig, ax = plt.subplots(figsize=(8.0, 4.8 + 0.135 * max(column_lines) + 0.12 * per_column))
    levels = np.concatenate([s["im"][np.isfinite(s["im"]) & (s["im"] > 0)] for s in states])
    if levels.size == 0:
        raise InputError("no limit state has an intensity level to plot")
    im_max, im_min = float(levels.max()), float(levels.min())
    x = np.linspace(im_max * 1e-3, im_max * 1.08, 400)
    # Spread the error bars of different limit states sideways so that they do not hide each other.
    spacing = (im_max - im_min) / max(1, max(len(s["im"]) for s in states) - 1) if im_max > im_min else im_max
    dodge = 0.06 * spacing
    handles = []
    banded = False

    for k, (state, label) in enumerate(zip(states, labels)):
        colour, marker = COLOURS[k % len(COLOURS)], MARKERS[k % len(MARKERS)]
        if has_fit(state):
            ax.plot(x, lognormal_cdf(x, state["median"], state["beta"]), color=colour, linewidth=1.8, zorder=2)
        band = state["band"] if has_fit(state) else None
        if band is not None:
            band_im, band_low, band_high = band
            ax.fill_between(band_im, band_low, band_high, color=colour, alpha=BAND_ALPHA, linewidth=0, zorder=1)
            banded = True
        shown = np.isfinite(state["probability"]) & (state["trials"] > 0)
        p = state["probability"][shown]
        low = np.clip(p - state["ci_low"][shown], 0.0, None)
        high = np.clip(state["ci_high"][shown] - p, 0.0, None)
        offset = (k - 0.5 * (len(states) - 1)) * dodge
        ax.errorbar(state["im"][shown] + offset, p, yerr=np.vstack((low, high)), fmt=marker, color=colour,
                    markersize=5.5, markerfacecolor="white", markeredgewidth=1.4, elinewidth=1.0, capsize=3,
                    zorder=3)
        line = Line2D([], [], color=colour, marker=marker, markerfacecolor="white", markeredgewidth=1.4,
                      linewidth=1.8, linestyle="-" if has_fit(state) else "none")
        handle = (Patch(facecolor=colour, alpha=BAND_ALPHA, linewidth=0), line) if band is not None else line
        handles.append((handle, label))

    ax.set_xlim(0.0, im_max * 1.08)
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel(axis_label(study))
    ax.set_ylabel("probability of exceedance")
    ax.grid(True, color="0.88", linewidth=0.6)
    ax.set_axisbelow(True)
    # Below the axes, where it can hide no data point.
    ax.legend([h for h, _ in handles], [lab for _, lab in handles], loc="upper center",
              bbox_to_anchor=(0.5, -0.12), ncol=columns, fontsize=8.5, frameon=False, labelspacing=0.9,
              columnspacing=2.0, title="limit states, least to most severe" if study["by_severity"] else None,
              title_fontsize=8.5)
    ax.set_title(title, fontsize=12)

    intervals = {s["interval"] for s in states if s["interval"]}
    interval = intervals.pop() if len(intervals) == 1 else "confidence"
    if is_cloud(study):
        points = "Markers: a cloud's samples in display bins (the fit uses every sample)"
        per_level = ""
    else:
        points = "Markers: observed fraction exceeding"
        trials = {int(t) for s in states for t in s["trials"] if t > 0}
        per_level = f"; {trials.pop()} trials per level" if len(trials) == 1 else ""
    lines = "Lines: lognormal fit by maximum likelihood" + ("; shaded: its 95 % bootstrap band." if banded else ".")
    note = textwrap.wrap(f"{points}, bars: {interval} interval{per_level}. {lines}", 135)
    fig.text(0.01, 0.01, "\n".join(note), fontsize=7.5, color="0.35", va="bottom")
    fig.tight_layout(pad=0.8, rect=(0, (0.02 + 0.12 * len(note)) / fig.get_figheight(), 1, 1))
    plot_support.save_figure(fig, output, dpi=150)


def summary(study):
    units = study["im_units"]
    unit = f" {units}" if units else ""
    lines = []
    if study["by_severity"]:
        lines += [f"severity order (least to most severe): {', '.join(s['name'] for s in study['states'])}", ""]
    for state in study["states"]:
        description = describe(state)
        lines.append(f"limit state {state['name']}" + (f" ({description})" if description else ""))
        if has_fit(state):
            lines.append(f"  lognormal fit: median = {state['median']:.6g}{unit}, "
                         f"beta = {state['beta']:.6g}, log-likelihood = {state['log_likelihood']:.6g}")
            if state["median_ci"] or state["beta_ci"]:
                parts = []
                if state["median_ci"]:
                    parts.append(f"median in [{state['median_ci'][0]:.6g}, {state['median_ci'][1]:.6g}]{unit}")
                if state["beta_ci"]:
                    parts.append(f"beta in [{state['beta_ci'][0]:.6g}, {state['beta_ci'][1]:.6g}]")
                lines.append(f"  95 % bootstrap intervals: {', '.join(parts)}")
            if math.isfinite(state["deviance"]):
                line = f"  goodness of fit: deviance = {state['deviance']:.6g}"
                if state["gof_dof"] is not None:
                    line += f" on {state['gof_dof']} dof"
                if math.isfinite(state["gof_p_value"]):
                    line += f", p = {p_text(state['gof_p_value'])}"
                    line += ": lognormal rejected at 5 %" if rejected(state) else ": not rejected at 5 %"
                gap = misfit(state)
                if math.isfinite(gap):
                    line += f"; largest |observed - fitted| = {gap:.4f}"
                lines.append(line)
        else:
            bracket = ""
            if math.isfinite(state["median_low"]) and math.isfinite(state["median_high"]):
                bracket = f"; the median lies in [{state['median_low']:.6g}, {state['median_high']:.6g}]"
            lines.append(f"  lognormal fit: none ({state['fit_status'] or 'median/beta are NaN'}){bracket}")
        if study["by_severity"]:
            place = study["states"].index(state) + 1
            lines.append(f"  severity: {place} of {len(study['states'])} (1 = least severe)")
        if state["crosses"]:
            lines.append(f"  fitted curve crosses, inside the levels: {', '.join(state['crosses'])}")
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
    parser = plot_support.parser(__doc__)
    parser.add_argument("results", help="study output HDF5 file")
    plot_support.add_output(parser)
    parser.add_argument("--summary", action="store_true", help="print the table of each limit state")
    plot_support.add_title(parser)
    args = parser.parse_args(argv)
    if not args.output and not args.summary:
        parser.error("nothing to do: give -o OUT.png, --summary or both")

    def work():
        study = read_study(args.results)
        if args.summary:
            print(summary(study))
        if args.output:
            plot(study, args.title or f"Fragility curves: {os.path.basename(args.results)}", args.output)

    return plot_support.run(work)


if __name__ == "__main__":
    sys.exit(main())
