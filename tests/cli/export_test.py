"""`blockfrag export` end to end on study outputs written here with h5py in the layout the study
writes (/fragility with its measure attributes and severity_order, one group per limit state with
median, beta, fit_status, type, threshold, the bootstrap intervals and the levels).

pelicun: fragility.csv's header and every value (ID, demand type and unit, each limit state's
family, median and beta in the order of severity), fragility.json's general information and limit
states. OpenQuake: the NRML 0.5 document's structure, the IMT and its unit (PGV in cm/s), the level
range, and median and beta recovered from mean and stddev to 1e-12. Refusals (exit 2, one clear
message, nothing written): the dimensionless measure, the pulse amplitude, Sa at 2 % damping, a
limit state without a fit (unless --fitted-only), a file that is not HDF5, an HDF5 file that is not
a study output, an output without /fragility, a missing file, a bad --id, a pelicun folder whose
parent is missing. --nested: the common-beta fit in both formats, a state outside it, outputs
without one or whose nested fit does not exist, a nested beta out of range. Prints "N passed,
M failed" last; exits non-zero on any failure.
"""

import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import traceback
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import numpy as np

SOURCE = Path(os.environ.get("BLOCKFRAG_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BLOCKFRAG = os.environ.get("BLOCKFRAG", str(SOURCE / "build" / "mpi_driver" / "blockfrag"))
NRML = "{http://openquake.org/xmlns/nrml/0.5}"
HASH = "0123456789abcdef"

LEVELS = [0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0]
# Names whose alphabetical order is not their order of severity, so the export must follow
# severity_order. Medians increase in that order.
STATES = [
    {"name": "slide_2cm", "type": "residual_slide", "threshold": 0.02, "median": 0.8912345678901234,
     "beta": 0.3141592653589793},
    {"name": "rock.half", "type": "max_rotation", "threshold": 0.5, "median": 1.234567890123,
     "beta": 0.55},
    {"name": "a_overturn", "type": "overturning", "threshold": 0.0, "median": 1.9876543210987654,
     "beta": 0.2718281828459045},
]


def run(*args):
    return subprocess.run([BLOCKFRAG, "export", *map(str, args)], capture_output=True, text=True,
                          timeout=120)


def write_output(path, im_name="pga", im_units="g", im_label="PGA", states=None, levels=None,
                 period=None, damping=None, severity=True, fragility=True, marked=True,
                 crossing_pairs=None, nested=None):
    states = STATES if states is None else states
    levels = LEVELS if levels is None else levels
    with h5py.File(path, "w") as f:
        if marked:
            f.attrs["config"] = '{"seed": 1}'
            f.attrs["config_hash"] = HASH
        f.create_dataset("samples/im", data=np.repeat(levels, 3))
        if not fragility:
            return
        g = f.create_group("fragility")
        g.attrs["im_name"] = im_name
        g.attrs["im_units"] = im_units
        g.attrs["im_label"] = im_label
        if period is not None:
            g.attrs["im_period_s"] = period
            g.attrs["im_damping"] = damping
        if severity:
            g.attrs["severity_order"] = ",".join(s["name"] for s in states)
        if crossing_pairs is not None:
            g.attrs["crossing_pairs"] = crossing_pairs
        if nested is not None:  # (status, beta, {name: median})
            g.attrs["nested_status"] = nested[0]
            g.attrs["nested_beta"] = nested[1]
        for s in states:
            h = g.create_group(s["name"])
            fitted = s.get("fit_status", "ok") == "ok"
            h.attrs["median"] = s["median"] if fitted else math.nan
            h.attrs["beta"] = s["beta"] if fitted else math.nan
            h.attrs["fit_status"] = s.get("fit_status", "ok")
            h.attrs["type"] = s["type"]
            h.attrs["threshold"] = s["threshold"]
            h.attrs["median_ci"] = np.array([0.9, 1.1]) * (s["median"] if fitted else math.nan)
            h.attrs["beta_ci"] = np.array([0.8, 1.25]) * (s["beta"] if fitted else math.nan)
            h.attrs["deviance"] = 4.5
            h.attrs["gof_p_value"] = 0.61
            if "overturned_exceeds" in s:
                h.attrs["overturned_exceeds"] = np.int64(s["overturned_exceeds"])
            h.create_dataset("im", data=np.array(levels, dtype=float))
            if nested is not None:
                h.attrs["nested_median"] = nested[2].get(s["name"], math.nan)
            h.create_dataset("probability", data=np.linspace(0.0, 1.0, len(levels)))


def assert_refused(result, *fragments):
    assert result.returncode == 2, f"exit code {result.returncode}, not 2: {result.stderr!r}"
    for fragment in fragments:
        assert fragment in result.stderr, f"stderr lacks {fragment!r}: {result.stderr!r}"
    assert len(result.stderr.strip().splitlines()) <= 2, f"a long error:\n{result.stderr}"


def assert_ok(result):
    assert result.returncode == 0, f"exit code {result.returncode}: {result.stderr!r}"


def read_pelicun(folder):
    with open(folder / "fragility.csv", newline="") as f:
        rows = list(csv.reader(f))
    with open(folder / "fragility.json") as f:
        model = json.load(f)
    return rows, model


def read_openquake(path):
    root = ET.parse(path).getroot()
    assert root.tag == NRML + "nrml", root.tag
    [model] = list(root)
    assert model.tag == NRML + "fragilityModel", model.tag
    return model


def recovered(mean, stddev):
    """Median and beta from OpenQuake's mean and stddev of the measure."""
    ratio_squared = (stddev / mean) ** 2
    return mean / math.sqrt(1.0 + ratio_squared), math.sqrt(math.log1p(ratio_squared))


def assert_close(value, expected, what, relative=1e-12):
    assert abs(value - expected) <= relative * abs(expected), f"{what}: {value!r} != {expected!r}"


def check_pelicun_row(rows, demand_type, demand_unit, identifier="BF.BLOCK." + HASH, states=None):
    states = STATES if states is None else states
    header = ["ID", "Incomplete", "Demand-Type", "Demand-Unit", "Demand-Offset",
              "Demand-Directional"]
    for k in range(1, len(states) + 1):
        header += [f"LS{k}-Family", f"LS{k}-Theta_0", f"LS{k}-Theta_1"]
    assert rows[0] == header, rows[0]
    assert len(rows) == 2, rows
    row = dict(zip(rows[0], rows[1]))
    assert len(rows[1]) == len(header), rows[1]
    assert row["ID"] == identifier and row["Incomplete"] == "0", row
    assert row["Demand-Type"] == demand_type and row["Demand-Unit"] == demand_unit, row
    assert row["Demand-Offset"] == "0" and row["Demand-Directional"] == "1", row
    for k, s in enumerate(states, start=1):
        assert row[f"LS{k}-Family"] == "lognormal", row
        assert float(row[f"LS{k}-Theta_0"]) == s["median"], (row, s)  # exact: shortest round trip
        assert float(row[f"LS{k}-Theta_1"]) == s["beta"], (row, s)


def test_pelicun_pga(work):
    write_output(work / "s.h5")
    assert_ok(run(work / "s.h5", "--format", "pelicun", "--output", work / "dl"))
    rows, model = read_pelicun(work / "dl")
    check_pelicun_row(rows, "Peak Ground Acceleration", "g")
    info = model["_GeneralInformation"]
    for key in ("ShortName", "Description", "Version", "ComponentGroups"):
        assert info[key], key
    assert HASH in info["ShortName"]
    entry = model["BF.BLOCK." + HASH]
    assert "PGA" in entry["Description"] and entry["Comments"], entry
    assert entry["LimitStates"] == {
        "LS1": {"DS1": {"Description": "slide_2cm: residual slide > 0.02 m"}},
        "LS2": {"DS2": {"Description": "rock.half: max |theta| > 0.5 alpha, or overturned"}},
        "LS3": {"DS3": {"Description": "a_overturn: overturned"}},
    }, entry["LimitStates"]
    assert list(model) == ["_GeneralInformation", "BF.BLOCK." + HASH], list(model)


def test_pelicun_pgv_and_sa(work):
    write_output(work / "v.h5", im_name="pgv", im_units="m/s", im_label="PGV")
    assert_ok(run(work / "v.h5", "--format", "pelicun", "--output", work / "v", "--id", "X.Y_1"))
    check_pelicun_row(read_pelicun(work / "v")[0], "Peak Ground Velocity", "mps", "X.Y_1")
    write_output(work / "a.h5", im_name="sa", im_label="Sa(1 s, 5 %)", period=1.0, damping=0.05)
    assert_ok(run(work / "a.h5", "--format", "pelicun", "--output", work / "a"))
    check_pelicun_row(read_pelicun(work / "a")[0], "Peak Spectral Acceleration|1.0", "g")
    write_output(work / "b.h5", im_name="sa", im_label="Sa(0.2 s, 5 %)", period=0.2, damping=0.05)
    assert_ok(run(work / "b.h5", "--format", "pelicun", "--output", work / "b"))
    check_pelicun_row(read_pelicun(work / "b")[0], "Peak Spectral Acceleration|0.2", "g")


def check_openquake(path, imt, scale, identifier="BF.BLOCK." + HASH, states=None):
    states = STATES if states is None else states
    model = read_openquake(path)
    assert model.get("id") == identifier.replace(".", "_"), model.attrib
    assert model.get("lossCategory") == "structural" and model.get("assetCategory"), model.attrib
    description = model.find(NRML + "description")
    assert description is not None and description.text.strip(), "no description"
    names = model.find(NRML + "limitStates").text.split()
    assert names == [s["name"] for s in states], names
    [function] = model.findall(NRML + "fragilityFunction")
    assert function.attrib == {"id": identifier, "format": "continuous", "shape": "logncdf"}, \
        function.attrib
    children = list(function)
    imls = children[0]
    assert imls.tag == NRML + "imls", imls.tag
    assert imls.get("imt") == imt, imls.attrib
    assert_close(float(imls.get("minIML")), min(LEVELS) * scale, "minIML")
    assert_close(float(imls.get("maxIML")), max(LEVELS) * scale, "maxIML")
    assert float(imls.get("noDamageLimit")) == 0.0, imls.attrib
    params = children[1:]
    assert [p.tag for p in params] == [NRML + "params"] * len(states)
    assert [p.get("ls") for p in params] == names
    for p, s in zip(params, states):
        mean, stddev = float(p.get("mean")), float(p.get("stddev"))
        median, beta = recovered(mean, stddev)
        assert_close(median, s["median"] * scale, f"{s['name']} median")
        assert_close(beta, s["beta"], f"{s['name']} beta")
        # The forward conversion as the brief states it.
        assert_close(mean, s["median"] * scale * math.exp(s["beta"] ** 2 / 2), "mean", 1e-14)


def test_openquake_pga_pgv_sa(work):
    write_output(work / "s.h5")
    assert_ok(run(work / "s.h5", "--format", "openquake", "--output", work / "pga.xml"))
    check_openquake(work / "pga.xml", "PGA", 1.0)
    write_output(work / "v.h5", im_name="pgv", im_units="m/s", im_label="PGV")
    assert_ok(run(work / "v.h5", "--format", "openquake", "--output", work / "pgv.xml"))
    check_openquake(work / "pgv.xml", "PGV", 100.0)  # m/s to cm/s
    assert "(cm/s)" in read_openquake(work / "pgv.xml").find(NRML + "description").text
    write_output(work / "a.h5", im_name="sa", im_label="Sa(1 s, 5 %)", period=1.0, damping=0.05)
    assert_ok(run(work / "a.h5", "--format", "openquake", "--output", work / "sa.xml"))
    check_openquake(work / "sa.xml", "SA(1.0)", 1.0)


def test_rerun_replaces_the_files(work):
    write_output(work / "s.h5")
    for _ in range(2):
        assert_ok(run(work / "s.h5", "--format", "openquake", "--output", work / "m.xml"))
        assert_ok(run(work / "s.h5", "--format", "pelicun", "--output", work / "dl"))
    check_openquake(work / "m.xml", "PGA", 1.0)
    assert sorted(p.name for p in work.iterdir()) == ["dl", "m.xml", "s.h5"], list(work.iterdir())
    assert sorted(p.name for p in (work / "dl").iterdir()) == ["fragility.csv", "fragility.json"]


def test_without_severity_order_by_median(work):
    write_output(work / "s.h5", states=list(reversed(STATES)), severity=False)
    assert_ok(run(work / "s.h5", "--format", "pelicun", "--output", work / "dl"))
    check_pelicun_row(read_pelicun(work / "dl")[0], "Peak Ground Acceleration", "g")


def test_overturned_blocks_and_crossing_fits(work):
    """overturned_exceeds (the study's newer outputs) decides whether a state's meaning says
    "or overturned"; crossing fits of two exported states are noted on stderr."""
    states = [dict(STATES[0], overturned_exceeds=1), dict(STATES[1], overturned_exceeds=0),
              dict(STATES[2], overturned_exceeds=1)]
    write_output(work / "s.h5", states=states, crossing_pairs="slide_2cm,rock.half")
    result = run(work / "s.h5", "--format", "pelicun", "--output", work / "dl")
    assert_ok(result)
    assert "slide_2cm and rock.half cross" in result.stderr, result.stderr
    entry = read_pelicun(work / "dl")[1]["BF.BLOCK." + HASH]
    assert entry["LimitStates"]["LS1"]["DS1"]["Description"] == \
        "slide_2cm: residual slide > 0.02 m, or overturned", entry
    assert entry["LimitStates"]["LS2"]["DS2"]["Description"] == \
        "rock.half: max |theta| > 0.5 alpha", entry
    write_output(work / "t.h5", crossing_pairs="")
    result = run(work / "t.h5", "--format", "openquake", "--output", work / "m.xml")
    assert_ok(result)
    assert "cross" not in result.stderr, result.stderr


NESTED_MEDIANS = {"slide_2cm": 0.95, "rock.half": 1.25, "a_overturn": 1.9}


def test_nested_exports_the_common_beta_fit(work):
    """--nested: each state's nested_median with the common nested_beta, in both formats, the
    descriptions saying so, no crossing note; a state outside it is left out or refused; an
    output without a nested fit, or whose nested fit does not exist, is refused."""
    write_output(work / "s.h5", crossing_pairs="slide_2cm,rock.half",
                 nested=("ok", 0.45, NESTED_MEDIANS))
    common = [dict(s, median=NESTED_MEDIANS[s["name"]], beta=0.45) for s in STATES]
    result = run(work / "s.h5", "--format", "pelicun", "--output", work / "dl", "--nested")
    assert_ok(result)
    assert "cross" not in result.stderr, result.stderr
    rows, model = read_pelicun(work / "dl")
    check_pelicun_row(rows, "Peak Ground Acceleration", "g", states=common)
    assert "one common beta" in model["_GeneralInformation"]["Description"]
    assert_ok(run(work / "s.h5", "--format", "openquake", "--output", work / "m.xml", "--nested"))
    check_openquake(work / "m.xml", "PGA", 1.0, states=common)
    assert "one common beta" in read_openquake(work / "m.xml").find(NRML + "description").text
    # Without --nested, the same file exports the separate fits as before.
    assert_ok(run(work / "s.h5", "--format", "pelicun", "--output", work / "sep"))
    check_pelicun_row(read_pelicun(work / "sep")[0], "Peak Ground Acceleration", "g")

    partial = dict(NESTED_MEDIANS)
    del partial["a_overturn"]
    write_output(work / "p.h5", nested=("ok", 0.45, partial))
    assert_refused(run(work / "p.h5", "--format", "pelicun", "--output", work / "p", "--nested"),
                   "a_overturn (fit_status: not in the nested fit")
    assert_ok(run(work / "p.h5", "--format", "pelicun", "--output", work / "p", "--nested",
                  "--fitted-only"))
    check_pelicun_row(read_pelicun(work / "p")[0], "Peak Ground Acceleration", "g",
                      states=common[:2])
    write_output(work / "old.h5")
    assert_refused(run(work / "old.h5", "--format", "pelicun", "--output", work / "o", "--nested"),
                   "old.h5: has no nested fit")
    write_output(work / "none.h5", nested=("the common beta's maximum lies at the search bound",
                                           math.nan, {}))
    assert_refused(run(work / "none.h5", "--format", "openquake", "--output", work / "n.xml",
                       "--nested"), "none.h5: its nested fit does not exist (the common beta's")
    write_output(work / "wide.h5", nested=("ok", 40.0, NESTED_MEDIANS))
    assert_refused(run(work / "wide.h5", "--format", "openquake", "--output", work / "w.xml",
                       "--nested"), "wide.h5: /fragility has nested_status \"ok\" but nested_beta 40")


def test_dimensionless_measure_is_refused(work):
    write_output(work / "s.h5", im_name="pga_over_g_tan_alpha", im_units="1",
                 im_label="PGA/(g tan alpha)")
    assert_refused(run(work / "s.h5", "--format", "pelicun", "--output", work / "dl"),
                   "s.h5", "PGA/(g tan alpha)", "dimensionless")
    assert_refused(run(work / "s.h5", "--format", "openquake", "--output", work / "m.xml"),
                   "s.h5", "dimensionless")
    assert not (work / "dl").exists() and not (work / "m.xml").exists()


def test_pulse_amplitude_and_damping_are_refused(work):
    write_output(work / "p.h5", im_name="pulse_amplitude", im_label="pulse amplitude")
    assert_refused(run(work / "p.h5", "--format", "openquake", "--output", work / "m.xml"),
                   "p.h5", "pulse amplitude")
    write_output(work / "d.h5", im_name="sa", im_label="Sa(1 s, 2 %)", period=1.0, damping=0.02)
    assert_refused(run(work / "d.h5", "--format", "pelicun", "--output", work / "dl"),
                   "d.h5", "2 %", "5 %")
    assert not (work / "dl").exists() and not (work / "m.xml").exists()


def test_unfitted_state_refused_or_left_out(work):
    states = [dict(STATES[0]), dict(STATES[1], fit_status="no exceedance at any level"),
              dict(STATES[2])]
    write_output(work / "s.h5", states=states)
    assert_refused(run(work / "s.h5", "--format", "pelicun", "--output", work / "dl"),
                   "rock.half", "no exceedance at any level", "--fitted-only")
    assert not (work / "dl").exists()
    result = run(work / "s.h5", "--format", "pelicun", "--output", work / "dl", "--fitted-only")
    assert_ok(result)
    assert "left out" in result.stderr and "rock.half" in result.stderr, result.stderr
    kept = [STATES[0], STATES[2]]
    check_pelicun_row(read_pelicun(work / "dl")[0], "Peak Ground Acceleration", "g", states=kept)
    assert_ok(run(work / "s.h5", "--format", "openquake", "--output", work / "m.xml",
                  "--fitted-only"))
    check_openquake(work / "m.xml", "PGA", 1.0, states=kept)


def test_files_that_are_not_outputs(work):
    (work / "notes.txt").write_text("not HDF5\n")
    assert_refused(run(work / "notes.txt", "--format", "pelicun", "--output", work / "dl"),
                   "notes.txt", "not an HDF5 file")
    write_output(work / "other.h5", marked=False)
    assert_refused(run(work / "other.h5", "--format", "openquake", "--output", work / "m.xml"),
                   "other.h5", "not a blockfrag study output")
    write_output(work / "bare.h5", fragility=False)
    assert_refused(run(work / "bare.h5", "--format", "openquake", "--output", work / "m.xml"),
                   "bare.h5", "/fragility")
    assert_refused(run(work / "absent.h5", "--format", "pelicun", "--output", work / "dl"),
                   "absent.h5", "no such file")
    assert_refused(run(work, "--format", "pelicun", "--output", work / "dl"), "folder")
    assert not (work / "dl").exists() and not (work / "m.xml").exists()


def test_bad_options_and_outputs(work):
    write_output(work / "s.h5")
    assert_refused(run(work / "s.h5", "--format", "pelicun", "--output", work / "dl", "--id",
                       "BF-1"), "--id")
    assert_refused(run(work / "s.h5", "--format", "csv", "--output", work / "dl"), "--format")
    assert_refused(run(work / "s.h5", "--format", "pelicun", "--output", work / "no" / "dl"),
                   "does not exist")
    assert_ok(run(work / "s.h5", "--format", "pelicun", "--output", str(work / "slash") + "/"))
    assert (work / "slash" / "fragility.csv").is_file()
    assert_refused(run(work / "s.h5", "--format", "openquake", "--output", work / "no" / "m.xml"),
                   "does not exist")
    assert_refused(run(work / "s.h5", "--format", "openquake", "--output", work / "s.h5"),
                   "study output")
    assert not (work / "no").exists()
    with h5py.File(work / "s.h5") as f:  # the study output is untouched
        assert f.attrs["config_hash"] == HASH


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
