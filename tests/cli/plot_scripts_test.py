"""postproc's plot scripts end to end on small synthetic inputs written here.

plot_history.py: a PNG of plausible size whose background shows the colours of the modes present
and not of the modes absent; one-line errors (no traceback, non-zero exit) for a missing file, a
missing column and an unknown mode. plot_fragility.py: a PNG showing each limit state's colour,
a --summary table with the file's numbers, one-line errors for a missing file, a file that is not
HDF5 and one without /fragility. Prints "N passed, M failed" last; exits non-zero on any failure.
"""

import math
import os
import struct
import subprocess
import sys
import tempfile
import traceback
from pathlib import Path

import h5py
import matplotlib.image
import numpy as np

SOURCE = Path(os.environ.get("BLOCKFRAG_SOURCE_DIR", Path(__file__).resolve().parents[2]))
PLOT_HISTORY = SOURCE / "postproc" / "plots" / "plot_history.py"
PLOT_FRAGILITY = SOURCE / "postproc" / "plots" / "plot_fragility.py"

# Colours the scripts promise: the mode shading of plot_history.py and the first two limit-state
# colours of plot_fragility.py.
ROCK, FLIGHT, SLIDE, SLIDE_ROCK = "#fde3c8", "#d5ecd4", "#cfe2f3", "#e4d3ef"
FIRST_STATE, SECOND_STATE = "#0072B2", "#D55E00"


def run(*args):
    return subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True, timeout=120)


def png_size(path):
    """(width, height) from the IHDR chunk; fails unless the file is a PNG."""
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    assert data[12:16] == b"IHDR"
    return struct.unpack(">II", data[16:24])


def colour_pixels(pixels, hex_colour, tolerance=2.0 / 255.0):
    rgb = np.array([int(hex_colour[i:i + 2], 16) / 255.0 for i in (1, 3, 5)])
    return int(np.sum(np.all(np.abs(pixels[..., :3] - rgb) <= tolerance, axis=-1)))


def check_plausible_png(path):
    width, height = png_size(path)
    assert 800 <= width <= 4000 and 600 <= height <= 4000, f"odd size {width} x {height}"
    pixels = matplotlib.image.imread(path)
    ink = np.mean(pixels[..., :3] @ np.array([0.299, 0.587, 0.114]) < 0.6)
    # Axes, labels and curves darken a few percent of a figure (the pale mode shading does not
    # count); a blank or broken one darkens nearly nothing, a solid block nearly everything.
    assert 0.01 < ink < 0.3, f"{path}: {ink:.3f} of the pixels are dark"
    return pixels


def assert_clean_error(result, *fragments):
    assert result.returncode != 0, "exit code 0 on bad input"
    assert "Traceback" not in result.stderr, f"a traceback instead of a message:\n{result.stderr}"
    for fragment in fragments:
        assert fragment in result.stderr, f"stderr lacks {fragment!r}: {result.stderr!r}"
    assert len(result.stderr.strip().splitlines()) <= 3, f"a long error:\n{result.stderr}"


def write_history(path, modes=None, drop=None):
    """A block that rocks, flies and lands rocking again, with a free-rocking-like theta."""
    t = np.linspace(0.0, 3.0, 601)
    theta = -0.3 * np.sin(2.0 * np.pi * t / 3.0) * np.exp(-0.3 * t)
    mode = modes or ["rock" if (ti < 1.2 or ti > 1.5) else "flight" for ti in t]
    columns = ["t", "x", "y", "theta", "vx", "vy", "omega", "mode", "friction_per_weight", "normal_per_weight"]
    if drop:
        columns.remove(drop)
    with open(path, "w") as out:
        out.write(",".join(columns) + "\n")
        for i, ti in enumerate(t):
            flying = mode[i] == "flight"
            row = {"t": ti, "x": 0.01 * ti, "y": 1.0, "theta": theta[i], "vx": 0.01, "vy": 0.0,
                   "omega": 0.0, "mode": mode[i], "friction_per_weight": 0.0 if flying else 0.2 * math.cos(ti),
                   "normal_per_weight": 0.0 if flying else 1.0 + 0.1 * math.sin(3 * ti)}
            out.write(",".join(str(row[c]) for c in columns) + "\n")


def write_study(path, with_fragility=True, with_names=True):
    with h5py.File(path, "w") as f:
        f.attrs["config_hash"] = "synthetic"
        if not with_fragility:
            f.create_group("results").create_dataset("status", data=np.zeros(4, dtype=np.int64))
            return
        group = f.create_group("fragility")
        if with_names:
            group.attrs["im_name"] = "pulse_amplitude"
            group.attrs["im_units"] = "g"
        # Baker's check data with its fit, plus a level without trials.
        im = [0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2]
        trials = [40, 40, 40, 40, 40, 40, 40, 40, 0]
        exceed = [0, 0, 3, 4, 6, 13, 12, 16, 0]
        state = group.create_group("overturn")
        fill(state, im, trials, exceed)
        state.attrs.update({"median": 1.076116, "beta": 0.429237, "log_likelihood": -10.797705,
                            "fit_status": "ok", "type": "overturning", "threshold": 0.0,
                            "interval": "Wilson score, 95 %"})
        # Separated data: no fit, NaN attributes, the median bracketed.
        state = group.create_group("slide_5cm")
        fill(state, im, trials, [0, 0, 0, 0, 40, 40, 40, 40, 0])
        state.attrs.update({"median": math.nan, "beta": math.nan, "log_likelihood": 0.0,
                            "fit_status": "separated", "median_low": 0.6, "median_high": 0.7,
                            "type": "residual_slide", "threshold": 0.05, "interval": "Wilson score, 95 %"})


def fill(group, im, trials, exceed):
    n, z = np.array(trials, dtype=np.int64), np.array(exceed, dtype=np.int64)
    with np.errstate(invalid="ignore", divide="ignore"):
        p = np.where(n > 0, z / np.maximum(n, 1), np.nan)
    group.create_dataset("im", data=np.array(im))
    group.create_dataset("trials", data=n)
    group.create_dataset("exceedances", data=z)
    group.create_dataset("probability", data=p)
    group.create_dataset("ci_low", data=np.where(n > 0, np.clip(p - 0.1, 0, 1), np.nan))
    group.create_dataset("ci_high", data=np.where(n > 0, np.clip(p + 0.1, 0, 1), np.nan))


# --- plot_history.py ----------------------------------------------------------------------------------

def test_history_plot_shows_the_modes_present(work):
    write_history(work / "h.csv")
    result = run(PLOT_HISTORY, work / "h.csv", "-o", work / "h.png")
    assert result.returncode == 0, result.stderr
    pixels = check_plausible_png(work / "h.png")
    assert colour_pixels(pixels, ROCK) > 10000, "no rock shading"
    assert colour_pixels(pixels, FLIGHT) > 2000, "no flight shading"
    assert colour_pixels(pixels, SLIDE) == 0, "slide shading without any sliding"
    assert colour_pixels(pixels, SLIDE_ROCK) == 0, "slide-rock shading without any"


def test_history_plot_refuses_a_missing_file(work):
    assert_clean_error(run(PLOT_HISTORY, work / "absent.csv", "-o", work / "x.png"), "absent.csv")
    assert not (work / "x.png").exists()


def test_history_plot_names_a_missing_column(work):
    write_history(work / "h.csv", drop="normal_per_weight")
    assert_clean_error(run(PLOT_HISTORY, work / "h.csv", "-o", work / "x.png"), "normal_per_weight")


def test_history_plot_refuses_an_unknown_mode(work):
    write_history(work / "h.csv", modes=["rock"] * 300 + ["tumbling"] * 301)
    assert_clean_error(run(PLOT_HISTORY, work / "h.csv", "-o", work / "x.png"), "tumbling")


def test_history_plot_reports_an_unwritable_output(work):
    write_history(work / "h.csv")
    assert_clean_error(run(PLOT_HISTORY, work / "h.csv", "-o", work / "no_dir" / "x.png"), "cannot write")


# --- plot_fragility.py --------------------------------------------------------------------------------

def test_fragility_plot_shows_every_limit_state(work):
    write_study(work / "s.h5")
    result = run(PLOT_FRAGILITY, work / "s.h5", "-o", work / "f.png")
    assert result.returncode == 0, result.stderr
    pixels = check_plausible_png(work / "f.png")
    assert colour_pixels(pixels, FIRST_STATE) > 500, "the first limit state is not drawn"
    assert colour_pixels(pixels, SECOND_STATE) > 100, "the second limit state is not drawn"


def test_fragility_plot_without_axis_names(work):
    write_study(work / "s.h5", with_names=False)
    result = run(PLOT_FRAGILITY, work / "s.h5", "-o", work / "f.png")
    assert result.returncode == 0, result.stderr
    check_plausible_png(work / "f.png")


def test_fragility_summary_prints_the_tables(work):
    write_study(work / "s.h5")
    result = run(PLOT_FRAGILITY, work / "s.h5", "--summary")
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "overturn" in out and "slide_5cm" in out
    assert "median = 1.07612 g" in out and "beta = 0.429237" in out, out
    assert "none (separated)" in out and "[0.6, 0.7]" in out, out
    rows = [line.split() for line in out.splitlines()]
    assert ["0.4", "40", "3", "0.0750", "0.0000", "0.1750"] in rows, out
    assert ["1.2", "0", "0", "-", "-", "-"] in rows, out  # the level without trials
    assert ["0.7", "40", "40", "1.0000", "0.9000", "1.0000"] in rows, out
    assert not (work / "f.png").exists()


def test_fragility_plot_refuses_a_missing_file(work):
    assert_clean_error(run(PLOT_FRAGILITY, work / "absent.h5", "-o", work / "f.png"), "absent.h5")


def test_fragility_plot_refuses_a_file_that_is_not_hdf5(work):
    write_history(work / "h.csv")
    assert_clean_error(run(PLOT_FRAGILITY, work / "h.csv", "--summary"), "h.csv")


def test_fragility_plot_refuses_a_file_without_fragility(work):
    write_study(work / "s.h5", with_fragility=False)
    assert_clean_error(run(PLOT_FRAGILITY, work / "s.h5", "-o", work / "f.png"), "/fragility")
    assert not (work / "f.png").exists()


def test_fragility_plot_needs_something_to_do(work):
    write_study(work / "s.h5")
    result = run(PLOT_FRAGILITY, work / "s.h5")
    assert result.returncode == 2 and "nothing to do" in result.stderr, result.stderr


def main():
    tests = [(name, f) for name, f in globals().items() if name.startswith("test_") and callable(f)]
    passed = failed = 0
    for name, test in tests:
        with tempfile.TemporaryDirectory() as directory:
            try:
                test(Path(directory))
                passed += 1
            except Exception:  # noqa: BLE001  (any failure of one test is reported, the rest still run)
                failed += 1
                print(f"FAIL: {name}\n{traceback.format_exc()}", file=sys.stderr)
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
