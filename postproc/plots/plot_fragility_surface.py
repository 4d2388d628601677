#!/usr/bin/python3
"""Plot a blockfrag study's fragility surfaces: the fitted probit's contours over the observed grid.

Reads /fragility_surface of a surface study's HDF5 output (a study whose intensity_measure has a
"second" axis, docs/studies.md): per limit state the grid axes im1 and im2, the observed
probability at each cell (n1 x n2) and the fit's coefficients b0, b1, b2 of
P = Phi(b0 + b1 ln im1 + b2 ln im2) with its fit_status and goodness of fit (deviance, gof_dof,
gof_p_value). One panel per limit state: each cell a
marker coloured by its observed probability (cells without trials hollow), the fitted surface's
contours at --contours (default 0.1, 0.5, 0.9) labelled with their probability, both axes
logarithmic and labelled with the measures and units (/fragility_surface's im1_label, im1_units,
im2_label, im2_units). A limit state without a fit says why in its panel. --summary prints each
fit and its median form (ln median1 = c0 + c1 ln im2, beta1) as text.

    /usr/bin/python3 postproc/plots/plot_fragility_surface.py results.h5 -o surface.png
    /usr/bin/python3 postproc/plots/plot_fragility_surface.py results.h5 --limit-state overturn -o o.png
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_support  # noqa: E402  (beside this script; it chooses matplotlib's backend before pyplot)
from plot_support import InputError, text  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import FixedLocator, FuncFormatter, LogLocator, NullFormatter, NullLocator  # noqa: E402

# Beyond this many limit states one panel each is no longer readable: pick one with --limit-state.
MAX_PANELS = 6
FITTED = ("ok", "not_increasing")


def read_surfaces(path):
    """The axes' names and every limit state's grid and fit, as plain numpy values."""
    with plot_support.open_hdf5(path) as f:
        if "fragility_surface" not in f:
            raise InputError(f"{path}: no /fragility_surface (not a study with a second intensity measure)")
        root = f["fragility_surface"]
        try:
            axes = {key: text(root.attrs[key])
                    for key in ("im1_label", "im1_units", "im2_label", "im2_units")}
            states = []
            for name in root:
                group = root[name]
                states.append({
                    "name": name,
                    "im1": group["im1"][()], "im2": group["im2"][()],
                    "probability": group["probability"][()], "trials": group["trials"][()],
                    "status": text(group.attrs["fit_status"]),
                    "coefficients": np.asarray(group.attrs["coefficients"], dtype=float),
                    "standard_errors": np.asarray(group.attrs["standard_errors"], dtype=float),
                    "median": [float(group.attrs[key]) for key in (
                        "ln_median_intercept", "ln_median_intercept_se", "ln_median_slope",
                        "ln_median_slope_se", "beta1", "beta1_se")],
                    "log_likelihood": float(group.attrs["log_likelihood"]),
                    "gof": (float(group.attrs.get("deviance", math.nan)), int(group.attrs.get("gof_dof", 0)),
                            float(group.attrs.get("gof_p_value", math.nan))),
                })
        except KeyError as error:
            raise InputError(f"{path}: /fragility_surface lacks {error.args[0]}") from None
    for state in states:
        shape = (len(state["im1"]), len(state["im2"]))
        if state["probability"].shape != shape or state["trials"].shape != shape:
            raise InputError(f"{path}: /fragility_surface/{state['name']}: probability is not "
                             f"{shape[0]} x {shape[1]}, the grid of im1 by im2")
    return axes, states


def axis_label(label, units):
    return label if units == "1" else f"{label} ({units})"


def fitted_probability(coefficients, x1, x2):
    eta = coefficients[0] + coefficients[1] * np.log(x1) + coefficients[2] * np.log(x2)
    return 0.5 * np.vectorize(math.erfc)(-eta / math.sqrt(2.0))


def draw_panel(ax, axes, state, contours, colours):
    x1, x2 = state["im1"], state["im2"]
    grid1, grid2 = np.meshgrid(x1, x2, indexing="ij")
    has = state["trials"] > 0
    points = ax.scatter(grid1[has], grid2[has], c=state["probability"][has], cmap=colours, vmin=0, vmax=1,
                        s=70, edgecolors="0.25", linewidths=0.6, zorder=3)
    if np.any(~has):
        ax.scatter(grid1[~has], grid2[~has], facecolors="none", edgecolors="0.5", s=70, zorder=3)
    # The fit beyond the outer cells is extrapolation: draw it over the grid's span only.
    pad1, pad2 = (x1[-1] / x1[0]) ** 0.04 if len(x1) > 1 else 1.2, (x2[-1] / x2[0]) ** 0.04 if len(x2) > 1 else 1.2
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(x1[0] / pad1, x1[-1] * pad1)
    ax.set_ylim(x2[0] / pad2, x2[-1] * pad2)
    if state["status"] in FITTED:
        fine1 = np.geomspace(x1[0], x1[-1], 200)
        fine2 = np.geomspace(x2[0], x2[-1], 200)
        f1, f2 = np.meshgrid(fine1, fine2, indexing="ij")
        lines = ax.contour(f1, f2, fitted_probability(state["coefficients"], f1, f2), levels=contours,
                           colors="k", linewidths=1.2, zorder=2)
        ax.clabel(lines, fmt=lambda p: f"P = {p:g}", fontsize=8)
        b0, b1, b2 = state["coefficients"]
        s0, s1, s2 = state["standard_errors"]
        note = (f"P = Φ({b0:.3g} + {b1:.3g} ln x + {b2:.3g} ln y), "
                f"SE {s0:.2g}, {s1:.2g}, {s2:.2g}")
        if state["status"] == "ok":
            c0, _, c1, c1_se, beta, beta_se = state["median"]
            unit = "" if axes["im1_units"] == "1" else f" {axes['im1_units']}"
            note += (f"\nmedian x = {math.exp(c0):.3g}{unit} · (y / 1 {axes['im2_units']})^({c1:.3g} ± {c1_se:.2g}), "
                     f"β = {beta:.3g} ± {beta_se:.2g}")
        else:
            note += "\nfalls with x: no median form"
        deviance, dof, p_value = state["gof"]
        if dof >= 1:
            note += f"\ndeviance {deviance:.3g} on {dof} degrees of freedom, p = {p_value:.2g}"
    else:
        note = f"no fitted surface: {state['status'].replace('_', ' ')}"
    ax.set_title(f"{state['name']}\n{note}", fontsize=8.5)
    ax.set_xlabel(axis_label(axes["im1_label"], axes["im1_units"]))
    ax.set_ylabel(axis_label(axes["im2_label"], axes["im2_units"]))
    # Ticks at the grid's values when they are few enough to read, else at 1, 2, 5 per decade.
    plain = FuncFormatter(lambda v, _: f"{v:g}")
    for axis, values in ((ax.xaxis, x1), (ax.yaxis, x2)):
        axis.set_major_locator(FixedLocator(values) if len(values) <= 8 else LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
        axis.set_major_formatter(plain)
        axis.set_minor_locator(NullLocator())
        axis.set_minor_formatter(NullFormatter())
    return points


def plot(axes, states, contours, title, output):
    columns = min(len(states), 3)
    rows = math.ceil(len(states) / columns)
    fig, panels = plt.subplots(rows, columns, figsize=(5.6 * columns + 1.2, 5.0 * rows + 0.6), squeeze=False,
                               layout="constrained")
    colours = plt.get_cmap("viridis")
    points = None
    for ax, state in zip(panels.flat, states):
        points = draw_panel(ax, axes, state, contours, colours)
    for ax in list(panels.flat)[len(states):]:
        ax.set_visible(False)
    bar = fig.colorbar(points, ax=panels.ravel().tolist(), shrink=0.8)
    bar.set_label("observed probability of exceedance (markers)")
    fig.suptitle(title)
    plot_support.save_figure(fig, output, dpi=150)


def summary(axes, states):
    for state in states:
        print(f"{state['name']}: fit {state['status']}")
        if state["status"] not in FITTED:
            continue
        b, se = state["coefficients"], state["standard_errors"]
        print(f"  P = Phi(b0 + b1 ln {axes['im1_label']} + b2 ln {axes['im2_label']}), "
              f"ln L = {state['log_likelihood']:.6g}")
        for k in range(3):
            print(f"  b{k} = {b[k]:.6g} +- {se[k]:.3g}")
        deviance, dof, p_value = state["gof"]
        if dof >= 1:
            print(f"  deviance {deviance:.6g} on {dof} degrees of freedom, p = {p_value:.3g}"
                  + (": the probit is rejected at 5 %" if p_value < 0.05 else ""))
        if state["status"] == "ok":
            c0, c0_se, c1, c1_se, beta, beta_se = state["median"]
            print(f"  ln median = {c0:.6g} (+- {c0_se:.3g}) + {c1:.6g} (+- {c1_se:.3g}) ln {axes['im2_label']}, "
                  f"beta = {beta:.6g} +- {beta_se:.3g}")


def main(argv=None):
    parser = plot_support.parser(__doc__)
    parser.add_argument("results", help="study output HDF5 file (a surface study's)")
    plot_support.add_output(parser)
    parser.add_argument("--limit-state", metavar="NAME", help="draw only this limit state")
    parser.add_argument("--contours", default="0.1,0.5,0.9",
                        help="probabilities of the fitted contours, comma-separated (default 0.1,0.5,0.9)")
    parser.add_argument("--summary", action="store_true", help="print each fit as text")
    plot_support.add_title(parser)
    args = parser.parse_args(argv)
    try:
        contours = sorted(float(p) for p in args.contours.split(","))
    except ValueError:
        parser.error(f"--contours: expected probabilities like 0.1,0.5,0.9, got {args.contours!r}")
    if not all(0 < p < 1 for p in contours):
        parser.error(f"--contours: every probability must be in (0, 1), got {args.contours!r}")
    if not args.output and not args.summary:
        parser.error("nothing to do: give -o OUT.png, --summary or both")

    def work():
        axes, states = read_surfaces(args.results)
        if args.limit_state is not None:
            known = [state["name"] for state in states]
            if args.limit_state not in known:
                raise InputError(f"--limit-state {args.limit_state}: {args.results} has no such limit state "
                                 f"(it has: {', '.join(known) or 'none'})")
            states = [state for state in states if state["name"] == args.limit_state]
        if not states:
            raise InputError(f"{args.results}: /fragility_surface has no limit state")
        if len(states) > MAX_PANELS and args.output:
            raise InputError(f"{len(states)} limit states are more than the {MAX_PANELS} panels one figure "
                             "can show: pick one with --limit-state")
        if args.summary:
            summary(axes, states)
        if args.output:
            title = args.title or f"Fragility surfaces: {os.path.basename(args.results)}"
            plot(axes, states, contours, title, args.output)

    return plot_support.run(work)


if __name__ == "__main__":
    sys.exit(main())
