"""`blockfrag risk` end to end on a small real study (the example study at 40 samples a level):

- Cornell et al. (2002): against a power-law hazard k0 x^-k written as OpenQuake writes a curve
  (probabilities of exceedance in 1 year, %.6E, levels as poe-%.7f), the lognormal fit's lambda
  is k0 theta^-k exp(k^2 beta^2 / 2) to 1e-4, for each fitted limit state;
- one curve as OpenQuake's CSV (row 1 of two sites), the USGS service's JSON (its PGA response of
  two) and a plain table (tests/data/hazard) gives one lambda, fit and points, to 1e-5;
- an OpenQuake curve with poe = 1 at its eight lowest levels starts at the ninth and says so;
- the bins and the motions past the curve make up lambda; the interval holds lambda and comes
  from the study's resamples; the probabilities are 1 - exp(-lambda t);
- two studies weighted 0.25 and 0.75 give the weighted sum of their lambdas;
- risk.csv has a row per limit state and method with the JSON's numbers;
- the study's common-beta fit is stored (in order, its beta among the separate ones) and
  `export --nested` writes it, read back from OpenQuake's mean and stddev to 1e-12;
- configs/hazard's real sites are what its script writes, and each site is read (poe = 1 at the
  lowest levels of Los Angeles and San Francisco).
Prints "N passed, M failed" last; exits non-zero on any failure.
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

SOURCE = Path(os.environ.get("BLOCKFRAG_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BLOCKFRAG = os.environ.get("BLOCKFRAG", str(SOURCE / "build" / "mpi_driver" / "blockfrag"))
HAZARD = SOURCE / "tests" / "data" / "hazard"


def run(*args):
    result = subprocess.run([BLOCKFRAG, *map(str, args)], capture_output=True, text=True,
                            timeout=600)
    if result.returncode != 0:
        raise AssertionError(f"blockfrag {' '.join(map(str, args))}: exit {result.returncode}: "
                             f"{result.stderr[-500:]}")
    return result


def small_study(folder, name, seed):
    study = json.loads((SOURCE / "configs" / "example_study.json").read_text())
    study.update({"samples_per_level": 40, "seed": seed, "output": name,
                  "bootstrap_resamples": 100})
    study["intensity_measure"].update({"from": 0.3, "to": 2.4, "count": 8})
    config = folder / (name + ".json")
    config.write_text(json.dumps(study))
    run("run", config, "--output", folder / name)
    return folder / name


def risk(study, hazard, folder, *extra):
    """`blockfrag risk` of one study output, or of a list of its arguments (--study ...)."""
    studies = study if isinstance(study, list) else [study]
    out = folder / "risk.json"
    table = run("risk", *studies, "--hazard", hazard, "--output", out, "--csv", folder / "risk.csv",
                *extra)
    return json.loads(out.read_text()), table.stdout


def power_law_openquake(path, k0, k, low, high, count=45):
    levels = sorted({round(low * (high / low) ** (i / (count - 1)), 7) for i in range(count)})
    lines = ["#,,,,,\"generated_by='OpenQuake engine 3.18.0', kind='mean', "
             "investigation_time=1.0, imt='PGA'\"",
             "lon,lat,depth," + ",".join("poe-%.7f" % x for x in levels),
             "11.10000,46.10000,0.00000," +
             ",".join("%.6E" % -math.expm1(-k0 * x ** -k) for x in levels)]
    path.write_text("\n".join(lines) + "\n")


def fitted_states(report):
    return [s for s in report["limit_states"] if s["fit"] is not None]


def check_cornell(study, folder):
    with h5py.File(study, "r") as f:
        fits = {name: (g.attrs["median"], g.attrs["beta"]) for name, g in f["fragility"].items()
                if g.attrs["fit_status"] == "ok"}
    assert fits, "the small study has no fitted limit state"
    k0, k = 1e-4, 2.5
    for name, (theta, beta) in fits.items():
        hazard = folder / "power_law.csv"
        power_law_openquake(hazard, k0, k, theta * math.exp(-(k * beta + 6.5) * beta),
                            theta * math.exp(7.0 * beta))
        report, _ = risk(study, hazard, folder)
        state = next(s for s in report["limit_states"] if s["name"] == name)
        exact = k0 * theta ** -k * math.exp(0.5 * k * k * beta * beta)
        error = abs(state["fit"]["lambda"] / exact - 1)
        print(f"  Cornell check, {name}: theta {theta:.4g}, beta {beta:.4g}: lambda "
              f"{state['fit']['lambda']:.6e}, closed form {exact:.6e}, relative error {error:.1e}")
        assert error < 1e-4, (name, state["fit"]["lambda"], exact)


def check_same_curve(study, folder):
    lambdas = []
    for hazard, extra in [(HAZARD / "hazard_curve-mean-PGA_1.csv", ["--site", "1"]),
                          (HAZARD / "usgs_hazard.json", []),
                          (HAZARD / "plain_table.csv", ["--imt", "PGA"])]:
        report, _ = risk(study, hazard, folder, *extra)
        assert report["hazard"]["imt"] == "PGA"
        lambdas.append({s["name"]: (s["fit"] and s["fit"]["lambda"], s["points"]["lambda"])
                        for s in report["limit_states"]})
    for other in lambdas[1:]:
        for name, (fit, points) in lambdas[0].items():
            if fit is not None:
                assert abs(other[name][0] / fit - 1) < 1e-5, (name, fit, other[name][0])
            assert abs(other[name][1] / points - 1) < 1e-5, (name, points, other[name][1])


def check_poe_one(study, folder):
    report, table = risk(study, HAZARD / "hazard_curve-high-PGA_2.csv", folder)
    hazard = report["hazard"]
    assert hazard["levels_at_poe_one"] == 8, hazard["levels_at_poe_one"]
    assert hazard["im"][0] == 0.0738, hazard["im"][0]
    assert "its 8 lower levels have poe = 1" in table and "from 0.0738" in table, table
    for state in report["limit_states"]:
        assert math.isfinite(state["points"]["lambda"])


def check_report(study, folder):
    report, _ = risk(study, HAZARD / "hazard_curve-mean-PGA_1.csv", folder, "--site", "1")
    assert report["blockfrag_risk"] == 1 and report["years"] == [1.0, 50.0, 100.0]
    assert len(report["hazard"]["im"]) == 19 and report["hazard"]["site"] == "lon 11.10000, lat 46.10000"
    rows = list(csv.DictReader(line for line in (folder / "risk.csv").read_text().splitlines()
                               if not line.startswith("#")))
    for state in report["limit_states"]:
        for method in ("fit", "points"):
            estimate = state[method]
            if estimate is None:
                continue
            bins = sum(estimate["bin_lambda"]) + estimate["lambda_beyond_hazard"]
            assert abs(bins / estimate["lambda"] - 1) < 1e-12, (state["name"], method)
            assert estimate["interval_note"] == "", estimate["interval_note"]
            assert estimate["interval_resamples"] > 50, estimate["interval_resamples"]
            assert estimate["lambda_low"] <= estimate["lambda"] <= estimate["lambda_high"]
            for p in estimate["probability_in_years"]:
                assert abs(p["probability"] + math.expm1(-estimate["lambda"] * p["years"])) < 1e-15
            row = next(r for r in rows if r["limit_state"] == state["name"] and
                       r["method"] == method)
            assert row["scope"] == "combined"
            assert float(row["lambda"]) == estimate["lambda"]
            assert float(row["p_50yr"]) == estimate["probability_in_years"][1]["probability"]
    assert len(rows) == sum((s["fit"] is not None) + 1 for s in report["limit_states"])


def check_weighted(study, other, folder):
    hazard = HAZARD / "usgs_hazard.json"
    one, _ = risk(study, hazard, folder)
    two, _ = risk(other, hazard, folder)
    both, _ = risk(["--study", f"{study}:0.25", "--study", f"{other}:0.75"], hazard, folder)
    assert [s["weight"] for s in both["studies"]] == [0.25, 0.75]
    for a, b, c in zip(one["limit_states"], two["limit_states"], both["limit_states"]):
        expected = 0.25 * a["points"]["lambda"] + 0.75 * b["points"]["lambda"]
        assert abs(c["points"]["lambda"] / expected - 1) < 1e-12, c["name"]
        if a["fit"] and b["fit"]:
            expected = 0.25 * a["fit"]["lambda"] + 0.75 * b["fit"]["lambda"]
            assert abs(c["fit"]["lambda"] / expected - 1) < 1e-12, c["name"]


def check_real_sites(study, folder):
    """configs/hazard's file is what its script writes, and each of its sites is read."""
    script = SOURCE / "configs" / "hazard" / "make_usgs_2008_sites.py"
    committed = (SOURCE / "configs" / "hazard" / "usgs_2008_wus_pga_sites.csv").read_text()
    copy = folder / "make_usgs_2008_sites.py"
    copy.write_text(script.read_text())
    subprocess.run([sys.executable, copy], check=True, timeout=60)
    assert (folder / "usgs_2008_wus_pga_sites.csv").read_text() == committed
    at_poe_one = []
    for site in range(4):
        report, _ = risk(study, SOURCE / "configs" / "hazard" / "usgs_2008_wus_pga_sites.csv",
                         folder, "--site", site)
        at_poe_one.append(report["hazard"]["levels_at_poe_one"])
        # Salt Lake City's lowest rate, 0.118372651 a year, read back from poe in 50 years.
        if site == 3:
            assert abs(report["hazard"]["annual_rate"][0] / 0.118372651 - 1) < 1e-5
    # Los Angeles and San Francisco round to poe = 1 at their lowest levels.
    assert at_poe_one == [3, 2, 0, 0], at_poe_one


def check_nested_fit(study, folder):
    """The study stores its common-beta fit beside the separate ones, and export --nested writes
    it: every fitted state's nested_median in order of severity with one beta, read back from
    OpenQuake's mean and stddev."""
    with h5py.File(study, "r") as f:
        g = f["fragility"]
        assert g.attrs["nested_status"] == "ok", g.attrs["nested_status"]
        names = g.attrs["nested_states"].split(",")
        fitted = [n for n in g.attrs["severity_order"].split(",")
                  if g[n].attrs["fit_status"] == "ok"]
        assert names == fitted, (names, fitted)
        beta = g.attrs["nested_beta"]
        medians = [g[n].attrs["nested_median"] for n in names]
        assert medians == sorted(medians), medians
        assert 0 < g.attrs["nested_beta_se"] < 0.2 * beta
        # The common beta lies among the separate ones.
        betas = [g[n].attrs["beta"] for n in names]
        assert min(betas) <= beta <= max(betas), (beta, betas)
    run("export", study, "--format", "openquake", "--output", folder / "nested.xml", "--nested")
    params = [e for e in ET.parse(folder / "nested.xml").iter() if e.tag.endswith("params")]
    assert [p.get("ls") for p in params] == names
    for p, median in zip(params, medians):
        mean, stddev = float(p.get("mean")), float(p.get("stddev"))
        ratio = (stddev / mean) ** 2
        assert abs(mean / math.sqrt(1 + ratio) / median - 1) < 1e-12
        assert abs(math.sqrt(math.log1p(ratio)) / beta - 1) < 1e-12


def main():
    passed = failed = 0
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        study = small_study(folder, "small.h5", 20261121)
        other = small_study(folder, "other.h5", 7)
        checks = [("Cornell's closed form", lambda: check_cornell(study, folder)),
                  ("one curve in three formats", lambda: check_same_curve(study, folder)),
                  ("poe = 1 at low levels", lambda: check_poe_one(study, folder)),
                  ("JSON and CSV", lambda: check_report(study, folder)),
                  ("weighted studies", lambda: check_weighted(study, other, folder)),
                  ("real sites' curves", lambda: check_real_sites(study, folder)),
                  ("nested fit stored and exported", lambda: check_nested_fit(study, folder))]
        for name, check in checks:
            try:
                check()
                passed += 1
                print(f"ok: {name}")
            except Exception:
                failed += 1
                print(f"FAILED: {name}")
                traceback.print_exc()
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
