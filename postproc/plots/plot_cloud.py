#!/usr/bin/python3
"""Plot every sample of a blockfrag study: its intensity against its max |theta|/alpha, by verdict.

Reads the study's HDF5 output: /samples/im (the sample's intensity: its stripe's, or its own in a
cloud), /results/max_abs_theta, /results/overturned and /results/status, the block's geometry
(/samples/alpha, /samples/half_width, /samples/half_height when sampled, else the base scene's
block in the root attribute config: a rectangle's half_width/half_height, or a polygon's easier
base corner) and the limit states (/fragility/<name> attributes type and threshold). Each sample
is a point at (im, max |theta|/alpha) on a log intensity axis, coloured overturned, above a
rotation limit or below; with --limit-state NAME, exceeding NAME or not. Samples that share an
intensity (stripes) are spread a little sideways; failed and rejected samples (status not 0) are
left out and counted. With a record suite (/samples/record, /records/file), --by-record draws one
panel per record.

    /usr/bin/python3 postproc/plots/plot_cloud.py results.h5 -o samples.png
    /usr/bin/python3 postproc/plots/plot_cloud.py results.h5 -o by_record.png --by-record
    /usr/bin/python3 postproc/plots/plot_cloud.py results.h5 -o slide.png --limit-state slide_5cm
"""

import json
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
from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter  # noqa: E402

# Okabe & Ito's colours, as in plot_fragility.py: vermillion, orange, blue.
OVERTURNED, EXCEEDED, BELOW = "#D55E00", "#E69F00", "#0072B2"
# Beyond this many records one panel each is no longer readable.
MAX_PANELS = 64
# Stripes put every sample of a level at one intensity: spread them this far sideways (a factor).
JITTER = 0.035


def polygon_alpha(vertices, where):
    """alpha of a polygon block: atan of its easier base corner's |x - x_cm| / (y_cm - y_base), the
    centre of mass from the shoelace formulas, the base the lowest edge (as the engine takes it)."""
    try:
        v = np.asarray(vertices, dtype=float)
    except (TypeError, ValueError) as error:
        raise InputError(f"{where}: the polygon's vertices are not pairs of numbers") from error
    if v.ndim != 2 or v.shape[1] != 2 or len(v) < 3 or not np.all(np.isfinite(v)):
        raise InputError(f"{where}: the polygon is not a list of at least 3 [x, y] vertices")
    x, y = v[:, 0], v[:, 1]
    x1, y1 = np.roll(x, -1), np.roll(y, -1)
    cross = x * y1 - x1 * y
    area = cross.sum() / 2.0
    if area == 0.0:
        raise InputError(f"{where}: the polygon has no area")
    cx = ((x + x1) * cross).sum() / (6.0 * area)
    cy = ((y + y1) * cross).sum() / (6.0 * area)
    base = x[y == y.min()]
    height = cy - y.min()
    if len(base) != 2 or height <= 0:
        raise InputError(f"{where}: the polygon does not rest on one lowest edge below its centre of mass")
    return math.atan(float(np.min(np.abs(base - cx))) / height)


def sample_alphas(file, path, count):
    """Each sample's alpha: sampled, or from its sampled half-width/half-height, or the base scene's."""
    samples = file["samples"]
    if "alpha" in samples:
        return np.asarray(samples["alpha"][...], dtype=float).ravel()
    if "config" not in file.attrs:
        raise InputError(f"{path}: no /samples/alpha and no root attribute config to take the block's shape from")
    try:
        block = json.loads(text(file.attrs["config"]))["scene"]["block"]
    except (ValueError, KeyError, TypeError) as error:
        raise InputError(f"{path}: the root attribute config has no scene.block ({error})") from error
    if "polygon" in block:
        return np.full(count, polygon_alpha(block["polygon"], f"{path}: config /scene/block/polygon"))
    try:
        a = float(block["half_width"]) if "half_width" not in samples else None
        b = float(block["half_height"]) if "half_height" not in samples else None
    except (KeyError, TypeError, ValueError) as error:
        raise InputError(f"{path}: config /scene/block has neither half_width/half_height nor polygon") from error
    a = np.asarray(samples["half_width"][...], dtype=float).ravel() if a is None else np.full(count, a)
    b = np.asarray(samples["half_height"][...], dtype=float).ravel() if b is None else np.full(count, b)
    if len(a) != count or len(b) != count:
        raise InputError(f"{path}: /samples/half_width or half_height differs in length from /samples/im")
    return np.arctan2(a, b)


def column(file, path, name, count=None, dtype=float):
    values = plot_support.dataset(file, path, name, dtype, hint="a blockfrag study output").ravel()
    if count is not None and len(values) != count:
        raise InputError(f"{path}: {name} has {len(values)} entries, /samples/im {count}")
    return values


def read_samples(path):
    with plot_support.open_hdf5(path) as file:
        im = column(file, path, "/samples/im")
        n = len(im)
        data = {
            "im": im,
            "max_abs_theta": column(file, path, "/results/max_abs_theta", n),
            "overturned": column(file, path, "/results/overturned", n) != 0,
            "final_slide": column(file, path, "/results/final_slide", n) if "/results/final_slide" in file else None,
            "post_earthquake_safety_factor": column(file, path, "/results/post_earthquake_safety_factor", n)
            if "/results/post_earthquake_safety_factor" in file else None,
            "status": column(file, path, "/results/status", n) if "/results/status" in file else np.zeros(n),
        }
        data["alpha"] = sample_alphas(file, path, n)
        if len(data["alpha"]) != n:
            raise InputError(f"{path}: /samples/alpha has {len(data['alpha'])} entries, /samples/im {n}")
        fragility = file["fragility"] if plot_support.has_group(file, "fragility") else None
        attrs = fragility.attrs if fragility is not None else {}
        units = text(attrs["im_units"]) if "im_units" in attrs else \
            (text(file["samples/im"].attrs["units"]) if "units" in file["samples/im"].attrs else "")
        name = text(attrs["im_label"]) if "im_label" in attrs else \
            (text(attrs["im_name"]).replace("_", " ") if "im_name" in attrs else "intensity")
        data["im_label"] = f"{name} [{units}]" if units and units != "1" else name
        data["cloud"] = text(attrs["scaling"]).startswith("none") if "scaling" in attrs else False
        data["limit_states"] = read_limit_states(file, fragility)
        data["records"] = None
        if "/samples/record" in file and "/records/file" in file:
            files = [os.path.splitext(os.path.basename(text(f)))[0] for f in file["records/file"][...]]
            record = column(file, path, "/samples/record", n, dtype=np.int64)
            if np.any((record < 0) | (record >= len(files))):
                raise InputError(f"{path}: /samples/record names a record that /records/file does not hold")
            data["records"] = (record, files)
    return data


def read_limit_states(file, fragility):
    """(name, type, threshold, whether an overturned block exceeds it) of each limit state in
    /fragility; the last from the group's attribute overturned_exceeds, else the config's limit
    state, else true for a rotation limit and false for a slide limit."""
    configured = {}
    try:
        for entry in json.loads(text(file.attrs["config"]))["limit_states"]:
            configured[entry["name"]] = entry
    except (KeyError, ValueError, TypeError):
        pass
    states = []
    for name, state in (fragility.items() if fragility is not None else []):
        if not isinstance(state, h5py.Group) or "type" not in state.attrs:
            continue
        kind = text(state.attrs["type"])
        threshold = float(state.attrs["threshold"]) if "threshold" in state.attrs else math.nan
        if "overturned_exceeds" in state.attrs:
            overturned = bool(state.attrs["overturned_exceeds"])
        elif isinstance(configured.get(name, {}).get("overturned_exceeds"), bool):
            overturned = configured[name]["overturned_exceeds"]
        else:
            overturned = kind != "residual_slide"
        states.append((name, kind, threshold, overturned))
    return states


def ratio(data):
    with np.errstate(divide="ignore", invalid="ignore"):
        return data["max_abs_theta"] / data["alpha"]


def verdicts(data, limit_state):
    """(categories, per-sample category index): the legend's labels and colours and where each
    sample falls."""
    r = ratio(data)
    if limit_state is None:
        limits = sorted(t for _, kind, t, _ in data["limit_states"] if kind == "max_rotation" and math.isfinite(t))
        if limits:
            above = f"above a rotation limit (max |θ|/α > {limits[0]:g})" if len(limits) == 1 else \
                f"above the lowest rotation limit (max |θ|/α > {limits[0]:g})"
            categories = [("overturned", OVERTURNED), (above, EXCEEDED), ("below", BELOW)]
            index = np.where(data["overturned"], 0, np.where(r > limits[0], 1, 2))
        else:
            categories = [("overturned", OVERTURNED), ("not overturned", BELOW)]
            index = np.where(data["overturned"], 0, 1)
        return categories, index
    name, kind, threshold, overturned_exceeds = limit_state
    if kind == "overturning":
        exceeded = data["overturned"].copy()
        what = "overturned"
    elif kind == "max_rotation":
        exceeded = r > threshold
        what = f"max |θ|/α > {threshold:g}"
    elif kind == "residual_slide":
        if data["final_slide"] is None:
            raise InputError("the file has no /results/final_slide for a residual_slide limit state")
        exceeded = np.abs(data["final_slide"]) > threshold
        what = f"residual slide > {threshold:g} m"
    elif kind == "post_earthquake_unstable":
        if data["post_earthquake_safety_factor"] is None:
            raise InputError("the file has no /results/post_earthquake_safety_factor for a "
                             "post_earthquake_unstable limit state")
        with np.errstate(invalid="ignore"):  # NaN: no factor (not standing at rest), not counted
            exceeded = data["post_earthquake_safety_factor"] < threshold
        what = f"post-earthquake safety factor < {threshold:g}"
    else:
        raise InputError(f"limit state {name} has a type this script does not know: {kind}")
    if overturned_exceeds and kind != "overturning":
        exceeded |= data["overturned"]
        what += " or overturned"
    categories = [(f"exceeds {name} ({what})", OVERTURNED), (f"does not exceed {name}", BELOW)]
    return categories, np.where(exceeded, 0, 1)


def shared_intensities(data):
    """Whether samples share intensities (stripes, or a cloud of a few records at one scale)."""
    return not data["cloud"] or len(np.unique(data["im"])) < len(data["im"]) / 2


def positions(data):
    """x of each sample: its intensity, spread sideways (deterministically) when samples share them."""
    x = data["im"].copy()
    if shared_intensities(data):
        spread = np.random.default_rng(0).uniform(-1.0, 1.0, len(x))
        x *= np.exp(JITTER * spread)
    return x


def draw_panel(ax, x, y, index, categories, limits, size):
    for k, (_, colour) in reversed(list(enumerate(categories))):
        mask = index == k
        ax.scatter(x[mask], y[mask], s=size, color=colour, linewidths=0, zorder=3 + (len(categories) - k),
                   rasterized=len(x) > 5000)
    ax.axhline(1.0, color="0.45", linewidth=0.8, linestyle=":", zorder=2)  # out of sight above y_top
    for name, threshold in limits:
        ax.axhline(threshold, color=EXCEEDED, linewidth=0.9, linestyle="--", zorder=2)
    ax.set_xscale("log")
    ax.grid(True, which="both", color="0.9", linewidth=0.5)
    ax.set_axisbelow(True)


def label_intensities(ax, data, x_range, most):
    """Plain numbers on the log intensity axis, at most `most` of them, evenly spread in log: the
    levels of stripes, else 1-2-5 steps."""
    if not data["cloud"]:
        candidates = np.unique(data["im"][np.isfinite(data["im"]) & (data["im"] > 0)])
    else:
        low, high = math.floor(math.log10(x_range[0])), math.ceil(math.log10(x_range[1]))
        steps = (1, 2, 5) if high - low <= 3 else (1,)
        candidates = np.array([m * 10.0 ** e for e in range(low, high + 1) for m in steps])
        candidates = candidates[(candidates >= x_range[0]) & (candidates <= x_range[1])]
    # Keep a tick only when it is far enough (in log) from the last one kept.
    gap = 0.0 if len(candidates) <= most else math.log(x_range[1] / x_range[0]) / most
    ticks = []
    for tick in candidates:
        if not ticks or math.log(tick / ticks[-1]) >= 0.999 * gap:
            ticks.append(tick)
    ax.xaxis.set_major_locator(FixedLocator(ticks))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:.3g}"))
    ax.xaxis.set_minor_formatter(NullFormatter())


def plot(data, limit_state, by_record, title, output):
    ok = data["status"] == 0
    left_out = int(np.sum(~ok))
    finite = np.isfinite(data["im"]) & (data["im"] > 0) & np.isfinite(ratio(data))
    shown = ok & finite
    if not shown.any():
        raise InputError("no successful sample with a positive intensity to plot")
    x, y = positions(data)[shown], ratio(data)[shown]
    categories, index = verdicts(data, limit_state)
    index = index[shown]
    limits = [(name, t) for name, kind, t, _ in data["limit_states"]
              if kind == "max_rotation" and math.isfinite(t) and (limit_state is None or limit_state[0] == name)]
    counts = [int(np.sum(index == k)) for k in range(len(categories))]
    handles = [Line2D([], [], marker="o", linestyle="none", markersize=6, markerfacecolor=colour,
                      markeredgewidth=0, label=f"{label}: {count}")
               for (label, colour), count in zip(categories, counts)]
    if limits:
        handles.append(Line2D([], [], color=EXCEEDED, linewidth=0.9, linestyle="--",
                              label="rotation limit" + ("s: " if len(limits) > 1 else ": ")
                              + ", ".join(f"{name} ({t:g})" for name, t in limits)))
    # Up to the largest rotation or limit shown: |theta| = alpha only when the samples come near it.
    highest = max([float(y.max())] + [t for _, t in limits])
    y_top = 1.15 if highest == 0 else 1.08 * highest
    if y_top > 1.0:
        handles.append(Line2D([], [], color="0.45", linewidth=0.8, linestyle=":", label="|θ| = α"))
    size = 10.0 if len(x) < 3000 else (5.0 if len(x) < 30000 else 2.0)
    x_range = (x.min() / 1.15, x.max() * 1.15)

    if by_record:
        record, files = data["records"]
        record = record[shown]
        count = len(files)
        columns = min(count, 6 if count > 12 else 4 if count > 4 else count)
        rows = math.ceil(count / columns)
        panel = (2.3, 1.9) if columns > 4 else (3.0, 2.4)
        fig, axes = plt.subplots(rows, columns, figsize=(panel[0] * columns + 0.8, panel[1] * rows + 1.4),
                                 sharex=True, sharey=True, squeeze=False)
        for j, ax in enumerate(axes.flat):
            if j >= count:
                ax.set_visible(False)
                continue
            mask = record == j
            draw_panel(ax, x[mask], y[mask], index[mask], categories, limits, 9.0)
            ax.set_title(files[j].replace("_", " "), fontsize=7.5, pad=3)
            ax.tick_params(labelsize=7)
        axes.flat[0].set_xlim(*x_range)
        label_intensities(axes.flat[0], data, x_range, 4)
        axes.flat[0].set_ylim(0.0, y_top)
        for ax in axes[-1, :]:
            ax.set_xlabel(data["im_label"], fontsize=8)
        # A last row with empty places: the panels above them carry the axis labels.
        for j in range(count, rows * columns):
            above = axes.flat[j - columns]
            above.xaxis.set_tick_params(labelbottom=True)
            above.set_xlabel(data["im_label"], fontsize=8)
        for ax in axes[:, 0]:
            ax.set_ylabel("max |θ| / α", fontsize=8)
        columns = min(len(handles), 3)
        fig.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, 1.0 - 0.4 / fig.get_figheight()),
                   ncol=columns, fontsize=8, frameon=False)
        fig.suptitle(title, fontsize=12, y=1.0 - 0.05 / fig.get_figheight(), va="top")
        top = 1.0 - (0.3 + 0.17 * math.ceil(len(handles) / columns)) / fig.get_figheight()
    else:
        fig, ax = plt.subplots(figsize=(8.0, 5.6 + 0.2 * math.ceil(len(handles) / 2)))
        draw_panel(ax, x, y, index, categories, limits, size)
        ax.set_xlim(*x_range)
        label_intensities(ax, data, x_range, 12)
        ax.set_ylim(0.0, y_top)
        ax.set_xlabel(data["im_label"])
        ax.set_ylabel("max |θ| / α")
        # Below the axes, where it can hide no sample.
        ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2, fontsize=8.5,
                  frameon=False)
        ax.set_title(title, fontsize=12)
        top = 1.0

    note = f"{int(shown.sum())} samples"
    if shared_intensities(data):
        note += f"; samples of one intensity spread ±{100 * JITTER:.1f} % sideways to be seen"
    if left_out:
        note += f"; {left_out} failed or rejected sample{'s' if left_out != 1 else ''} left out"
    if int(np.sum(ok & ~finite)):
        note += f"; {int(np.sum(ok & ~finite))} without a finite intensity or rotation left out"
    note += ". α = atan(a/b) of each sample's block (a polygon's: its easier base corner's)."
    note = textwrap.wrap(note, int(20 * fig.get_figwidth()))
    fig.text(0.01, 0.01, "\n".join(note), fontsize=7, color="0.35", va="bottom")
    fig.tight_layout(rect=(0, (0.03 + 0.12 * len(note)) / fig.get_figheight(), 1, top))
    plot_support.save_figure(fig, output, dpi=150)


def main(argv=None):
    parser = plot_support.parser(__doc__)
    parser.add_argument("results", help="study output HDF5 file")
    plot_support.add_output(parser, required=True)
    parser.add_argument("--by-record", action="store_true", help="one panel per record of a record suite")
    parser.add_argument("--limit-state", metavar="NAME", help="colour by whether each sample exceeds this limit state")
    plot_support.add_title(parser)
    args = parser.parse_args(argv)

    def work():
        data = read_samples(args.results)
        limit_state = None
        if args.limit_state is not None:
            known = {state[0]: state for state in data["limit_states"]}
            if args.limit_state not in known:
                raise InputError(f"--limit-state {args.limit_state}: {args.results} has no such limit state "
                                 f"(it has: {', '.join(known) or 'none'})")
            limit_state = known[args.limit_state]
        if args.by_record:
            if data["records"] is None:
                raise InputError(f"--by-record: {args.results} is not a study of records (no /samples/record)")
            if len(data["records"][1]) > MAX_PANELS:
                raise InputError(f"--by-record: {len(data['records'][1])} records are more than the "
                                 f"{MAX_PANELS} panels one figure can show")
        title = args.title or f"Each sample's rotation and verdict: {os.path.basename(args.results)}"
        plot(data, limit_state, args.by_record, title, args.output)

    return plot_support.run(work)


if __name__ == "__main__":
    sys.exit(main())
