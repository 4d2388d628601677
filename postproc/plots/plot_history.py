#!/usr/bin/python3
"""Plot a block's time history: rotation, slip and contact forces against time, shaded by mode.

Reads the CSV that `blockfrag simulate --history FILE.csv` writes (columns t, x, y, theta, vx, vy,
omega, mode, friction_per_weight, normal_per_weight) and writes a PNG with three stacked panels.

    /usr/bin/python3 postproc/plots/plot_history.py history.csv -o history.png [--title TEXT]
"""

import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_support  # noqa: E402  (beside this script; it chooses matplotlib's backend before pyplot)
from plot_support import InputError  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

COLUMNS = ("t", "x", "y", "theta", "vx", "vy", "omega", "mode", "friction_per_weight",
           "normal_per_weight")

# Pale enough that the curves stay the figure's subject; rest is left white.
MODE_STYLE = {
    "rest": (None, "rest"),
    "slide": ("#cfe2f3", "slide"),
    "rock": ("#fde3c8", "rock"),
    "slide_rock": ("#e4d3ef", "slide-rock"),
    "flight": ("#d5ecd4", "flight"),
}


def read_history(path):
    try:
        with open(path, newline="") as stream:
            reader = csv.DictReader(stream)
            missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
            if missing:
                raise InputError(f"{path}: not a blockfrag history: missing column(s) {', '.join(missing)}")
            rows = list(reader)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except OSError as error:
        raise InputError(f"cannot read {path}: {error.strerror}") from error
    if not rows:
        raise InputError(f"{path}: the history has no rows")

    data = {}
    for column in COLUMNS:
        if column == "mode":
            continue
        try:
            data[column] = np.array([float(row[column]) for row in rows])
        except (TypeError, ValueError) as error:
            raise InputError(f"{path}: column {column} holds a value that is not a number") from error
    modes = [row["mode"] for row in rows]
    unknown = sorted(set(modes) - set(MODE_STYLE))
    if unknown:
        raise InputError(f"{path}: unknown mode(s) {', '.join(unknown)} (expected one of {', '.join(MODE_STYLE)})")
    data["mode"] = np.array(modes)
    return data


def shade_modes(axes, t, modes):
    """Colour the background of every panel by the mode in force from each row to the next."""
    present = []
    for mode, (colour, label) in MODE_STYLE.items():
        mask = modes == mode
        if not mask.any():
            continue
        present.append((colour, label))
        if colour is None:
            continue
        # A row's mode holds until the next row: extend each run one sample to the right.
        held = mask | np.concatenate(([False], mask[:-1]))
        for ax in axes:
            ax.fill_between(t, 0, 1, where=held, step="post", color=colour, linewidth=0,
                            transform=ax.get_xaxis_transform(), zorder=0)
    return present


def plot(data, title, output):
    t = data["t"]
    theta_deg = np.degrees(data["theta"])
    fig, (ax_theta, ax_x, ax_force) = plt.subplots(3, 1, sharex=True, figsize=(8.0, 7.5),
                                                   gridspec_kw={"height_ratios": [1.2, 1.0, 1.0]})

    ax_theta.plot(t, theta_deg, color="#1f3b73", linewidth=1.2)
    ax_theta.set_ylabel(r"rotation $\theta$ [deg]")
    peak = int(np.argmax(np.abs(theta_deg)))
    overturned = abs(theta_deg[peak]) >= 90.0 - 1e-9
    ax_theta.set_title(f"{'overturned' if overturned else 'max |θ| = ' + format(abs(theta_deg[peak]), '.2f') + '°'}"
                       f" at t = {t[peak]:.3g} s", loc="right", fontsize=9)

    ax_x.plot(t, data["x"], color="#8c2d04", linewidth=1.2)
    ax_x.set_ylabel("displacement $x$ [m]")
    ax_x.set_title(f"max |x| = {np.max(np.abs(data['x'])):.4g} m, final x = {data['x'][-1]:.4g} m", loc="right",
                   fontsize=9)

    ax_force.plot(t, data["normal_per_weight"], color="#333333", linewidth=1.0, label="normal $V/Mg$")
    ax_force.plot(t, data["friction_per_weight"], color="#2b8cbe", linewidth=1.0, label="friction $F/Mg$")
    ax_force.set_ylabel("contact force / weight")
    ax_force.set_xlabel("time $t$ [s]")
    ax_force.legend(loc="lower right", bbox_to_anchor=(1.0, 1.0), ncol=2, frameon=False, fontsize=9,
                    borderaxespad=0.2)

    # Shading spans the full height of each panel; it must not widen the data limits.
    axes = (ax_theta, ax_x, ax_force)
    limits = [ax.get_ylim() for ax in axes]
    present = shade_modes(axes, t, data["mode"])
    for ax, (low, high) in zip(axes, limits):
        ax.set_ylim(low, high)
    for ax in axes:
        ax.axhline(0.0, color="0.6", linewidth=0.6, zorder=1)
        ax.grid(True, color="0.85", linewidth=0.5)
        ax.set_axisbelow(True)
        ax.margins(x=0)

    handles = [Patch(facecolor=colour or "white", edgecolor="0.6", linewidth=0.5, label=label)
               for colour, label in present]
    ax_theta.legend(handles=handles, loc="lower left", bbox_to_anchor=(0.0, 1.0), ncol=len(handles),
                    frameon=False, fontsize=9, handlelength=1.5, borderaxespad=0.2, columnspacing=1.2)
    fig.suptitle(title, fontsize=12)
    fig.align_ylabels((ax_theta, ax_x, ax_force))
    fig.tight_layout()
    plot_support.save_figure(fig, output, dpi=150)


def main(argv=None):
    parser = plot_support.parser(__doc__)
    parser.add_argument("history", help="time history CSV from blockfrag simulate --history")
    plot_support.add_output(parser, required=True)
    plot_support.add_title(parser, "the CSV's file name")
    args = parser.parse_args(argv)

    def work():
        data = read_history(args.history)
        if not np.all(np.isfinite(data["t"])):
            raise InputError(f"{args.history}: time column holds NaN or infinity")
        plot(data, args.title or f"Time history: {os.path.basename(args.history)}", args.output)

    return plot_support.run(work)


if __name__ == "__main__":
    sys.exit(main())
