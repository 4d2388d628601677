"""Writes the hazard files of this folder (README.md says what each is and which documentation
its layout follows). One curve, lambda(x) = 2e-3 (x / 0.1 g)^-2 exp(-0.25 ln^2(x / 0.1 g)) per
year, at OpenQuake's demo levels, written as each tool writes it:
  /usr/bin/python3 tests/data/hazard/make_hazard_files.py
"""

import json
import math
from pathlib import Path

HERE = Path(__file__).resolve().parent
LEVELS = [0.005, 0.007, 0.0098, 0.0137, 0.0192, 0.0269, 0.0376, 0.0527, 0.0738, 0.103, 0.145,
          0.203, 0.284, 0.397, 0.556, 0.778, 1.09, 1.52, 2.13]
YEARS = 50.0


def rate(x, scale=1.0):
    u = math.log(x / 0.1)
    return scale * 2e-3 * math.exp(-2.0 * u - 0.25 * u * u)


def poe(x, scale=1.0):
    return -math.expm1(-rate(x, scale) * YEARS)


def openquake(path, sites):
    # OpenQuake writes the metadata as a '#' line, the levels as poe-%.7f and poes as %.6E
    # (export_hcurves_by_imt_csv; the manual's "Outputs from Classical PSHA").
    header = "lon,lat,depth," + ",".join("poe-%.7f" % x for x in LEVELS)
    lines = ["#,,,,,\"generated_by='OpenQuake engine 3.18.0', start_date='2023-10-03T06:09:08', "
             "checksum=2107362341, kind='mean', investigation_time=%.1f, imt='PGA'\"" % YEARS,
             header]
    for lon, lat, scale in sites:
        lines.append("%.5f,%.5f,0.00000," % (lon, lat) +
                     ",".join("%.6E" % poe(x, scale) for x in LEVELS))
    path.write_text("\n".join(lines) + "\n")


def usgs(path):
    # nshmp-haz-ws HazardService: response[] per IMT, metadata.xvalues in g, data[] per component,
    # "Total" the sum, values to 8 significant digits (Util.DoubleSerializer, %.8g).
    def response(imt, display, scale):
        return {"metadata": {"edition": {"id": 0, "value": "E2014", "display": "Dynamic: ..."},
                             "region": {"id": 0, "value": "COUS", "display": "Conterminous U.S."},
                             "latitude": 46.1, "longitude": 11.1,
                             "imt": {"id": 0, "value": imt, "display": display},
                             "vs30": {"id": 0, "value": "760", "display": "760 m/s (B/C boundary)"},
                             "xlabel": "Ground Motion (g)",
                             "ylabel": "Annual Frequency of Exceedence",
                             "xvalues": LEVELS},
                "data": [{"component": "Fault", "yvalues": [float("%.8g" % (0.4 * rate(x, scale)))
                                                          for x in LEVELS]},
                         {"component": "Total", "yvalues": [float("%.8g" % rate(x, scale))
                                                          for x in LEVELS]}]}
    answer = {"status": "success", "date": "2024-01-01T00:00:00-07:00",
              "url": "https://earthquake.usgs.gov/nshmp-haz-ws/hazard/E2014/COUS/11.1/46.1/any/760",
              "response": [response("SA1P0", "1.00 Second Spectral Acceleration", 0.3),
                           response("PGA", "Peak Ground Acceleration", 1.0)]}
    path.write_text(json.dumps(answer, indent=2) + "\n")


def table(path):
    lines = ["# the curve of make_hazard_files.py: PGA (g), annual frequency of exceedance",
             "im_g,annual_frequency"]
    lines += ["%g,%.10g" % (x, rate(x)) for x in LEVELS]
    path.write_text("\n".join(lines) + "\n")


openquake(HERE / "hazard_curve-mean-PGA_1.csv", [(11.0, 46.0, 0.5), (11.1, 46.1, 1.0)])
openquake(HERE / "hazard_curve-high-PGA_2.csv", [(11.1, 46.1, 60.0)])
usgs(HERE / "usgs_hazard.json")
table(HERE / "plain_table.csv")
