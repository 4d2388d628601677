#!/usr/bin/python3
"""Plot an overturning spectrum of blockfrag: the map by verdict, the boundaries, the safe islands.

Reads the output of `blockfrag spectrum`: /map/frequency_ratio (omega_p / p), /map/amplitude_ratio
(a_p / (g tan alpha)), /map/verdict [frequency][amplitude] (0 stands, 1 overturns with no impact,
2 after one impact, 3 after more, 4 still moving at the cap, 5 failed, 6 rejected), /boundary (each
crossing's frequency_index, amplitude_ratio and direction: +1 onset of overturning, -1 end of an
overturning band), /minimum_overturning (each frequency's minimum overturning amplitude, refined
below the map's lowest onset) and the root attributes (alpha, pulse, config). The map is drawn as an
image, one colour per verdict; a standing point above an overturning one of its frequency is a safe
island and gets a colour of its own. The boundaries are lines through the crossings found by
bisection: the lowest onset of each frequency (the map's minimum overturning amplitude) joined
across frequencies, thick; every other crossing joined to the nearest crossing of the same
direction at the next frequency when it lies within a few amplitude cells, so a line ends where its
island or band ends. The refined minimum is a green line over it, with a dot where it lies below
the map's lowest onset (a band the map stepped over); files without it are drawn without it.
Several files are drawn as panels side by side (a map and a zoom into it, whose extent the first
panel outlines); the frequency axis is logarithmic when the grid's is.

    /usr/bin/python3 postproc/plots/plot_spectrum.py spectrum.h5 -o spectrum.png
    /usr/bin/python3 postproc/plots/plot_spectrum.py map.h5 zoom.h5 -o spectrum.png \
        --mark-point 1.2247,1.26
"""

import argparse
import json
import math
import os
import sys
import textwrap
from collections import deque

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_support  # noqa: E402  (beside this script; it chooses matplotlib's backend before pyplot)
from plot_support import InputError, text  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import BoundaryNorm, ListedColormap  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402
from matplotlib.ticker import FormatStrFormatter, LogLocator, NullFormatter  # noqa: E402

# The refined minimum overturning amplitude's colour (Okabe & Ito's bluish green).
MINIMUM_COLOUR = "#009E73"
# The classes drawn, in image order: (verdict code or "island", colour, legend label). Okabe & Ito's
# colours, as the other plots use them.
ISLAND = 7  # a drawn class of its own: stands, with an overturning point below it
# Crossings at neighbouring frequencies belong to one boundary line when at most this many amplitude
# cells apart (the steepest edges of a 400 x 400 map move about 7 cells from one frequency to the
# next; farther apart, they are two islands).
LINK_CELLS = 8
CLASSES = [
    (0, "#F2F2F2", "stands"),
    (ISLAND, "#56B4E9", "stands above an overturning amplitude: safe island"),
    (1, "#D55E00", "overturns, no impact"),
    (2, "#E69F00", "overturns after 1 impact"),
    (3, "#CC79A7", "overturns after 2 or more impacts"),
    (4, "#F0E442", "still moving at the run's cap"),
    (5, "#000000", "failed or rejected"),
]


def read_spectrum(path):
    hint = "a blockfrag spectrum output"
    with plot_support.open_hdf5(path) as f:
        frequency = plot_support.dataset(f, path, "/map/frequency_ratio", hint=hint)
        amplitude = plot_support.dataset(f, path, "/map/amplitude_ratio", hint=hint)
        verdict = plot_support.dataset(f, path, "/map/verdict", np.int64, hint=hint)
        boundary = {
            key: plot_support.dataset(f, path, "/boundary/" + key, None, hint=hint)
            for key in ("frequency_index", "amplitude_ratio", "direction")
        }
        config = plot_support.attribute(f, path, "config", lambda value: json.loads(text(value)))
        alpha = plot_support.attribute(f, path, "alpha", float)
        pulse = plot_support.attribute(f, path, "pulse", text)
        minimum = None
        if plot_support.has_group(f, "/minimum_overturning"):
            minimum = {
                key: plot_support.dataset(f, path, "/minimum_overturning/" + key, hint=hint)
                for key in ("amplitude_ratio", "map_amplitude_ratio")
            }
            minimum["tolerance"] = plot_support.attribute(f["/minimum_overturning"], path, "tolerance",
                                                          float)
    nf, na = len(frequency), len(amplitude)
    if minimum is not None and any(len(minimum[key]) != nf for key in
                                   ("amplitude_ratio", "map_amplitude_ratio")):
        raise InputError(f"{path}: /minimum_overturning has not one value per frequency ({nf})")
    if verdict.shape != (nf, na) or nf < 1 or na < 2:
        raise InputError(f"{path}: /map/verdict has shape {verdict.shape}, not ({nf}, {na})")
    index = boundary["frequency_index"].astype(np.int64)
    if len(index) and (index.min() < 0 or index.max() >= nf):
        raise InputError(f"{path}: /boundary/frequency_index outside the map")
    return {
        "path": path,
        "frequency": frequency,
        "amplitude": amplitude,
        "verdict": verdict,
        "boundary": boundary,
        "config": config,
        "alpha": alpha,
        "pulse": pulse,
        "minimum": minimum,
    }


def drawn_classes(verdict):
    """The verdicts with the safe islands marked: standing (0 or 4 is not overturned; 0 only is
    drawn as an island) above an overturning point of the same frequency."""
    overturned = (verdict >= 1) & (verdict <= 3)
    below = np.maximum.accumulate(overturned, axis=1)  # an overturning point at or below
    classes = np.where(verdict >= 5, 5, verdict)
    classes = np.where((verdict == 0) & below, ISLAND, classes)
    return classes


def islands(classes):
    """The connected groups of island cells (4-neighbours), largest first, as lists of (i, j)."""
    seen = np.zeros(classes.shape, dtype=bool)
    groups = []
    for start in zip(*np.nonzero(classes == ISLAND)):
        if seen[start]:
            continue
        seen[start] = True
        group, queue = [], deque([start])
        while queue:
            i, j = queue.popleft()
            group.append((i, j))
            for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                a, b = i + di, j + dj
                if 0 <= a < classes.shape[0] and 0 <= b < classes.shape[1] and not seen[a, b] \
                        and classes[a, b] == ISLAND:
                    seen[a, b] = True
                    queue.append((a, b))
        groups.append(group)
    return sorted(groups, key=len, reverse=True)


def edges(values, log):
    """Cell edges around the grid values: halfway between neighbours (in log when log)."""
    v = np.log(values) if log else np.asarray(values, dtype=float)
    if len(v) == 1:
        half = 0.02 if log else 0.02 * abs(v[0])  # a narrow column around the one value
        e = np.array([v[0] - half, v[0] + half])
    else:
        middle = (v[1:] + v[:-1]) / 2
        e = np.concatenate([[v[0] - (middle[0] - v[0])], middle, [v[-1] + (v[-1] - middle[-1])]])
    return np.exp(e) if log else e


def log_spaced(config, frequency):
    spec = config.get("frequency_ratio", {})
    if spec.get("spacing") == "log":
        return True
    if len(frequency) > 2 and np.all(frequency > 0):
        ratios = frequency[1:] / frequency[:-1]
        return bool(np.allclose(ratios, ratios[0], rtol=1e-9)) and not np.allclose(
            np.diff(frequency), np.diff(frequency)[0], rtol=1e-9)
    return False


def boundary_lines(data):
    """The boundaries as polylines, each (direction, lowest, frequencies, amplitudes): the lowest
    onset of every frequency as one line (broken where a frequency has none); every other crossing
    joined to the nearest unclaimed crossing of its direction at the next frequency when the two
    are within LINK_CELLS amplitude cells, else ending its line there."""
    frequency, amplitude = data["frequency"], data["amplitude"]
    nf = len(frequency)
    cell = float(np.median(np.diff(amplitude)))
    b = data["boundary"]
    per_frequency = [[] for _ in range(nf)]
    for i, a, d in zip(b["frequency_index"], b["amplitude_ratio"], b["direction"]):
        per_frequency[int(i)].append((float(a), int(d)))
    lowest = np.full(nf, np.nan)
    others = [[] for _ in range(nf)]
    for i, crossings in enumerate(per_frequency):
        crossings.sort()
        onsets = [a for a, d in crossings if d > 0]
        if onsets:
            lowest[i] = onsets[0]
        others[i] = [(a, d) for a, d in crossings if not (d > 0 and a == lowest[i])]
    lines = [(+1, True, frequency, lowest)]
    open_lines = []  # (direction, [frequency], [amplitude]) ending at the previous frequency
    for i in range(nf):
        extended = []
        unclaimed = list(open_lines)
        for a, d in others[i]:
            best = None
            for line in unclaimed:
                gap = abs(line[2][-1] - a)
                if line[0] == d and gap <= LINK_CELLS * cell and (
                        best is None or gap < abs(best[2][-1] - a)):
                    best = line
            if best is None:
                best = (d, [], [])
            else:
                unclaimed.remove(best)
            best[1].append(frequency[i])
            best[2].append(a)
            extended.append(best)
        for line in unclaimed:
            lines.append((line[0], False, np.array(line[1]), np.array(line[2])))
        open_lines = extended
    for line in open_lines:
        lines.append((line[0], False, np.array(line[1]), np.array(line[2])))
    return lines


def minimum_line(data):
    """The refined minimum as (frequencies, amplitudes, lowered): lowered where it lies below the
    map's lowest onset by more than its tolerance (a band the map stepped over). None for a file
    without it."""
    minimum = data["minimum"]
    if minimum is None:
        return None
    refined, unrefined = minimum["amplitude_ratio"], minimum["map_amplitude_ratio"]
    with np.errstate(invalid="ignore"):
        lowered = refined < unrefined * (1 - minimum["tolerance"])
    return data["frequency"], refined, lowered


def describe(data):
    c = data["config"]
    block = c.get("block", {})
    contact = c.get("contact", {})
    effects = c.get("effects", "auto")
    model = "full model" if effects == "auto" else "effects " + "+".join(effects)
    pulse = c.get("pulse", {})
    family = data["pulse"] + (f", {pulse['cycles']:g} cycle(s)" if "cycles" in pulse else "") + (
        f", n = {pulse['n']}" if "n" in pulse else "")
    R = math.hypot(block.get("half_width", 0.0), block.get("half_height", 0.0))
    rocking = contact.get("rocking_restitution")
    rocking_text = "" if rocking is None else (
        ", r = Housner's" if rocking == "housner" else f", r = {rocking:g}")
    return (f"{family}; block alpha = {math.degrees(data['alpha']):.2f} deg, R = {R:.4g} m; "
            f"mu = {contact.get('friction', float('nan')):g}, e = {contact.get('restitution', float('nan')):g}"
            f"{rocking_text}; {model}")


def draw_panel(ax, data, mark_frequency, mark_point, zoom_box):
    frequency, amplitude = data["frequency"], data["amplitude"]
    log = log_spaced(data["config"], frequency)
    classes = drawn_classes(data["verdict"])
    codes = [code for code, _, _ in CLASSES]
    index = np.vectorize({code: k for k, code in enumerate(codes)}.get)(classes)
    cmap = ListedColormap([colour for _, colour, _ in CLASSES])
    norm = BoundaryNorm(np.arange(len(CLASSES) + 1) - 0.5, len(CLASSES))
    x, y = edges(frequency, log), edges(amplitude, False)
    ax.pcolormesh(x, y, index.T, cmap=cmap, norm=norm, shading="flat", rasterized=True)
    if log:
        ax.set_xscale("log")
        # Plain numbers, not powers of ten: at 1, 2, 5 on wide ranges, more on narrow ones.
        span = x[-1] / x[0]
        subs = (1.0, 2.0, 5.0) if span > 30 else (1.0, 1.5, 2.0, 3.0, 5.0) if span > 4 else (
            1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)
        ax.xaxis.set_major_locator(LogLocator(subs=subs))
        ax.xaxis.set_major_formatter(FormatStrFormatter("%g"))
        ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(y[0], y[-1])
    if y[0] < 1.0 < y[-1]:
        ax.axhline(1.0, color="0.35", lw=0.8, ls=":", zorder=3)
    few = len(frequency) < 12
    for direction, lowest, fx, fy in boundary_lines(data):
        # A crossing linked to none at its neighbours would draw no line: a dot shows it.
        single = len(fx) == 1 or few
        ax.plot(fx, fy, color="black", lw=2.0 if lowest else 1.0, ls="-" if direction > 0 else "--",
                zorder=4, marker="o" if single else None, ms=2.5 if few else 1.5)
    refined = minimum_line(data)
    if refined is not None:
        fx, fy, lowered = refined
        ax.plot(fx, fy, color=MINIMUM_COLOUR, lw=1.4, zorder=5, marker="o" if few else None, ms=2.5)
        ax.plot(fx[lowered], fy[lowered], ls="", marker="o", ms=4, color=MINIMUM_COLOUR, mec="black",
                mew=0.5, zorder=6)
    groups = islands(classes)
    if groups:
        i, j = zip(*groups[0])
        fi = frequency[list(i)]
        cx = math.exp(np.mean(np.log(fi))) if log else float(np.mean(fi))
        cy = float(np.mean(amplitude[list(j)]))
        tx = cx * (1.6 if log else 1.0) + (0 if log else 0.15 * (x[-1] - x[0]))
        ty = cy + 0.12 * (y[-1] - y[0])
        tx, ty = min(tx, x[-1] * (0.85 if log else 1.0)), min(ty, y[-1] - 0.05 * (y[-1] - y[0]))
        ax.annotate(f"safe island\n({len(groups)} in all)" if len(groups) > 1 else "safe island",
                    xy=(cx, cy), xytext=(tx, ty), fontsize=8, zorder=6,
                    arrowprops=dict(arrowstyle="->", color="black", lw=0.8),
                    bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="0.5", lw=0.5))
    for value in mark_frequency:
        if x[0] <= value <= x[-1]:
            ax.axvline(value, color="black", lw=0.8, ls="-.", zorder=5)
    for fx, fy in mark_point:
        if x[0] <= fx <= x[-1] and y[0] <= fy <= y[-1]:
            ax.plot([fx], [fy], marker="*", ms=11, color="white", mec="black", mew=0.9, zorder=7)
    if zoom_box is not None:
        (x0, x1), (y0, y1) = zoom_box
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, ec="black", lw=1.0, zorder=6))
    ax.set_xlabel(r"frequency ratio $\omega_p / p$")
    ax.set_ylabel(r"amplitude ratio $a_p / (g \tan\alpha)$")
    ax.set_title(os.path.basename(data["path"]), fontsize=9)


def plot(datasets, title, output, mark_frequency, mark_point):
    panels = len(datasets)
    fig, axes = plt.subplots(1, panels, figsize=(6.4 * panels, 7.2 if panels == 1 else 6.4),
                             squeeze=False)
    for k, data in enumerate(datasets):
        zoom_box = None
        if k == 0 and panels > 1:
            other = datasets[1]
            zoom_box = ((other["frequency"][0], other["frequency"][-1]),
                        (other["amplitude"][0], other["amplitude"][-1]))
        draw_panel(axes[0][k], data, mark_frequency, mark_point, zoom_box)
    present = set()
    for data in datasets:
        present |= set(np.unique(drawn_classes(data["verdict"])).tolist())
    handles = [Patch(facecolor=colour, edgecolor="0.6", label=label)
               for code, colour, label in CLASSES if code in present]
    handles += [
        Line2D([], [], color="black", lw=2.0, label="lowest onset of overturning on the map (bisected)"),
        Line2D([], [], color="black", lw=1.0, label="higher onsets (upper island edges)"),
        Line2D([], [], color="black", lw=1.0, ls="--", label="ends of overturning (lower island edges)"),
        Line2D([], [], color="0.35", lw=0.8, ls=":", label=r"static limit $a_p = g \tan\alpha$"),
    ]
    refined = [data for data in datasets if data["minimum"] is not None]
    if refined:
        tolerances = sorted({data["minimum"]["tolerance"] for data in refined})
        handles.append(Line2D([], [], color=MINIMUM_COLOUR, lw=1.4,
                              label="minimum overturning amplitude, refined (tolerance "
                                    + ", ".join(f"{t:g}" for t in tolerances) + ")"))
        handles.append(Line2D([], [], ls="", marker="o", ms=4, color=MINIMUM_COLOUR, mec="black", mew=0.5,
                              label="refined below the map's lowest onset"))
    if mark_point:
        handles.append(Line2D([], [], ls="", marker="*", ms=11, color="white", mec="black", mew=0.9,
                              label="marked: " + ", ".join(f"({a:g}, {b:g})" for a, b in mark_point)))
    if mark_frequency:
        handles.append(Line2D([], [], color="black", lw=0.8, ls="-.",
                              label="marked: " + ", ".join(f"{v:g}" for v in mark_frequency)))
    fig.legend(handles=handles, loc="lower center", ncol=2 if panels == 1 else 3, fontsize=8,
               frameon=False)
    width = 86 * panels
    fig.suptitle("\n".join(textwrap.wrap(title, width) + textwrap.wrap(describe(datasets[0]), width)),
                 fontsize=10)
    fig.tight_layout(rect=(0, 0.17 if panels == 1 else 0.12, 1, 0.94))
    plot_support.save_figure(fig, output, dpi=150)


def point(text_value):
    """--mark-point's value: two numbers separated by a comma."""
    try:
        frequency, amplitude = (float(part) for part in text_value.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected FREQUENCY,AMPLITUDE, got {text_value!r}") from None
    return frequency, amplitude


def main(argv=None):
    parser = plot_support.parser(__doc__)
    parser.add_argument("spectra", nargs="+", help="spectrum output HDF5 file(s), one panel each (at most 3)")
    plot_support.add_output(parser, required=True)
    parser.add_argument("--mark-frequency", type=float, action="append", default=[], metavar="RATIO",
                        help="draw a vertical line at this frequency ratio (repeatable)")
    parser.add_argument("--mark-point", type=point, action="append", default=[],
                        metavar="FREQUENCY,AMPLITUDE",
                        help="draw a star at this (frequency ratio, amplitude ratio) (repeatable)")
    plot_support.add_title(parser)
    args = parser.parse_args(argv)

    def work():
        if len(args.spectra) > 3:
            raise InputError(f"{len(args.spectra)} files are more than the 3 panels one figure shows")
        datasets = [read_spectrum(path) for path in args.spectra]
        title = args.title or f"Overturning spectrum: {os.path.basename(args.spectra[0])}"
        plot(datasets, title, args.output, args.mark_frequency, args.mark_point)

    return plot_support.run(work)


if __name__ == "__main__":
    sys.exit(main())
