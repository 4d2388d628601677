#!/usr/bin/python3
"""Draw a block's motion: its outline at a series of times on the ground, coloured by mode.

Reads the CSV that `blockfrag simulate --history FILE.csv` writes (columns t, x, y, theta, ...,
mode: the centre of mass relative to the ground, m and rad) and the scene it ran (for the block's
shape: a rectangle's half_width/half_height or a polygon's vertices; a study file's scene works
too). Draws about 16 outlines, evenly spaced in the rows, filled with the mode's colour of
plot_history.py and edged in a darker shade, the centre of mass's trail, the ground, and below a
strip of the modes over time with the snapshots' times marked. A scene with a "seat" (a polyline
in the frame of the block's vertices) is drawn in that frame: the seat and the body under it in
place of the flat ground, nothing beyond its ends, and the history's x (the centre of mass's
displacement from its place at rest) added to the block's centroid there. With --gif, also an animated GIF
of the block moving (matplotlib's Pillow writer), real time unless that needs more than
--max-frames frames.

    /usr/bin/python3 postproc/plots/plot_motion.py history.csv scene.json -o motion.png
    /usr/bin/python3 postproc/plots/plot_motion.py history.csv scene.json --gif motion.gif [--fps 20]
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_support  # noqa: E402  (beside this script; it chooses matplotlib's backend before pyplot)
from plot_support import InputError  # noqa: E402
# The same history reader and mode colours as the time-history plot (a sibling script).
from plot_history import MODE_STYLE, read_history  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.animation import FuncAnimation, PillowWriter  # noqa: E402
from matplotlib.patches import Patch, Polygon, Rectangle  # noqa: E402

# The outlines' edges: a darker shade of each mode's fill, so a covered snapshot still shows its mode.
MODE_EDGE = {"rest": "#4d4d4d", "slide": "#2f6fa8", "rock": "#c4661b", "slide_rock": "#7a4a9e",
             "flight": "#3f8a3a"}
REST_FILL = "#ffffff"
# How far the outline may reach below the ground (or float above it while in contact), as a
# fraction of the block's size, before the scene is taken not to be the history's.
FIT_TOLERANCE = 0.02


def fill_colour(mode):
    return MODE_STYLE[mode][0] or REST_FILL


def read_shape(path):
    """The block's outline in body coordinates about its centre of mass, counter-clockwise."""
    return read_scene(path)[0]


def read_scene(path):
    """The block's outline about its centre of mass (as read_shape), and the scene's seat: None on
    flat ground, else (points, centre): the polyline, left to right, and the block's centre of mass
    at rest, both in the frame of the block's vertices (a rectangle's centre is its origin)."""
    try:
        with open(path) as stream:
            scene = json.load(stream)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except OSError as error:
        raise InputError(f"cannot read {path}: {error.strerror}") from error
    except ValueError as error:
        raise InputError(f"{path}: not JSON ({error})") from error
    if isinstance(scene, dict) and isinstance(scene.get("scene"), dict):
        scene = scene["scene"]  # a study file: its base scene
    block = scene.get("block") if isinstance(scene, dict) else None
    if not isinstance(block, dict):
        raise InputError(f"{path}: no /block (is it a blockfrag scene?)")
    if "polygon" in block:
        try:
            vertices = np.asarray(block["polygon"], dtype=float)
        except (TypeError, ValueError) as error:
            raise InputError(f"{path}: /block/polygon is not a list of [x, y] pairs") from error
        if vertices.ndim != 2 or vertices.shape[1] != 2 or len(vertices) < 3 or not np.all(np.isfinite(vertices)):
            raise InputError(f"{path}: /block/polygon is not a list of at least 3 [x, y] pairs")
        x, y = vertices[:, 0], vertices[:, 1]
        x1, y1 = np.roll(x, -1), np.roll(y, -1)
        cross = x * y1 - x1 * y
        area = cross.sum() / 2.0
        if area == 0.0:
            raise InputError(f"{path}: /block/polygon has no area")
        centroid = np.array([((x + x1) * cross).sum(), ((y + y1) * cross).sum()]) / (6.0 * area)
        return vertices - centroid, read_seat(path, scene, centroid)
    try:
        a, b = float(block["half_width"]), float(block["half_height"])
    except (KeyError, TypeError, ValueError) as error:
        raise InputError(f"{path}: /block has neither half_width and half_height nor polygon") from error
    if not (a > 0 and b > 0 and math.isfinite(a) and math.isfinite(b)):
        raise InputError(f"{path}: /block's half_width and half_height must be positive")
    return np.array([[-a, -b], [a, -b], [a, b], [-a, b]]), read_seat(path, scene, np.zeros(2))


def read_seat(path, scene, centre):
    if "seat" not in scene:
        return None
    try:
        points = np.asarray(scene["seat"], dtype=float)
    except (TypeError, ValueError) as error:
        raise InputError(f"{path}: /seat is not a list of [x, y] pairs") from error
    if points.ndim != 2 or points.shape[1] != 2 or len(points) < 2 or not np.all(np.isfinite(points)):
        raise InputError(f"{path}: /seat is not a list of at least 2 [x, y] pairs")
    if np.any(np.diff(points[:, 0]) <= 0):
        raise InputError(f"{path}: /seat's x must increase strictly, left to right")
    return points, centre


def on_seat(data, seat):
    """The history with x in the seat's frame: its x is the centre of mass's displacement from rest."""
    if seat is None:
        return data
    shifted = dict(data)
    shifted["x"] = data["x"] + seat[1][0]
    return shifted


def outline(shape, x, y, theta):
    """World coordinates of the body outline with its centre of mass at (x, y), turned by theta."""
    c, s = math.cos(theta), math.sin(theta)
    return np.column_stack((x + c * shape[:, 0] - s * shape[:, 1], y + s * shape[:, 0] + c * shape[:, 1]))


def point_segment_distance(points, a, b):
    """Distance from each of the points (n x 2) to each segment a[j] -> b[j] (m x 2): n x m."""
    d = b - a
    rel = points[:, None, :] - a[None, :, :]
    u = np.clip(np.sum(rel * d[None], axis=2) / np.sum(d * d, axis=1)[None], 0.0, 1.0)
    return np.hypot(*np.moveaxis(rel - u[..., None] * d[None], 2, 0))


def inside_depth(points, polygon):
    """How far each point lies inside the closed polygon (0 outside): its distance to the outline."""
    x, y = points[:, 0:1], points[:, 1:2]
    x0, y0 = polygon[:, 0][None], polygon[:, 1][None]
    x1, y1 = np.roll(polygon[:, 0], -1)[None], np.roll(polygon[:, 1], -1)[None]
    straddles = (y0 > y) != (y1 > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        crossing_x = x0 + (y - y0) * (x1 - x0) / (y1 - y0)
    inside = np.sum(straddles & (x < crossing_x), axis=1) % 2 == 1
    distance = point_segment_distance(points, polygon, np.roll(polygon, -1, axis=0)).min(axis=1)
    return np.where(inside, distance, 0.0)


def seat_depth_and_gap(corners, points):
    """How deep the block (its outline, corners) reaches into the seat (points), and its distance
    from the seat when it does not. Into the seat: a block vertex below a seat segment under it
    (measured across the segment), or a seat point inside the block."""
    a, b = points[:-1], points[1:]
    depth = 0.0
    for k in range(len(a)):
        over = (corners[:, 0] >= a[k, 0]) & (corners[:, 0] <= b[k, 0])
        if over.any():
            d = b[k] - a[k]
            # The height over the segment's line, across it: the cross product with its direction.
            height = (d[0] * (corners[over, 1] - a[k, 1]) - d[1] * (corners[over, 0] - a[k, 0])) / np.hypot(*d)
            depth = max(depth, float(-height.min()))
    depth = max(depth, float(inside_depth(points, corners).max()))
    gap = min(float(point_segment_distance(corners, a, b).min()),
              float(point_segment_distance(points, corners, np.roll(corners, -1, axis=0)).min()))
    return depth, gap


def check_fit(shape, data, history, scene, seat=None):
    """Refuse a scene whose block does not stand on the ground of this history (with a seat, data's
    x in the seat's frame: on_seat)."""
    if seat is not None:
        check_seat_fit(shape, data, history, scene, seat[0])
        return
    size = float(np.max(np.hypot(shape[:, 0], shape[:, 1])))
    lowest = np.array([outline(shape, x, y, th)[:, 1].min() for x, y, th in zip(data["x"], data["y"], data["theta"])])
    tolerance = FIT_TOLERANCE * size
    below = int(np.argmin(lowest))
    if lowest[below] < -tolerance:
        raise InputError(f"the block of {scene} would reach {-lowest[below]:.3g} m below the ground at "
                         f"t = {data['t'][below]:.3g} s of {history}: is this the scene of that history?")
    touching = data["mode"] != "flight"
    if touching.any():
        gap = np.where(touching, lowest, -np.inf)
        above = int(np.argmax(gap))
        if gap[above] > tolerance:
            raise InputError(f"the block of {scene} would float {gap[above]:.3g} m above the ground at "
                             f"t = {data['t'][above]:.3g} s of {history} ({data['mode'][above]}): "
                             f"is this the scene of that history?")


def check_seat_fit(shape, data, history, scene, points):
    size = float(np.max(np.hypot(shape[:, 0], shape[:, 1])))
    tolerance = FIT_TOLERANCE * size
    fits = [seat_depth_and_gap(outline(shape, x, y, th), points)
            for x, y, th in zip(data["x"], data["y"], data["theta"])]
    depth = np.array([f[0] for f in fits])
    gap = np.array([f[1] for f in fits])
    deepest = int(np.argmax(depth))
    if depth[deepest] > tolerance:
        raise InputError(f"the block of {scene} would reach {depth[deepest]:.3g} m into the seat at "
                         f"t = {data['t'][deepest]:.3g} s of {history}: is this the scene of that history?")
    touching = data["mode"] != "flight"
    if touching.any():
        gap = np.where(touching & (depth == 0.0), gap, -np.inf)
        above = int(np.argmax(gap))
        if gap[above] > tolerance:
            raise InputError(f"the block of {scene} would float {gap[above]:.3g} m off the seat at "
                             f"t = {data['t'][above]:.3g} s of {history} ({data['mode'][above]}): "
                             f"is this the scene of that history?")


def extent(shape, data, seat=None):
    corners = np.vstack([outline(shape, x, y, th) for x, y, th in zip(data["x"], data["y"], data["theta"])])
    size = float(np.max(np.hypot(shape[:, 0], shape[:, 1])))
    margin = 0.12 * size
    if seat is None:
        return (corners[:, 0].min() - margin, corners[:, 0].max() + margin,
                min(0.0, corners[:, 1].min()) - margin, corners[:, 1].max() + margin)
    # The seat in view: all of it that lies within the block's reach, with a margin of body under it.
    points = seat[0]
    x_low, x_high = corners[:, 0].min() - margin, corners[:, 0].max() + margin
    seen = points[(points[:, 0] >= x_low) & (points[:, 0] <= x_high)]
    seat_low = min(np.interp([x_low, x_high], points[:, 0], points[:, 1]).min(),
                   seen[:, 1].min() if len(seen) else np.inf)
    return (x_low, x_high, min(seat_low - 0.25 * size, corners[:, 1].min() - margin),
            corners[:, 1].max() + margin)


def draw_ground(ax, x_low, x_high, depth, seat=None):
    if seat is not None:
        draw_seat(ax, seat[0], -depth)
        return
    ax.add_patch(Rectangle((x_low, -depth), x_high - x_low, depth, facecolor="0.93", edgecolor="0.6",
                           hatch="////", linewidth=0, zorder=0))
    ax.axhline(0.0, color="0.15", linewidth=1.2, zorder=1)


SEAT_FILL = "#ddd6c8"  # the body under a seat (concrete), hatched like the flat ground
SEAT_LINE = "#3b3b3b"


def draw_seat(ax, points, bottom):
    """The seat's polyline over the body under it, which ends with the seat (no ground beyond)."""
    body = np.vstack(([points[0, 0], bottom], points, [points[-1, 0], bottom]))
    ax.add_patch(Polygon(body, closed=True, facecolor=SEAT_FILL, edgecolor="0.6", hatch="////", linewidth=0,
                         zorder=0))
    ax.plot(points[:, 0], points[:, 1], color=SEAT_LINE, linewidth=1.6, solid_capstyle="butt", zorder=1)
    ax.plot([points[0, 0], points[0, 0]], [bottom, points[0, 1]], color=SEAT_LINE, linewidth=0.9, zorder=1)
    ax.plot([points[-1, 0], points[-1, 0]], [bottom, points[-1, 1]], color=SEAT_LINE, linewidth=0.9, zorder=1)


def snapshot_rows(count, wanted):
    """About `wanted` rows evenly spread over the history, the first and the last among them."""
    return np.unique(np.linspace(0, count - 1, min(wanted, count)).round().astype(int))


def mode_legend(modes):
    present = [m for m in MODE_STYLE if np.any(modes == m)]
    return [Patch(facecolor=fill_colour(m), edgecolor=MODE_EDGE[m], linewidth=1.0, label=MODE_STYLE[m][1])
            for m in present]


def plot(data, shape, title, output, wanted, seat=None, ax=None, strip=None):
    """The snapshots (with a seat: data's x in the seat's frame, on_seat). Given the two axes, draws
    into them (one panel of a larger figure) and leaves the figure to the caller."""
    rows = snapshot_rows(len(data["t"]), wanted)
    x_low, x_high, y_low, y_high = extent(shape, data, seat)
    width = 9.0
    height = min(7.0, max(2.2, width * 0.86 * (y_high - y_low) / (x_high - x_low)))
    own = ax is None
    if own:
        fig, (ax, strip) = plt.subplots(2, 1, figsize=(width, height + 1.9),
                                        gridspec_kw={"height_ratios": [height, 0.45]})

    draw_ground(ax, x_low, x_high, -y_low, seat)
    for order, i in enumerate(rows):
        mode = data["mode"][i]
        corners = outline(shape, data["x"][i], data["y"][i], data["theta"][i])
        last = order == len(rows) - 1
        ax.add_patch(Polygon(corners, closed=True, facecolor=fill_colour(mode), edgecolor=MODE_EDGE[mode],
                             linewidth=2.2 if last else 1.1, zorder=3 + order))
    # The centre of mass's path over the outlines, its place at each snapshot a dot.
    top_layer = 5 + len(rows)
    ax.plot(data["x"], data["y"], color="0.35", linewidth=0.8, zorder=top_layer)
    ax.plot(data["x"][rows], data["y"][rows], "o", color="0.2", markersize=2.2, zorder=top_layer)
    # The start on top of everything, dashed: later outlines often cover it.
    start = outline(shape, data["x"][0], data["y"][0], data["theta"][0])
    ax.add_patch(Polygon(start, closed=True, fill=False, edgecolor="0.15", linestyle="--", linewidth=0.9,
                         zorder=4 + len(rows)))
    ax.set_xlim(x_low, x_high)
    ax.set_ylim(y_low, y_high + 0.08 * (y_high - y_low))
    ax.set_aspect("equal")
    ax.set_xlabel("x relative to the ground [m]" if seat is None else "x relative to the seat [m]")
    ax.set_ylabel("height [m]")
    handles = mode_legend(data["mode"]) + [
        plt.Line2D([], [], color="0.35", linewidth=0.8, marker="o", markersize=2.2, label="centre of mass"),
        plt.Line2D([], [], color="0.15", linewidth=0.9, linestyle="--", label=f"start (t = {data['t'][0]:.3g} s)"),
        plt.Line2D([], [], color=MODE_EDGE[data["mode"][rows[-1]]], linewidth=2.2,
                   label=f"last (t = {data['t'][rows[-1]]:.3g} s)")]
    ax.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=min(len(handles), 4),
              frameon=False, fontsize=8.5, handlelength=1.5, borderaxespad=0.2, columnspacing=1.2)
    spacing = (data["t"][rows[-1]] - data["t"][rows[0]]) / max(1, len(rows) - 1)

    # The modes over time, with the snapshots' times: which outline is when.
    t = data["t"]
    for mode in MODE_STYLE:
        mask = data["mode"] == mode
        if mask.any():
            held = mask | np.concatenate(([False], mask[:-1]))
            strip.fill_between(t, 0, 1, where=held, step="post", color=fill_colour(mode), linewidth=0)
    strip.vlines(t[rows], 0, 1, color="0.15", linewidth=0.8)
    strip.set_xlim(t[0], t[-1] if t[-1] > t[0] else t[0] + 1.0)
    strip.set_ylim(0, 1)
    strip.set_yticks([])
    strip.set_xlabel(f"time t [s]; lines: the {len(rows)} snapshots, about {spacing:.2g} s apart")
    for side in ("top", "right", "left"):
        strip.spines[side].set_visible(False)

    if not own:
        # Inside the panel, at its top: above it the legend takes the room.
        ax.text(0.5, 0.985, title, transform=ax.transAxes, ha="center", va="top", fontsize=10.5)
        return
    fig.suptitle(title, fontsize=12)
    fig.tight_layout()
    plot_support.save_figure(fig, output, dpi=150)


def animate(data, shape, title, output, fps, max_frames, seat=None):
    t = data["t"]
    duration = float(t[-1] - t[0])
    frames = max(2, min(max_frames, int(math.ceil(duration * fps)) + 1))
    times = np.linspace(t[0], t[-1], frames)
    speed = duration / ((frames - 1) / fps) if frames > 1 and duration > 0 else 1.0
    x = np.interp(times, t, data["x"])
    y = np.interp(times, t, data["y"])
    theta = np.interp(times, t, data["theta"])
    # The mode of the row in force at each frame's time.
    modes = data["mode"][np.clip(np.searchsorted(t, times, side="right") - 1, 0, len(t) - 1)]
    hold = int(round(fps))  # the last picture stays a second before the loop restarts

    x_low, x_high, y_low, y_high = extent(shape, data, seat)
    height = min(5.0, max(2.4, 6.4 * 0.86 * (y_high - y_low) / (x_high - x_low)))
    fig, ax = plt.subplots(figsize=(6.4, height + 0.9))
    draw_ground(ax, x_low, x_high, -y_low, seat)
    ax.set_xlim(x_low, x_high)
    ax.set_ylim(y_low, y_high + 0.08 * (y_high - y_low))
    ax.set_aspect("equal")
    ax.set_xlabel("x relative to the ground [m]" if seat is None else "x relative to the seat [m]", fontsize=8)
    ax.tick_params(labelsize=7)
    trail, = ax.plot([], [], color="0.35", linewidth=0.8, zorder=4)
    block = Polygon(outline(shape, x[0], y[0], theta[0]), closed=True, linewidth=1.2, zorder=3)
    ax.add_patch(block)
    label = ax.set_title("", fontsize=9, loc="left")
    ax.set_title(title + (f" ({speed:.2g}x speed)" if abs(speed - 1.0) > 0.01 else ""), fontsize=8, loc="right",
                 color="0.35")
    fig.tight_layout()

    def draw(frame):
        k = min(frame, frames - 1)
        block.set_xy(outline(shape, x[k], y[k], theta[k]))
        block.set_facecolor(fill_colour(modes[k]))
        block.set_edgecolor(MODE_EDGE[modes[k]])
        shown = t <= times[k]
        trail.set_data(data["x"][shown], data["y"][shown])
        label.set_text(f"t = {times[k]:.2f} s   {MODE_STYLE[modes[k]][1]}")
        return block, trail, label

    animation = FuncAnimation(fig, draw, frames=frames + hold, blit=False)
    try:
        with plot_support.writing(output):
            animation.save(output, writer=PillowWriter(fps=fps), dpi=90)
    finally:
        plt.close(fig)


def main(argv=None):
    parser = plot_support.parser(__doc__)
    parser.add_argument("history", help="time history CSV from blockfrag simulate --history")
    parser.add_argument("scene", help="the scene JSON the history ran (or a study file: its scene)")
    parser.add_argument("-o", "--output", help="PNG file to write: the snapshots")
    parser.add_argument("--gif", metavar="OUT.gif", help="animated GIF to write")
    parser.add_argument("--snapshots", type=int, default=16, help="outlines on the PNG (default 16)")
    parser.add_argument("--fps", type=int, default=20, help="GIF frames per second (default 20)")
    parser.add_argument("--max-frames", type=int, default=300,
                        help="at most this many GIF frames; a longer motion plays faster (default 300)")
    plot_support.add_title(parser, "the CSV's file name")
    args = parser.parse_args(argv)
    if not args.output and not args.gif:
        parser.error("nothing to do: give -o OUT.png, --gif OUT.gif or both")
    if args.snapshots < 2 or args.fps < 1 or args.max_frames < 2:
        parser.error("--snapshots and --max-frames must be at least 2, --fps at least 1")

    def work():
        data = read_history(args.history)
        for column in ("t", "x", "y", "theta"):
            if not np.all(np.isfinite(data[column])):
                raise InputError(f"{args.history}: column {column} holds NaN or infinity")
        if np.any(np.diff(data["t"]) < 0):
            raise InputError(f"{args.history}: time goes backwards")
        shape, seat = read_scene(args.scene)
        data = on_seat(data, seat)
        check_fit(shape, data, args.history, args.scene, seat)
        title = args.title or f"Motion: {os.path.basename(args.history)}"
        if args.output:
            plot(data, shape, title, args.output, args.snapshots, seat)
        if args.gif:
            animate(data, shape, args.title or os.path.basename(args.history), args.gif, args.fps, args.max_frames,
                    seat)

    return plot_support.run(work)


if __name__ == "__main__":
    sys.exit(main())
