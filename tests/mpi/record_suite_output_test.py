"""Record-suite studies end to end, on 2 ranks: the HDF5 output's /records (each record's measures,
checked against the record file itself), /samples (the record each sample ran, the scale that
brought it to its level, its PGA and PGV) and /fragility (the measure's name, units and label); a
cloud study's per-sample intensities and its per-sample fit. Prints "N passed, M failed" last.
"""

import json
import math
import os
import subprocess
import tempfile
from pathlib import Path

import h5py
import numpy as np

BLOCKFRAG = os.environ["BLOCKFRAG"]
SOURCE = Path(os.environ["BLOCKFRAG_SOURCE_DIR"])
RECORDS = SOURCE / "tests" / "data" / "records"
passed = failed = 0


def check(condition, message):
    global passed, failed
    if condition:
        passed += 1
    else:
        failed += 1
        print("FAIL:", message)


def run_study(folder, study, name):
    path = folder / f"{name}.json"
    path.write_text(json.dumps(study))
    result = subprocess.run(["mpirun", "-n", "2", "--oversubscribe", BLOCKFRAG, "run", str(path),
                             "--output", str(folder / f"{name}.h5")],
                            capture_output=True, text=True, timeout=600)
    check(result.returncode == 0, f"{name}: exit {result.returncode}: {result.stderr[-500:]}")
    return h5py.File(folder / f"{name}.h5", "r")


def two_column_peak(path):
    values = [abs(float(line.replace(",", " ").split()[1])) for line in path.read_text().splitlines()
              if line.strip() and not line.lstrip().startswith("#")]
    return max(values)


def study(records, measure, per_level):
    return {
        "scene": {"block": {"half_width": 0.3, "half_height": 1.0},
                  "contact": {"friction": 0.7, "restitution": 0.5},
                  "ground_motion": {"type": "record_suite", "records": records}},
        "inputs": {"friction": {"distribution": "uniform", "min": 0.5, "max": 0.9},
                   "direction": {"distribution": "random_sign"}},
        "intensity_measure": measure,
        "samples_per_level": per_level,
        "design": "latin_hypercube",
        "limit_states": [{"name": "rock_tenth", "type": "max_rotation", "theta_over_alpha": 0.1}],
        "seed": 11,
    }


with tempfile.TemporaryDirectory() as scratch:
    folder = Path(scratch)
    files = [str(RECORDS / name) for name in ("decaying_sine.AT2", "cosine_pulse.txt", "old_header.at2")]

    with run_study(folder, study(files, {"type": "pga", "levels": [0.1, 0.3]}, 6), "stripes") as out:
        names = [n.decode() for n in out["records/file"][()]]
        check(names == files, f"/records/file {names}")
        # cosine_pulse.txt: -0.4 cos(...), written exactly: its PGA is 0.4 g.
        check(out["records/pga_g"][1] == two_column_peak(RECORDS / "cosine_pulse.txt") == 0.4,
              f"/records/pga_g[1] = {out['records/pga_g'][1]}")
        # Its velocity: 0.4 g T / (2 pi) with T = 0.5 s for the smooth cosine; the record draws it
        # linearly between samples 50 per period, and integrating that is the trapezoid rule,
        # whose error on a sinusoid is (2 pi / 50)^2 / 12 = 1.3e-3 of it.
        smooth = 0.4 * 9.81 * 0.5 / (2 * math.pi)
        check(abs(out["records/pgv_m_s"][1] - smooth) < 1.4e-3 * smooth,
              f"/records/pgv_m_s[1] = {out['records/pgv_m_s'][1]}, {smooth} smooth")
        check(np.all(out["records/duration_s"][()] > 0), "a record without duration")
        record = out["samples/record"][()]
        level = out["samples/level"][()]
        for k in range(2):
            counts = np.bincount(record[level == k], minlength=3)
            check(list(counts) == [2, 2, 2], f"level {k} runs records {counts}")
        im = out["samples/im"][()]
        check(np.array_equal(im, np.where(level == 0, 0.1, 0.3)), "/samples/im is not the level")
        scale = out["samples/scale"][()]
        pga = out["records/pga_g"][()][record]
        check(np.allclose(scale * pga, im, rtol=1e-14, atol=0), "scale x record PGA is not the level")
        check(np.allclose(out["samples/pga_g"][()], im, rtol=1e-14, atol=0), "/samples/pga_g")
        check(np.allclose(out["samples/pgv_m_s"][()], scale * out["records/pgv_m_s"][()][record],
                          rtol=1e-14, atol=0), "/samples/pgv_m_s")
        attrs = out["fragility"].attrs
        check((attrs["im_name"], attrs["im_units"], attrs["im_label"]) == ("pga", "g", "PGA"),
              f"/fragility attributes {dict(attrs)}")
        check(out["samples/im"].attrs["units"] == "g", "/samples/im has no units")
        check(np.all(out["results/settled"][()] == 1), "a sample did not settle")

    cloud = study(files, {"type": "pgv", "scaling": "none", "scale": 1.5}, 30)
    with run_study(folder, cloud, "cloud") as out:
        record = out["samples/record"][()]
        im = out["samples/im"][()]
        check(np.all(out["samples/scale"][()] == 1.5), "a cloud sample not at the fixed scale")
        check(np.allclose(im, 1.5 * out["records/pgv_m_s"][()][record], rtol=1e-14, atol=0),
              "a cloud sample's intensity is not its record's PGV times 1.5")
        check(len(set(im)) == 3, f"{len(set(im))} distinct intensities from 3 records")
        state = out["fragility/rock_tenth"]
        check(state["trials"][()].sum() == 30, "the cloud's display bins do not hold every sample")
        check(str(out["fragility"].attrs["scaling"]).startswith("none"), "scaling attribute")
        check(state.attrs["fit_status"] in ("ok", "no_exceedances", "all_exceedances", "separated",
                                            "no_trend"), f"fit_status {state.attrs['fit_status']}")

print(f"{passed} passed, {failed} failed")
raise SystemExit(1 if failed else 0)
