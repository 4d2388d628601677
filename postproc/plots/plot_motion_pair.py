#!/usr/bin/python3
"""Draw several blocks' motions side by side: plot_motion.py's snapshots, one panel each.

Takes pairs HISTORY.csv SCENE.json (as plot_motion.py does, a seat's scene drawn on its seat) and
checks each history against its scene the same way; one title per panel with --titles.

    /usr/bin/python3 postproc/plots/plot_motion_pair.py h1.csv s1.json h2.csv s2.json -o both.png \\
        [--titles "forward" "reversed"] [--suptitle TEXT] [--snapshots 12]
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_support  # noqa: E402  (beside this script; it chooses matplotlib's backend before pyplot)
from plot_support import InputError  # noqa: E402
from plot_history import read_history  # noqa: E402
from plot_motion import check_fit, on_seat, plot, read_scene  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(argv=None):
    parser = plot_support.parser(__doc__)
    parser.add_argument("pairs", nargs="+", metavar="HISTORY SCENE",
                        help="time history CSV and the scene JSON it ran, for each panel")
    plot_support.add_output(parser, required=True)
    parser.add_argument("--titles", nargs="+", help="one title per panel (default: the CSVs' names)")
    parser.add_argument("--suptitle", help="a title over the panels")
    parser.add_argument("--snapshots", type=int, default=12, help="outlines per panel (default 12)")
    args = parser.parse_args(argv)
    if len(args.pairs) % 2:
        parser.error("give HISTORY SCENE pairs: an even number of files")
    panels = len(args.pairs) // 2
    titles = args.titles or [os.path.basename(h) for h in args.pairs[::2]]
    if len(titles) != panels:
        parser.error(f"--titles: {panels} panels, {len(titles)} titles")
    if args.snapshots < 2:
        parser.error("--snapshots must be at least 2")

    def work():
        runs = []
        for history, scene in zip(args.pairs[::2], args.pairs[1::2]):
            data = read_history(history)
            for column in ("t", "x", "y", "theta"):
                if not np.all(np.isfinite(data[column])):
                    raise InputError(f"{history}: column {column} holds NaN or infinity")
            shape, seat = read_scene(scene)
            data = on_seat(data, seat)
            check_fit(shape, data, history, scene, seat)
            runs.append((data, shape, seat))
        fig, axes = plt.subplots(2, panels, figsize=(6.2 * panels, 9.6), squeeze=False,
                                 gridspec_kw={"height_ratios": [7.0, 0.45]})
        for k, ((data, shape, seat), title) in enumerate(zip(runs, titles)):
            plot(data, shape, title, None, args.snapshots, seat, ax=axes[0][k], strip=axes[1][k])
        if args.suptitle:
            fig.suptitle(args.suptitle, fontsize=12)
        fig.tight_layout()
        plot_support.save_figure(fig, args.output, dpi=130)

    return plot_support.run(work)


if __name__ == "__main__":
    sys.exit(main())
