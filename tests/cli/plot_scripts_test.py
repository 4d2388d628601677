"""postproc's plot scripts end to end on small synthetic inputs written here.

plot_history.py: a PNG of plausible size whose background shows the colours of the modes present
and not of the modes absent; one-line errors (no traceback, non-zero exit) for a missing file, a
missing column and an unknown mode. plot_fragility.py: a PNG showing each limit state's colour,
the bootstrap band's light colour when the file has the band and not when it has none, a legend
and a --summary with the goodness of fit (deviance, p-value, the rejection and the largest
|observed - fitted|, recomputed here) and the limit states by severity, a --summary table with the
file's numbers, one-line errors for a missing file, a file that is not HDF5, one without
/fragility and a band without its upper edge. plot_cloud.py: a PNG with the three verdict
colours, the verdict counts that alpha = atan(a/b) (sampled or the config's; a polygon's easier
corner) gives, one colour pair with --limit-state, panels by record, one-line errors.
plot_motion.py: a PNG showing the colours of the modes present and not of the absent one, an
animated GIF of several distinct frames, a polygon given in another frame drawn like the
rectangle, a one-line error for a scene that is not the history's; on a seat, the seat drawn (and
no seat on the flat ground), a block that sinks into the seat or floats off it while touching
refused, one that falls past the seat's end accepted. plot_motion_pair.py: two panels side by
side, the seat drawn, each history checked against its scene. plot_fragility_pair.py: both studies'
colours, a panel per limit state both have; with --kinds a panel per kind in the order asked, each
kind's limit states by threshold, a kind one study lacks kept (the dry study's post-earthquake
panel); one-line errors for studies that measure intensity differently and a kind neither has;
exit code 2 for an unknown or missing kind. plot_spectrum.py: a PNG showing
the colours of the verdicts present (a safe island's among them) and not of those absent, the
islands found as connected cells above an overturning point, boundary lines that join neighbouring
crossings and not distant ones, one-line errors for a missing file, a file that is not a spectrum
and a bad --mark-point. plot_fragility_surface.py: a PNG with one panel per limit state whose
markers take the colour map's colours of the cells' probabilities, fitted contours through the
points where the file's coefficients give P = 0.5, a --summary with the file's coefficients and
median form, a panel for a limit state without a fit, one-line errors for a file without
/fragility_surface, an unknown --limit-state and bad --contours. plot_work_precision.py: a PNG
from a synthetic accuracy output, one-line errors naming the file and the dataset or group it
lacks. plot_risk.py: a PNG with each limit state's colour, its integrand each bin's lambda per
unit of ln im, one-line errors for a missing file, a JSON that is not a risk.json, a hazard
curve of one level and a limit state whose estimate or points are damaged (named by their JSON
path), and exit code 1 for an output it cannot write. Every error on an input exits 2, one on an output 1
(postproc/plots/plot_support.py). Prints "N passed, M failed" last; exits non-zero on any
failure.
"""

import math
import os
import struct
import subprocess
import sys
import tempfile
import traceback
from pathlib import Path

import contextlib
import importlib.util
import io
import json

import h5py
import matplotlib.image
import numpy as np
from PIL import Image

SOURCE = Path(os.environ.get("BLOCKFRAG_SOURCE_DIR", Path(__file__).resolve().parents[2]))
PLOT_HISTORY = SOURCE / "postproc" / "plots" / "plot_history.py"
PLOT_FRAGILITY = SOURCE / "postproc" / "plots" / "plot_fragility.py"
PLOT_CLOUD = SOURCE / "postproc" / "plots" / "plot_cloud.py"
PLOT_MOTION = SOURCE / "postproc" / "plots" / "plot_motion.py"
PLOT_MOTION_PAIR = SOURCE / "postproc" / "plots" / "plot_motion_pair.py"
PLOT_FRAGILITY_PAIR = SOURCE / "postproc" / "plots" / "plot_fragility_pair.py"
PLOT_SPECTRUM = SOURCE / "postproc" / "plots" / "plot_spectrum.py"
PLOT_SURFACE = SOURCE / "postproc" / "plots" / "plot_fragility_surface.py"
PLOT_WORK_PRECISION = SOURCE / "postproc" / "plots" / "plot_work_precision.py"
PLOT_RISK = SOURCE / "postproc" / "plots" / "plot_risk.py"

# Colours the scripts promise: the mode shading of plot_history.py and the first two limit-state
# colours of plot_fragility.py.
ROCK, FLIGHT, SLIDE, SLIDE_ROCK = "#fde3c8", "#d5ecd4", "#cfe2f3", "#e4d3ef"
FIRST_STATE, SECOND_STATE = "#0072B2", "#D55E00"
# plot_fragility_pair.py's two studies.
FIRST_STUDY, SECOND_STUDY = "#1f77b4", "#d62728"
# plot_cloud.py's verdicts; plot_motion.py's outline edges of a rocking block.
OVERTURNED, EXCEEDED, BELOW = "#D55E00", "#E69F00", "#0072B2"
ROCK_EDGE = "#c4661b"
# plot_motion.py's body under a seat.
SEAT_FILL = "#ddd6c8"


def blend(hex_colour, alpha):
    """The colour a fill of this opacity takes over white."""
    rgb = [int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)]
    return "#" + "".join(f"{round(255 - alpha * (255 - c)):02x}" for c in rgb)


# plot_fragility.py's bootstrap band: the curve's colour at opacity 0.2 over white.
SECOND_BAND = blend(SECOND_STATE, 0.2)


MODULES = {}


def load(script):
    """A plot script as a module (loaded once), to check what it computes without drawing."""
    if script not in MODULES:
        spec = importlib.util.spec_from_file_location(script.stem, script)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        MODULES[script] = module
    return MODULES[script]


def call(script, *args):
    """The script's main() in this process, like run() but without starting Python and importing
    matplotlib again (most of a run's time). An exception main() lets out fails the test, as a
    traceback would; argparse's errors exit, and their code is the run's."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = load(script).main([str(a) for a in args])
        except SystemExit as exit_request:
            code = exit_request.code
    return subprocess.CompletedProcess(args, code, out.getvalue(), err.getvalue())


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


def check_plausible_png(path, min_height=600):
    width, height = png_size(path)
    assert 800 <= width <= 4000 and min_height <= height <= 4000, f"odd size {width} x {height}"
    pixels = matplotlib.image.imread(path)
    ink = np.mean(pixels[..., :3] @ np.array([0.299, 0.587, 0.114]) < 0.6)
    # Axes, labels and curves darken a few percent of a figure (the pale mode shading does not
    # count); a blank or broken one darkens nearly nothing, a solid block nearly everything.
    assert 0.01 < ink < 0.3, f"{path}: {ink:.3f} of the pixels are dark"
    return pixels


def assert_clean_error(result, *fragments, code=2):
    """One short line on stderr holding each fragment, and exit code `code`: 2 for bad input, 1 for
    an output that cannot be written."""
    assert result.returncode == code, f"exit code {result.returncode}, not {code}: {result.stderr!r}"
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


BAKER_IM = [0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2]
BAKER_TRIALS = [40, 40, 40, 40, 40, 40, 40, 40, 0]
BAKER_EXCEED = [0, 0, 3, 4, 6, 13, 12, 16, 0]
BAKER_MEDIAN, BAKER_BETA = 1.076116, 0.429237


def write_study(path, with_fragility=True, with_names=True, diagnostics=False, band=True):
    """Baker's check data with its fit, and separated data; with diagnostics the attributes of the
    bootstrap and the goodness of fit, the limit states ranked by severity, and (with band) the
    overturning curve's bootstrap band."""
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
        im, trials = BAKER_IM, BAKER_TRIALS
        state = group.create_group("overturn")
        fill(state, im, trials, BAKER_EXCEED)
        state.attrs.update({"median": BAKER_MEDIAN, "beta": BAKER_BETA, "log_likelihood": -10.797705,
                            "fit_status": "ok", "type": "overturning", "threshold": 0.0,
                            "interval": "Wilson score, 95 %"})
        # Separated data: no fit, NaN attributes, the median bracketed.
        state = group.create_group("slide_5cm")
        fill(state, im, trials, [0, 0, 0, 0, 40, 40, 40, 40, 0])
        state.attrs.update({"median": math.nan, "beta": math.nan, "log_likelihood": 0.0,
                            "fit_status": "separated", "median_low": 0.6, "median_high": 0.7,
                            "type": "residual_slide", "threshold": 0.05, "interval": "Wilson score, 95 %"})
        if diagnostics:
            group.attrs.update({"severity_order": "slide_5cm,overturn", "scaling": "stripes",
                                "im_label": "pulse amplitude"})
            state = group["overturn"]
            state.attrs.update({"median_ci": np.array([0.93, 1.31]), "beta_ci": np.array([0.31, 0.58]),
                                "deviance": 15.2, "gof_p_value": 0.0188, "gof_dof": np.int64(6),
                                "severity_rank": np.int64(2), "crosses": "slide_5cm"})
            if band:
                x = np.linspace(0.006, 1.32, 200)
                state.create_dataset("band_im", data=x)
                state.create_dataset("band_low", data=[lognormal(v, 1.2, 0.5) for v in x])
                state.create_dataset("band_high", data=[lognormal(v, 0.95, 0.38) for v in x])
            group["slide_5cm"].attrs.update({"severity_rank": np.int64(1), "crosses": "overturn"})


def lognormal(x, median, beta):
    return 0.5 * math.erfc(-math.log(x / median) / (beta * math.sqrt(2.0)))


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
    assert_clean_error(call(PLOT_HISTORY, work / "absent.csv", "-o", work / "x.png"), "absent.csv")
    assert not (work / "x.png").exists()


def test_history_plot_names_a_missing_column(work):
    write_history(work / "h.csv", drop="normal_per_weight")
    assert_clean_error(call(PLOT_HISTORY, work / "h.csv", "-o", work / "x.png"), "normal_per_weight")


def test_history_plot_refuses_an_unknown_mode(work):
    write_history(work / "h.csv", modes=["rock"] * 300 + ["tumbling"] * 301)
    assert_clean_error(call(PLOT_HISTORY, work / "h.csv", "-o", work / "x.png"), "tumbling")


def test_history_plot_reports_an_unwritable_output(work):
    write_history(work / "h.csv")
    assert_clean_error(call(PLOT_HISTORY, work / "h.csv", "-o", work / "no_dir" / "x.png"), "cannot write",
                       code=1)


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
    assert_clean_error(call(PLOT_FRAGILITY, work / "absent.h5", "-o", work / "f.png"), "absent.h5")


def test_fragility_plot_refuses_a_file_that_is_not_hdf5(work):
    write_history(work / "h.csv")
    assert_clean_error(call(PLOT_FRAGILITY, work / "h.csv", "--summary"), "h.csv")


def test_fragility_plot_refuses_a_file_without_fragility(work):
    write_study(work / "s.h5", with_fragility=False)
    assert_clean_error(call(PLOT_FRAGILITY, work / "s.h5", "-o", work / "f.png"), "/fragility")
    assert not (work / "f.png").exists()


def test_fragility_plot_needs_something_to_do(work):
    write_study(work / "s.h5")
    result = run(PLOT_FRAGILITY, work / "s.h5")
    assert result.returncode == 2 and "nothing to do" in result.stderr, result.stderr


def test_fragility_plot_shades_the_bootstrap_band_when_the_file_has_it(work):
    write_study(work / "band.h5", diagnostics=True)
    write_study(work / "none.h5", diagnostics=True, band=False)
    for name in ("band", "none"):
        result = call(PLOT_FRAGILITY, work / f"{name}.h5", "-o", work / f"{name}.png")
        assert result.returncode == 0, result.stderr
    with_band = colour_pixels(check_plausible_png(work / "band.png"), SECOND_BAND)
    without = colour_pixels(check_plausible_png(work / "none.png"), SECOND_BAND)
    # Ranked by severity, overturning is second and takes the second colour; its band is a broad
    # area, while without one its light shade is only in the anti-aliased edges of its line.
    assert with_band > 5000, f"the band is not drawn: {with_band} pixels of {SECOND_BAND}"
    assert without < with_band / 20, f"{without} pixels of {SECOND_BAND} without a band ({with_band} with)"


def test_fragility_legend_and_summary_give_the_goodness_of_fit(work):
    write_study(work / "s.h5", diagnostics=True)
    fitted = [lognormal(x, BAKER_MEDIAN, BAKER_BETA) for x in BAKER_IM[:8]]
    misfit = max(abs(z / n - p) for z, n, p in zip(BAKER_EXCEED, BAKER_TRIALS, fitted))
    result = call(PLOT_FRAGILITY, work / "s.h5", "--summary")
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "severity order (least to most severe): slide_5cm, overturn" in out, out
    assert out.index("limit state slide_5cm") < out.index("limit state overturn"), out
    assert (f"goodness of fit: deviance = 15.2 on 6 dof, p = 0.019: lognormal rejected at 5 %; "
            f"largest |observed - fitted| = {misfit:.4f}") in out, out
    assert "95 % bootstrap intervals: median in [0.93, 1.31] g, beta in [0.31, 0.58]" in out, out
    assert "crosses, inside the levels: slide_5cm" in out, out
    assert out.count("severity: 2 of 2 (1 = least severe)") == 1, out

    plot = load(PLOT_FRAGILITY)
    study = plot.read_study(str(work / "s.h5"))
    assert [s["name"] for s in study["states"]] == ["slide_5cm", "overturn"]
    label = plot.legend_label(study["states"][1], "g")
    assert "median 1.08 g (0.93–1.31), β = 0.43 (0.31–0.58)" in label, label
    assert "deviance 15.2, p = 0.019" in label, label
    assert f"lognormal rejected at 5 %: points up to {misfit:.2f} off it" in label, label
    assert "crosses: slide_5cm" in label, label
    study["states"][1]["gof_p_value"] = 0.4
    label = plot.legend_label(study["states"][1], "g")
    assert "p = 0.4" in label and "rejected" not in label, label
    # The crossings given as /fragility's pairs instead.
    with h5py.File(work / "s.h5", "r+") as f:
        for name in ("overturn", "slide_5cm"):
            del f[f"fragility/{name}"].attrs["crosses"]
        f["fragility"].attrs["crossing_pairs"] = "overturn,slide_5cm"
    study = plot.read_study(str(work / "s.h5"))
    assert "crosses: slide_5cm" in plot.legend_label(study["states"][1], "g")
    assert "crosses: overturn" in plot.legend_label(study["states"][0], "g")
    # A file without the diagnostics: neither line.
    write_study(work / "old.h5")
    old = plot.read_study(str(work / "old.h5"))
    assert not old["by_severity"] and "deviance" not in plot.legend_label(old["states"][0], "g")
    assert "goodness of fit" not in plot.summary(old)


def test_fragility_plot_refuses_half_a_band(work):
    write_study(work / "s.h5", diagnostics=True)
    with h5py.File(work / "s.h5", "r+") as f:
        del f["fragility/overturn/band_high"]
    assert_clean_error(call(PLOT_FRAGILITY, work / "s.h5", "-o", work / "f.png"), "band_high")


# --- plot_cloud.py ------------------------------------------------------------------------------------

CLOUD_ALPHA = math.atan(0.5 / 1.0)


def write_samples(path, records=0, sampled_width=False, polygon=None):
    """Three stripes of 40 samples of a 1 m x 2 m block: at each level 10 overturned, 10 with
    max |theta|/alpha = 0.55 (above the rotation limit 0.5), 20 at 0.45; a quarter of each slid
    10 cm. With sampled_width each sample's half-width is 0.5 (the base scene's is 0.8)."""
    levels, per_level = [0.3, 0.6, 1.2], 40
    im = np.repeat(levels, per_level)
    pattern = np.array(["over"] * 10 + ["above"] * 10 + ["below"] * 20)
    verdict = np.tile(pattern, len(levels))
    ratio = np.where(verdict == "above", 0.55, 0.45)
    alpha = CLOUD_ALPHA if polygon is None else polygon
    theta = np.where(verdict == "over", math.pi / 2, ratio * alpha)
    slide = np.tile(np.where(np.arange(per_level) % 4 == 0, 0.1, 0.0), len(levels))
    block = {"half_width": 0.8 if sampled_width else 0.5, "half_height": 1.0}
    if polygon is not None:
        block = {"polygon": [[0, 0], [12.55, 0], [10, 3.4], [10, 16.7], [0, 16.7]]}
    config = {"scene": {"block": block}, "limit_states": [
        {"name": "overturn", "type": "overturning"},
        {"name": "rocking_half", "type": "max_rotation", "theta_over_alpha": 0.5},
        {"name": "slide_5cm", "type": "residual_slide", "threshold_m": 0.05}]}
    with h5py.File(path, "w") as f:
        f.attrs["config"] = json.dumps(config)
        f.create_dataset("samples/im", data=im).attrs["units"] = "g"
        if sampled_width:
            f.create_dataset("samples/half_width", data=np.full(len(im), 0.5))
        f.create_dataset("results/max_abs_theta", data=theta)
        f.create_dataset("results/overturned", data=(verdict == "over").astype(np.int64))
        f.create_dataset("results/final_slide", data=slide)
        f.create_dataset("results/status", data=np.zeros(len(im), dtype=np.int64))
        group = f.create_group("fragility")
        group.attrs.update({"im_label": "PGA", "im_units": "g", "scaling": "stripes"})
        for state in config["limit_states"]:
            threshold = state.get("theta_over_alpha", state.get("threshold_m", 0.0))
            group.create_group(state["name"]).attrs.update({"type": state["type"], "threshold": threshold})
        if records:
            f.create_dataset("samples/record", data=np.arange(len(im), dtype=np.int64) % records)
            f.create_dataset("records/file", data=[f"records/Quake_{k}.csv".encode() for k in range(records)])


def test_cloud_plot_shows_the_three_verdicts(work):
    write_samples(work / "s.h5")
    result = call(PLOT_CLOUD, work / "s.h5", "-o", work / "c.png")
    assert result.returncode == 0, result.stderr
    pixels = check_plausible_png(work / "c.png")
    for colour, name in ((OVERTURNED, "overturned"), (EXCEEDED, "above the limit"), (BELOW, "below")):
        assert colour_pixels(pixels, colour) > 300, f"no {name} samples drawn"


def test_cloud_verdicts_follow_alpha(work):
    cloud = load(PLOT_CLOUD)
    for name, options in (("rectangle", {}), ("sampled", {"sampled_width": True}),
                          ("polygon", {"polygon": 0.56241})):
        write_samples(work / f"{name}.h5", **options)
        data = cloud.read_samples(str(work / f"{name}.h5"))
        # The dam block's easier corner, as blockfrag simulate reports it (0.56241 rad).
        expected_alpha = 0.56241 if name == "polygon" else CLOUD_ALPHA
        assert np.allclose(data["alpha"], expected_alpha, atol=5e-6), (name, data["alpha"][:3])
        categories, index = cloud.verdicts(data, None)
        assert [label.split(" ")[0] for label, _ in categories] == ["overturned", "above", "below"]
        assert np.bincount(index).tolist() == [30, 30, 60], (name, np.bincount(index))
    states = {s[0]: s for s in data["limit_states"]}
    _, index = cloud.verdicts(data, states["slide_5cm"])
    assert int(np.sum(index == 0)) == 30, "slid 10 cm: a quarter of the samples"
    _, index = cloud.verdicts(data, states["rocking_half"])
    assert int(np.sum(index == 0)) == 60, "above 0.5 alpha or overturned: half"


def test_cloud_plot_by_limit_state_and_by_record(work):
    write_samples(work / "s.h5", records=3)
    result = call(PLOT_CLOUD, work / "s.h5", "-o", work / "slide.png", "--limit-state", "slide_5cm")
    assert result.returncode == 0, result.stderr
    pixels = check_plausible_png(work / "slide.png")
    assert colour_pixels(pixels, OVERTURNED) > 300 and colour_pixels(pixels, BELOW) > 300
    assert colour_pixels(pixels, EXCEEDED) == 0, "a rotation verdict's colour when colouring by a slide"
    result = call(PLOT_CLOUD, work / "s.h5", "-o", work / "records.png", "--by-record")
    assert result.returncode == 0, result.stderr
    check_plausible_png(work / "records.png", min_height=400)
    assert png_size(work / "records.png")[0] > png_size(work / "slide.png")[0], "three panels side by side"


def test_cloud_plot_errors_are_one_line(work):
    write_samples(work / "s.h5")
    assert_clean_error(call(PLOT_CLOUD, work / "s.h5", "-o", work / "x.png", "--by-record"), "--by-record")
    result = call(PLOT_CLOUD, work / "s.h5", "-o", work / "x.png", "--limit-state", "nope")
    assert result.returncode == 2 and "nope" in result.stderr and "rocking_half" in result.stderr, result.stderr
    write_study(work / "f.h5")
    assert_clean_error(call(PLOT_CLOUD, work / "f.h5", "-o", work / "x.png"), "/samples/im")
    assert not (work / "x.png").exists()


# --- plot_motion.py -----------------------------------------------------------------------------------

A, B = 0.5, 1.0
RECTANGLE = {"block": {"half_width": A, "half_height": B}}
# The same block as a polygon, counter-clockwise, in another frame: its centroid is (10.5, 6).
SHIFTED = {"block": {"polygon": [[10, 5], [11, 5], [11, 7], [10, 7]]}}


def write_motion(path):
    """A 1 m x 2 m block that slides 1 m, rocks on its right corner, flies a little way and rests."""
    rows = []
    for t in np.linspace(0.0, 3.0, 151):
        if t < 1.0:
            mode, x, y, theta = "slide", 0.5 * t * t, B, 0.0
        elif t < 2.0:
            theta = -0.25 * math.sin(math.pi * (t - 1.0))
            mode = "rock"
            x = 0.5 + A - A * math.cos(theta) - B * math.sin(theta)
            y = B * math.cos(theta) - A * math.sin(theta)
        elif t < 2.3:
            mode, x, y, theta = "flight", 0.5 + 0.5 * (t - 2.0), B + 2.0 * (t - 2.0) * (2.3 - t), 0.0
        else:
            mode, x, y, theta = "rest", 0.65, B, 0.0
        rows.append((t, x, y, theta, 0, 0, 0, mode, 0, 0 if mode == "flight" else 1))
    with open(path, "w") as out:
        out.write("t,x,y,theta,vx,vy,omega,mode,friction_per_weight,normal_per_weight\n")
        out.writelines(",".join(str(v) for v in row) + "\n" for row in rows)


def test_motion_plot_and_gif(work):
    write_motion(work / "h.csv")
    (work / "scene.json").write_text(json.dumps(RECTANGLE))
    result = call(PLOT_MOTION, work / "h.csv", work / "scene.json", "-o", work / "m.png", "--gif", work / "m.gif",
                 "--fps", "4")
    assert result.returncode == 0, result.stderr
    pixels = check_plausible_png(work / "m.png")
    for colour, name in ((SLIDE, "slide"), (ROCK, "rock"), (FLIGHT, "flight")):
        assert colour_pixels(pixels, colour) > 2000, f"no {name} colour"
    assert colour_pixels(pixels, SLIDE_ROCK) == 0, "slide-rock colour without any"
    assert colour_pixels(pixels, ROCK_EDGE, 3.0 / 255.0) > 400, "no rocking outline"
    assert colour_pixels(pixels, SEAT_FILL) == 0, "a seat on the flat ground"
    with Image.open(work / "m.gif") as gif:
        assert gif.format == "GIF" and gif.n_frames >= 10, f"{gif.format}, {gif.n_frames} frames"
        gif.seek(0)
        first = np.asarray(gif.convert("RGB"))
        gif.seek(gif.n_frames // 2)
        middle = np.asarray(gif.convert("RGB"))
    assert np.mean(np.any(first != middle, axis=-1)) > 0.005, "the block does not move"


def test_motion_plot_takes_a_polygon_about_its_centroid(work):
    write_motion(work / "h.csv")
    (work / "polygon.json").write_text(json.dumps(SHIFTED))
    result = call(PLOT_MOTION, work / "h.csv", work / "polygon.json", "-o", work / "p.png")
    assert result.returncode == 0, result.stderr
    check_plausible_png(work / "p.png")
    motion = load(PLOT_MOTION)
    shape = motion.read_shape(str(work / "polygon.json"))
    assert np.allclose(shape, [[-A, -B], [A, -B], [A, B], [-A, B]]), shape
    assert np.allclose(motion.outline(shape, 1.0, B, math.pi / 2)[0], [1.0 + B, B - A]), "turned the wrong way"


def test_motion_plot_refuses_another_scene(work):
    write_motion(work / "h.csv")
    (work / "tall.json").write_text(json.dumps({"block": {"half_width": 0.5, "half_height": 3.0}}))
    assert_clean_error(call(PLOT_MOTION, work / "h.csv", work / "tall.json", "-o", work / "x.png"),
                       "tall.json", "scene of that history")
    result = call(PLOT_MOTION, work / "h.csv", work / "absent.json", "-o", work / "x.png")
    assert result.returncode == 2 and "absent.json" in result.stderr, result.stderr
    assert not (work / "x.png").exists()


# The rectangle on a seat: a horizontal part to its right corner, then an incline at 45 deg, in the
# frame of its vertices (its centre at the origin, its base at y = -B).
ON_SEAT = {"block": {"half_width": A, "half_height": B}, "seat": [[-3, -B], [A, -B], [A + 1.5, -B + 1.5]]}


def write_seat_motion(path, into_incline=0.0, lift=0.0):
    """The rectangle on ON_SEAT as blockfrag writes it there (x the centre's displacement from rest, y
    in the seat's frame): at rest, sliding 0.3 m upstream (left), rocking on its left corner and back;
    into_incline slides it right instead, that far into the incline; lift raises it while it rocks."""
    rows = []
    for t in np.linspace(0.0, 3.0, 151):
        if t < 0.5:
            mode, x, y, theta = "rest", 0.0, 0.0, 0.0
        elif t < 1.0:
            mode, x, y, theta = "slide", (into_incline or -0.3) * (t - 0.5) / 0.5, 0.0, 0.0
        elif t < 2.0 and not into_incline:
            mode, theta = "rock", 0.3 * math.sin(math.pi * (t - 1.0))
            x = -0.3 - A + A * math.cos(theta) - B * math.sin(theta)
            y = -B + A * math.sin(theta) + B * math.cos(theta) + lift * math.sin(math.pi * (t - 1.0))
        else:
            mode, x, y, theta = "rest", into_incline or -0.3, 0.0, 0.0
        rows.append((t, x, y, theta, 0, 0, 0, mode, 0, 1))
    with open(path, "w") as out:
        out.write("t,x,y,theta,vx,vy,omega,mode,friction_per_weight,normal_per_weight\n")
        out.writelines(",".join(str(v) for v in row) + "\n" for row in rows)


def test_motion_plot_draws_the_seat(work):
    write_seat_motion(work / "h.csv")
    (work / "seat.json").write_text(json.dumps(ON_SEAT))
    result = call(PLOT_MOTION, work / "h.csv", work / "seat.json", "-o", work / "m.png", "--gif", work / "m.gif",
                  "--fps", "4")
    assert result.returncode == 0, result.stderr
    pixels = check_plausible_png(work / "m.png")
    assert colour_pixels(pixels, SEAT_FILL) > 5000, "no seat"
    assert colour_pixels(pixels, ROCK_EDGE, 3.0 / 255.0) > 400, "no rocking outline"
    # The seat is drawn where it is: at the right end of the view its incline has risen above the
    # horizontal part at the left end (a flat band of the seat's colour would not).
    seat_pixels = np.all(np.abs(pixels[..., :3] - np.array([0xdd, 0xd6, 0xc8]) / 255.0) <= 2 / 255, axis=-1)
    columns = np.nonzero(seat_pixels.any(axis=0))[0]
    top = [int(np.argmax(seat_pixels[:, c])) for c in (columns[0] + 3, columns[-1] - 3)]
    assert top[1] < top[0] - 10, f"the seat's incline is not drawn (its top at {top} px, left and right)"
    motion = load(PLOT_MOTION)
    shape, seat = motion.read_scene(str(work / "seat.json"))
    assert np.allclose(seat[1], [0, 0]) and np.allclose(seat[0][1], [A, -B]), seat


def test_motion_plot_refuses_a_block_in_the_seat(work):
    (work / "seat.json").write_text(json.dumps(ON_SEAT))
    (work / "flat.json").write_text(json.dumps(RECTANGLE))
    # Sliding 0.2 m right pushes its right corner 0.2 m under the incline (0.14 m across it).
    write_seat_motion(work / "h.csv", into_incline=0.2)
    assert_clean_error(call(PLOT_MOTION, work / "h.csv", work / "seat.json", "-o", work / "x.png"),
                       "into the seat", "seat.json")
    assert not (work / "x.png").exists()
    # Lifted 0.1 m off its corner while rocking: it floats.
    write_seat_motion(work / "h.csv", lift=0.1)
    assert_clean_error(call(PLOT_MOTION, work / "h.csv", work / "seat.json", "-o", work / "x.png"),
                       "off the seat")
    # Which the fit check finds on the seat, not as on the flat ground: 0.1 m below the seat's
    # line is sunk; a corner far past the seat's end, under its level, is not (it falls).
    motion = load(PLOT_MOTION)
    shape, seat = motion.read_scene(str(work / "seat.json"))
    data = {"t": np.array([0.0, 1.0]), "x": np.array([0.0, 0.0]), "y": np.array([-0.1, 0.0]),
            "theta": np.zeros(2), "mode": np.array(["rest", "rest"])}
    try:
        motion.check_fit(shape, data, "h", "s", seat)
        raise AssertionError("a block 0.1 m into the seat accepted")
    except motion.InputError as error:
        assert "0.1 m into the seat at t = 0 s" in str(error), error
    # Tilted over the seat's end with every corner above the seat or past its end, but the end
    # 0.081 m inside the block's base.
    data = {"t": np.array([0.0, 1.0]), "x": np.array([0.0, -3.2]), "y": np.array([0.0, -0.1]),
            "theta": np.array([0.0, 0.3]), "mode": np.array(["rest", "rock"])}
    try:
        motion.check_fit(shape, data, "h", "s", seat)
        raise AssertionError("the seat's end inside the block accepted")
    except motion.InputError as error:
        assert "0.0811 m into the seat at t = 1 s" in str(error), error
    falling = {"t": np.array([0.0, 1.0, 1.5]), "x": np.array([0.0, -4.5, -5.0]), "y": np.array([0.0, -0.5, -2.0]),
               "theta": np.array([0.0, 0.3, 0.5]), "mode": np.array(["rest", "flight", "flight"])}
    motion.check_fit(shape, falling, "h", "s", seat)


def test_motion_pair_draws_two_panels_on_their_seats(work):
    write_seat_motion(work / "h.csv")
    write_motion(work / "flat.csv")
    (work / "seat.json").write_text(json.dumps(ON_SEAT))
    (work / "flat.json").write_text(json.dumps(RECTANGLE))
    result = call(PLOT_MOTION_PAIR, work / "h.csv", work / "seat.json", work / "flat.csv", work / "flat.json",
                  "-o", work / "two.png", "--titles", "on a seat", "flat")
    assert result.returncode == 0, result.stderr
    width, height = png_size(work / "two.png")
    assert width > 1.2 * height, f"two panels side by side: {width} x {height}"
    pixels = check_plausible_png(work / "two.png")
    assert colour_pixels(pixels, SEAT_FILL) > 3000, "no seat"
    assert colour_pixels(pixels, ROCK_EDGE, 3.0 / 255.0) > 400, "no rocking outline"
    # Each history is checked against its own scene: swapped, they are refused.
    result = call(PLOT_MOTION_PAIR, work / "h.csv", work / "flat.json", work / "flat.csv", work / "seat.json",
                  "-o", work / "x.png")
    assert result.returncode == 2 and "scene of that history" in result.stderr, result.stderr
    assert not (work / "x.png").exists()


# --- plot_fragility_pair.py ---------------------------------------------------------------------------

def test_fragility_pair_draws_both_studies_per_limit_state(work):
    write_study(work / "a.h5")
    write_study(work / "b.h5", diagnostics=True)
    with h5py.File(work / "b.h5", "r+") as f:  # the second study's curves at 1.6 times the intensity
        for state in f["fragility"].values():
            state["im"][...] = 1.6 * state["im"][...]
            state.attrs["median"] = 1.6 * state.attrs["median"]
    result = call(PLOT_FRAGILITY_PAIR, work / "a.h5", work / "b.h5", "-o", work / "ab.png",
                  "--labels", "type A", "type B")
    assert result.returncode == 0, result.stderr
    width, height = png_size(work / "ab.png")
    assert width > 1.5 * height, f"two limit states side by side: {width} x {height}"
    pixels = check_plausible_png(work / "ab.png", min_height=300)
    assert colour_pixels(pixels, FIRST_STUDY) > 300, "the first study is not drawn"
    assert colour_pixels(pixels, SECOND_STUDY) > 300, "the second study is not drawn"


def test_fragility_pair_refuses_studies_that_measure_intensity_differently(work):
    write_study(work / "a.h5")
    write_study(work / "b.h5", with_names=False)
    assert_clean_error(call(PLOT_FRAGILITY_PAIR, work / "a.h5", work / "b.h5", "-o", work / "ab.png"),
                       "intensity differently")
    assert not (work / "ab.png").exists()
    assert_clean_error(call(PLOT_FRAGILITY_PAIR, work / "a.h5", work / "absent.h5", "-o", work / "ab.png"),
                       "absent.h5")


def add_post_earthquake_state(path):
    """A wet study's post-earthquake limit state, and a second dislocation threshold, beside
    write_study's two."""
    with h5py.File(path, "r+") as f:
        state = f["fragility"].create_group("unstable_after")
        fill(state, BAKER_IM, BAKER_TRIALS, BAKER_EXCEED)
        state.attrs.update({"median": 0.8, "beta": 0.4, "log_likelihood": -11.0, "fit_status": "ok",
                            "type": "post_earthquake_unstable", "threshold": 1.0})
        state = f["fragility"].create_group("slide_2cm")
        fill(state, BAKER_IM, BAKER_TRIALS, BAKER_EXCEED)
        state.attrs.update({"median": 0.9, "beta": 0.5, "log_likelihood": -11.0, "fit_status": "ok",
                            "type": "residual_slide", "threshold": 0.02})


def test_fragility_pair_draws_one_panel_per_kind(work):
    write_study(work / "dry.h5")
    write_study(work / "wet.h5")
    add_post_earthquake_state(work / "wet.h5")
    with h5py.File(work / "wet.h5", "r+") as f:  # the wet curves apart from the dry, at 1.6 times the intensity
        for state in f["fragility"].values():
            state["im"][...] = 1.6 * state["im"][...]
            state.attrs["median"] = 1.6 * state.attrs["median"]
    module = load(PLOT_FRAGILITY_PAIR)
    studies = [module.read_study(work / "dry.h5"), module.read_study(work / "wet.h5")]
    panels = module.panels_by_kind(studies, ["post_earthquake", "dislocation", "loss"])
    # In the order asked; each kind's states by ascending threshold; the dry study has no
    # post-earthquake state and its panel says so rather than vanishing.
    assert [title.split(" ")[0] for title, _ in panels] == ["post-earthquake", "dislocation", "loss"], panels
    names = [[[s["name"] for s in states] for states in per_study] for _, per_study in panels]
    assert names == [[[], ["unstable_after"]], [["slide_5cm"], ["slide_2cm", "slide_5cm"]],
                     [["overturn"], ["overturn"]]], names
    result = call(PLOT_FRAGILITY_PAIR, work / "dry.h5", work / "wet.h5", "-o", work / "kinds.png",
                  "--labels", "dry", "wet", "--kinds", "dislocation", "loss", "post_earthquake")
    assert result.returncode == 0, result.stderr
    width, height = png_size(work / "kinds.png")
    assert width > 2.5 * height, f"three panels side by side: {width} x {height}"
    pixels = check_plausible_png(work / "kinds.png", min_height=300)
    assert colour_pixels(pixels, FIRST_STUDY) > 300, "the dry study is not drawn"
    assert colour_pixels(pixels, SECOND_STUDY) > 300, "the wet study is not drawn"
    result = call(PLOT_FRAGILITY_PAIR, work / "dry.h5", work / "wet.h5", "-o", work / "two.png", "--kinds", "loss",
                  "dislocation")
    assert result.returncode == 0, result.stderr
    width, height = png_size(work / "two.png")
    assert 1.5 * height < width < 2.5 * height, f"two panels side by side: {width} x {height}"


def test_fragility_pair_refuses_a_kind_neither_study_has_and_an_unknown_kind(work):
    write_study(work / "dry.h5")
    write_study(work / "wet.h5")
    assert_clean_error(call(PLOT_FRAGILITY_PAIR, work / "dry.h5", work / "wet.h5", "-o", work / "x.png",
                            "--kinds", "loss", "rocking"), "neither study has a rocking limit state")
    assert not (work / "x.png").exists()
    result = call(PLOT_FRAGILITY_PAIR, work / "dry.h5", work / "wet.h5", "-o", work / "x.png", "--kinds", "damage")
    assert result.returncode == 2 and "invalid choice: 'damage'" in result.stderr, result.stderr
    result = call(PLOT_FRAGILITY_PAIR, work / "dry.h5", work / "wet.h5", "-o", work / "x.png", "--kinds")
    assert result.returncode == 2 and "--kinds" in result.stderr, result.stderr
    assert not (work / "x.png").exists()


# --- plot_spectrum.py ---------------------------------------------------------------------------------

# plot_spectrum.py's colours: stands, safe island, overturns with no impact, after more impacts,
# still moving; the refined minimum.
STANDS, ISLAND, NO_IMPACT, MORE_IMPACTS, MOVING = "#F2F2F2", "#56B4E9", "#D55E00", "#CC79A7", "#F0E442"
REFINED_MINIMUM = "#009E73"


def synthetic_spectrum(f_ratio, a_ratio):
    """A made-up verdict: overturns with no impact above 2 + f, after impacts from 1 + f / 2 to
    there, except a safe band 1.4 + f / 2 <= a < 1.6 + f / 2 while f < 1.5."""
    if a_ratio >= 2 + f_ratio:
        return 1
    if a_ratio >= 1 + f_ratio / 2 and not (f_ratio < 1.5 and 1.4 + f_ratio / 2 <= a_ratio < 1.6 + f_ratio / 2):
        return 3
    return 0


def write_spectrum(path, frequency=np.geomspace(0.5, 3.0, 30), amplitude=np.linspace(0.9, 6.0, 50),
                   minimum=True):
    """A spectrum output as blockfrag writes it, from synthetic_spectrum, its crossings taken at
    the first cell of each change (the script draws them, it does not check the bisection); with
    `minimum`, a refined minimum 0.2 below the map's lowest onset at the frequencies below 1, equal
    to it elsewhere."""
    verdict = np.array([[synthetic_spectrum(f, a) for a in amplitude] for f in frequency], dtype=np.int64)
    index, crossing, direction = [], [], []
    for i in range(len(frequency)):
        over = (verdict[i] >= 1) & (verdict[i] <= 3)
        for j in np.nonzero(over[1:] != over[:-1])[0]:
            index.append(i)
            crossing.append(0.5 * (amplitude[j] + amplitude[j + 1]))
            direction.append(1 if over[j + 1] else -1)
    config = {"block": {"half_width": 0.5, "half_height": 1.0}, "contact": {"friction": 0.6, "restitution": 0.6},
              "effects": "auto", "pulse": {"type": "cosine_pulse", "cycles": 1.0},
              "frequency_ratio": {"from": 0.5, "to": 3.0, "count": len(frequency), "spacing": "log"}}
    with h5py.File(path, "w") as f:
        f.attrs["config"] = json.dumps(config)
        f.attrs["alpha"] = math.atan(0.5)
        f.attrs["pulse"] = "cosine_pulse"
        f["map/frequency_ratio"] = frequency
        f["map/amplitude_ratio"] = amplitude
        f["map/verdict"] = verdict
        f["boundary/frequency_index"] = np.array(index, dtype=np.int64)
        f["boundary/amplitude_ratio"] = np.array(crossing)
        f["boundary/direction"] = np.array(direction, dtype=np.int64)
        if minimum:
            lowest = np.array([min(c for c, i, d in zip(crossing, index, direction) if i == k and d > 0)
                               for k in range(len(frequency))])
            f["minimum_overturning/frequency_ratio"] = frequency
            f["minimum_overturning/map_amplitude_ratio"] = lowest
            f["minimum_overturning/amplitude_ratio"] = np.where(frequency < 1, lowest - 0.2, lowest)
            f["minimum_overturning"].attrs["tolerance"] = 1e-3
    return verdict


def spectrum_png(path):
    """The pixels of a plausible spectrum figure: its map covers much of it in strong colours, so
    check_plausible_png's share of dark pixels does not apply; the boundary lines' black does."""
    width, height = png_size(path)
    assert 800 <= width <= 4000 and 600 <= height <= 4000, f"odd size {width} x {height}"
    pixels = matplotlib.image.imread(path)
    assert colour_pixels(pixels, "#000000", 0.1) > 2000, "no black lines or text"
    return pixels


def test_spectrum_plot_shows_the_verdicts_and_the_island(work):
    write_spectrum(work / "s.h5")
    result = call(PLOT_SPECTRUM, work / "s.h5", "-o", work / "s.png", "--mark-point", "1,1.5")
    assert result.returncode == 0, result.stderr
    pixels = spectrum_png(work / "s.png")
    for colour, name in ((ISLAND, "safe island"), (NO_IMPACT, "no impact"), (MORE_IMPACTS, "more impacts")):
        assert colour_pixels(pixels, colour) > 2000, f"no {name} colour"
    assert colour_pixels(pixels, MOVING) == 0, "the still-moving colour without any such point"
    assert colour_pixels(pixels, REFINED_MINIMUM) > 300, "no refined minimum"


def test_spectrum_plot_marks_where_the_refined_minimum_is_lower(work):
    write_spectrum(work / "s.h5")
    spectrum = load(PLOT_SPECTRUM)
    frequency, refined, lowered = spectrum.minimum_line(spectrum.read_spectrum(str(work / "s.h5")))
    assert np.array_equal(lowered, frequency < 1), lowered
    # A file written before the refinement existed is drawn without it.
    write_spectrum(work / "old.h5", minimum=False)
    assert spectrum.minimum_line(spectrum.read_spectrum(str(work / "old.h5"))) is None
    result = call(PLOT_SPECTRUM, work / "old.h5", "-o", work / "old.png")
    assert result.returncode == 0, result.stderr
    assert colour_pixels(spectrum_png(work / "old.png"), REFINED_MINIMUM) == 0


def test_spectrum_plot_draws_a_map_and_its_zoom(work):
    write_spectrum(work / "map.h5")
    write_spectrum(work / "zoom.h5", np.geomspace(0.8, 1.4, 20), np.linspace(1.6, 2.5, 40))
    result = call(PLOT_SPECTRUM, work / "map.h5", work / "zoom.h5", "-o", work / "z.png")
    assert result.returncode == 0, result.stderr
    width, height = png_size(work / "z.png")
    assert width > 1.5 * height, f"two panels side by side: {width} x {height}"
    assert colour_pixels(spectrum_png(work / "z.png"), ISLAND) > 4000, "no island in the zoom"


def test_spectrum_islands_and_boundary_lines(work):
    verdict = write_spectrum(work / "s.h5")
    spectrum = load(PLOT_SPECTRUM)
    data = spectrum.read_spectrum(str(work / "s.h5"))
    classes = spectrum.drawn_classes(verdict)
    # The safe band is one island: standing cells above overturning ones, and no others.
    frequency, amplitude = data["frequency"], data["amplitude"]
    expected = np.array([[f < 1.5 and 1.4 + f / 2 <= a < 1.6 + f / 2 for a in amplitude] for f in frequency])
    assert np.array_equal(classes == spectrum.ISLAND, expected)
    groups = spectrum.islands(classes)
    assert len(groups) == 1 and len(groups[0]) == expected.sum(), [len(g) for g in groups]
    # Lines: the lowest onset across every frequency; the island's two edges along the frequencies
    # that have the island, each one line (the no-impact onset is no boundary: both sides overturn).
    lines = spectrum.boundary_lines(data)
    lowest = [line for line in lines if line[1]]
    assert len(lowest) == 1 and not np.isnan(lowest[0][3]).any()
    island_frequencies = int((frequency < 1.5).sum())
    lengths = sorted(len(line[2]) for line in lines if not line[1])
    assert lengths == [island_frequencies, island_frequencies], lengths
    # Crossings far apart in amplitude at neighbouring frequencies are not joined.
    data["boundary"] = {"frequency_index": np.array([0, 0, 1, 1]), "amplitude_ratio": np.array([1.0, 2.0, 1.0, 4.0]),
                        "direction": np.array([1, -1, 1, -1])}
    ends = sorted(len(line[2]) for line in spectrum.boundary_lines(data) if not line[1] and len(line[2]))
    assert ends == [1, 1], ends


def test_spectrum_plot_errors_are_one_line(work):
    assert_clean_error(call(PLOT_SPECTRUM, work / "absent.h5", "-o", work / "x.png"), "absent.h5")
    write_study(work / "study.h5")
    assert_clean_error(call(PLOT_SPECTRUM, work / "study.h5", "-o", work / "x.png"),
                       "study.h5 has no dataset /map/frequency_ratio")
    write_spectrum(work / "s.h5")
    result = run(PLOT_SPECTRUM, work / "s.h5", "-o", work / "x.png", "--mark-point", "1")
    assert result.returncode == 2 and "Traceback" not in result.stderr, result.stderr
    assert "--mark-point: expected FREQUENCY,AMPLITUDE, got '1'" in result.stderr, result.stderr
    assert not (work / "x.png").exists()


# --- plot_fragility_surface.py ---------------------------------------------------------------------


def normal_cdf(x):
    return 0.5 * math.erfc(-x / math.sqrt(2.0))


def write_surface(path, b=(0.5, 2.5, 1.25), second_state_fitted=True):
    """A surface study's /fragility_surface: 5 amplitudes x 4 periods, counts from Phi(b . x)."""
    im1 = np.array([0.3, 0.5, 0.8, 1.3, 2.0])
    im2 = np.array([0.5, 0.8, 1.3, 2.0])
    with h5py.File(path, "w") as f:
        root = f.create_group("fragility_surface")
        for key, value in (("im1_label", "pulse amplitude"), ("im1_units", "g"),
                           ("im2_label", "pulse period"), ("im2_units", "s")):
            root.attrs[key] = value
        for name, fitted in (("overturn", True), ("slide", second_state_fitted)):
            group = root.create_group(name)
            group["im1"], group["im2"] = im1, im2
            p = np.array([[normal_cdf(b[0] + b[1] * math.log(x) + b[2] * math.log(y)) for y in im2] for x in im1])
            group["trials"] = np.full(p.shape, 100, dtype=np.int64)
            group["exceedances"] = np.round(100 * p).astype(np.int64)
            group["probability"] = np.round(100 * p) / 100
            nan = float("nan")
            group.attrs["fit_status"] = "ok" if fitted else "separated"
            group.attrs["coefficients"] = np.array(b if fitted else (nan, nan, nan))
            group.attrs["standard_errors"] = np.array((0.02, 0.05, 0.04) if fitted else (nan, nan, nan))
            group.attrs["log_likelihood"] = -42.0 if fitted else nan
            group.attrs["deviance"], group.attrs["gof_dof"] = (31.5, 17) if fitted else (nan, 0)
            group.attrs["gof_p_value"] = 0.0174 if fitted else nan
            median = (-b[0] / b[1], 0.01, -b[2] / b[1], 0.02, 1 / b[1], 0.008)
            for key, value in zip(("ln_median_intercept", "ln_median_intercept_se", "ln_median_slope",
                                   "ln_median_slope_se", "beta1", "beta1_se"), median):
                group.attrs[key] = value if fitted else nan


def test_surface_plot_colours_the_cells_and_draws_the_fit(work):
    write_surface(work / "s.h5")
    result = call(PLOT_SURFACE, work / "s.h5", "-o", work / "s.png", "--summary")
    assert result.returncode == 0, result.stderr
    pixels = check_plausible_png(work / "s.png", min_height=500)
    # The markers are filled with the colour map's colour of their probability: the ends of
    # viridis (P near 0 and near 1) are both present.
    import matplotlib
    for p in (0.0, 1.0):
        colour = "#" + "".join(f"{round(255 * c):02x}" for c in matplotlib.colormaps["viridis"](p)[:3])
        assert colour_pixels(pixels, colour, tolerance=0.03) > 20, f"no cell drawn in {colour}"
    # The summary gives the file's coefficients and the median form.
    assert "b1 = 2.5 +- 0.05" in result.stdout, result.stdout
    assert "beta = 0.4 +- 0.008" in result.stdout, result.stdout
    assert "deviance 31.5 on 17 degrees of freedom, p = 0.0174: the probit is rejected" in result.stdout, result.stdout
    # The fitted contours as the script computes them pass through P = 0.5 on ln median1 =
    # -(b0 + b2 ln x2) / b1.
    module = load(PLOT_SURFACE)
    x2 = 1.3
    median = math.exp(-(0.5 + 1.25 * math.log(x2)) / 2.5)
    assert abs(module.fitted_probability(np.array([0.5, 2.5, 1.25]), median, x2) - 0.5) < 1e-12


def test_surface_plot_says_when_a_limit_state_has_no_fit(work):
    write_surface(work / "s.h5", second_state_fitted=False)
    result = call(PLOT_SURFACE, work / "s.h5", "-o", work / "s.png", "--summary")
    assert result.returncode == 0, result.stderr
    assert "slide: fit separated" in result.stdout, result.stdout
    check_plausible_png(work / "s.png", min_height=500)
    result = call(PLOT_SURFACE, work / "s.h5", "-o", work / "one.png", "--limit-state", "slide")
    assert result.returncode == 0 and png_size(work / "one.png")[0] < png_size(work / "s.png")[0]


def test_surface_plot_errors_are_one_line(work):
    write_study(work / "study.h5")
    assert_clean_error(call(PLOT_SURFACE, work / "study.h5", "-o", work / "x.png"), "no /fragility_surface")
    assert_clean_error(call(PLOT_SURFACE, work / "absent.h5", "-o", work / "x.png"), "absent.h5: no such file")
    write_surface(work / "s.h5")
    assert_clean_error(call(PLOT_SURFACE, work / "s.h5", "-o", work / "x.png", "--limit-state", "nope"),
                       "--limit-state nope", "overturn, slide")
    result = run(PLOT_SURFACE, work / "s.h5", "-o", work / "x.png", "--contours", "0.5,1.5")
    assert result.returncode == 2 and "every probability must be in (0, 1)" in result.stderr, result.stderr
    assert not (work / "x.png").exists()


# --- plot_work_precision.py ----------------------------------------------------------------------


def write_accuracy(path, drop=None):
    """An accuracy output as `blockfrag accuracy` writes it: two rk4 steps and two adaptive
    tolerances, their errors falling with the cost; `drop` leaves one dataset out."""
    summary = {"max_error_max_abs_theta": [1e-3, 1e-5, 1e-7, 1e-9], "median_error_max_abs_theta": [1e-4, 1e-6, 1e-8, 0.0],
               "median_seconds": [1e-4, 1e-3, 2e-4, 5e-4], "parameter": [1e-2, 1e-3, 1e-6, 1e-8],
               "failures": np.zeros(4, dtype=np.int64)}
    with h5py.File(path, "w") as f:
        f.attrs["reference_method"] = "adaptive"
        f.attrs["reference_tolerance"] = 1e-12
        group = f.create_group("summary")
        group.attrs["labels"] = "rk4 dt=0.01\nrk4 dt=0.001\nadaptive tol=1e-06\nadaptive tol=1e-08"
        group.attrs["methods"] = "rk4\nrk4\nadaptive\nadaptive"
        for name, values in summary.items():
            if name != drop:
                group.create_dataset(name, data=np.asarray(values))
        f.create_dataset("scenes/check_error_max_abs_theta", data=np.array([1e-12, 3e-12]))


def test_work_precision_plot_draws_the_methods(work):
    write_accuracy(work / "a.h5")
    result = call(PLOT_WORK_PRECISION, work / "a.h5", work / "wp.png")
    assert result.returncode == 0, result.stderr
    check_plausible_png(work / "wp.png")


def test_work_precision_plot_errors_are_one_line(work):
    write_accuracy(work / "a.h5", drop="median_seconds")
    assert_clean_error(call(PLOT_WORK_PRECISION, work / "a.h5", work / "x.png"), "a.h5",
                       "/summary/median_seconds")
    write_study(work / "study.h5")
    assert_clean_error(call(PLOT_WORK_PRECISION, work / "study.h5", work / "x.png"), "study.h5", "/summary")
    assert_clean_error(call(PLOT_WORK_PRECISION, work / "absent.h5", work / "x.png"), "absent.h5: no such file")
    assert not (work / "x.png").exists()
# --- plot_risk.py ---------------------------------------------------------------------------------

def write_risk(path):
    """A risk.json as `blockfrag risk` writes it (docs/risk.md): a power-law hazard at 12 levels,
    two fitted limit states with points, each bin's lambda the fit's there."""
    im = np.geomspace(0.05, 3.0, 12)
    rate = 1e-4 * im ** -2.5
    states = []
    for name, median, beta in (("rock", 0.6, 0.4), ("overturn", 1.2, 0.5)):
        edges = np.sqrt(im[1:] * im[:-1])
        bins = [float(lognormal(e, median, beta) * (rate[i] - rate[i + 1])) for i, e in enumerate(edges)]
        estimate = {"lambda": sum(bins), "bin_lambda": bins}
        levels = [0.2, 0.4, 0.8, 1.6]
        states.append({"name": name, "median": median, "beta": beta, "levels": levels,
                       "probability": [float(lognormal(x, median, beta)) for x in levels],
                       "fit": estimate, "points": estimate})
    report = {"blockfrag_risk": 1, "years": [1.0, 50.0, 100.0],
              "hazard": {"file": "site.csv", "format": "openquake", "imt": "PGA", "site": "lon 1, lat 2",
                         "im": im.tolist(), "annual_rate": rate.tolist()},
              "studies": [{"file": "a.h5", "weight": 1.0, "im_units": "g", "limit_states": states}],
              "limit_states": states}
    path.write_text(json.dumps(report))


def test_risk_plot_shows_hazard_fragility_and_integrand(work):
    write_risk(work / "risk.json")
    result = call(PLOT_RISK, work / "risk.json", "-o", work / "risk.png")
    assert result.returncode == 0, result.stderr
    pixels = check_plausible_png(work / "risk.png", min_height=900)
    # Each limit state's colour in the fragility and integrand panels.
    assert colour_pixels(pixels, FIRST_STATE) > 200 and colour_pixels(pixels, SECOND_STATE) > 200
    # The integrand is each bin's lambda over its width in ln im.
    module = load(PLOT_RISK)
    im = np.array([0.1, 0.2, 0.8])
    assert np.allclose(module.integrand(im, [1.0, 2.0]), [1.0 / math.log(2.0), 2.0 / math.log(4.0)])


def test_risk_plot_refuses_what_is_not_a_risk_json(work):
    assert_clean_error(call(PLOT_RISK, work / "none.json", "-o", work / "x.png"), "none.json: no such file")
    (work / "other.json").write_text('{"a": 1}')
    assert_clean_error(call(PLOT_RISK, work / "other.json", "-o", work / "x.png"),
                       "other.json: not a blockfrag risk.json")
    (work / "short.json").write_text('{"blockfrag_risk": 1, "hazard": {"im": [1], "annual_rate": [1]}, '
                                     '"limit_states": [], "studies": [{"limit_states": []}]}')
    assert_clean_error(call(PLOT_RISK, work / "short.json", "-o", work / "x.png"),
                       "short.json: /hazard/im and /hazard/annual_rate are not one curve")



def test_risk_plot_names_a_damaged_limit_state_by_its_path(work):
    write_risk(work / "risk.json")
    report = json.loads((work / "risk.json").read_text())
    report["limit_states"][1]["fit"]["bin_lambda"] = report["limit_states"][1]["fit"]["bin_lambda"][:-1]
    (work / "short_bins.json").write_text(json.dumps(report))
    assert_clean_error(call(PLOT_RISK, work / "short_bins.json", "-o", work / "x.png"),
                       "short_bins.json: /limit_states/1/fit/bin_lambda: not a list of 11 numbers")
    report = json.loads((work / "risk.json").read_text())
    del report["limit_states"][0]["name"]
    (work / "nameless.json").write_text(json.dumps(report))
    assert_clean_error(call(PLOT_RISK, work / "nameless.json", "-o", work / "x.png"),
                       "nameless.json: /limit_states/0: not a limit state with a name")
    report = json.loads((work / "risk.json").read_text())
    report["studies"][0]["limit_states"][0]["probability"] = [0.5]
    (work / "points.json").write_text(json.dumps(report))
    assert_clean_error(call(PLOT_RISK, work / "points.json", "-o", work / "x.png"),
                       "points.json: /studies/0/limit_states/0/probability: not a list of 4 numbers")
    assert not (work / "x.png").exists()


def test_risk_plot_reports_an_unwritable_output(work):
    write_risk(work / "risk.json")
    assert_clean_error(call(PLOT_RISK, work / "risk.json", "-o", work / "no_dir" / "x.png"), "cannot write",
                       code=1)


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
