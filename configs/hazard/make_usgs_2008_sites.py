"""Writes usgs_2008_wus_pga_sites.csv: real sites' PGA hazard curves in OpenQuake's hazard-curve
CSV layout, for `blockfrag risk` (docs/risk.md).

The rates are the USGS 2008 National Seismic Hazard Model for the western U.S. (nshm-cous-2008,
"Western US"), at Vs30 = 760 m/s, computed by nshmp-haz and published with it as the output of
its example 7 (usgs/nshmp-haz, etc/example_outputs/7-deaggregation/curves/PGA/total.csv: mean
annual rates of exceeding each PGA in g, config valueFormat ANNUAL_RATE, 3-sigma truncation).
They are copied here digit for digit. OpenQuake writes probabilities of exceedance in an
investigation time: this file gives poe = 1 - exp(-50 lambda) in 50 years (%.6E, as OpenQuake
writes them), so blockfrag reads lambda = -ln(1 - poe) / 50 back to about 6 digits where poe is
well below 1 and to fewer where it nears 1 (below about 0.05 g, where a block's fragility is
nil); the lowest levels of Los Angeles and San Francisco round to poe = 1.
  /usr/bin/python3 configs/hazard/make_usgs_2008_sites.py
"""

import math
from pathlib import Path

LEVELS = [0.0025, 0.0045, 0.0075, 0.0113, 0.0169, 0.0253, 0.038, 0.057, 0.0854, 0.128, 0.192,
          0.288, 0.432, 0.649, 0.973, 1.46, 2.19, 3.28, 4.92, 7.38]
SITES = [
    ("Los Angeles CA", -118.25, 34.05, [
        5.65751194e-01, 4.60546107e-01, 3.52846533e-01, 2.68589324e-01, 1.96755851e-01,
        1.38892991e-01, 9.39674734e-02, 6.03017357e-02, 3.61972876e-02, 2.02823160e-02,
        1.07017814e-02, 5.31887461e-03, 2.43349159e-03, 9.74954193e-04, 3.19112149e-04,
        7.58898203e-05, 1.14905519e-05, 6.54934393e-07, 4.68235108e-09, 0.0]),
    ("San Francisco CA", -122.40, 37.75, [
        4.71018566e-01, 3.93716939e-01, 3.09117253e-01, 2.40097649e-01, 1.79647813e-01,
        1.29860376e-01, 9.04036218e-02, 6.05001871e-02, 3.87023382e-02, 2.32276107e-02,
        1.25730376e-02, 5.82377769e-03, 2.17157469e-03, 6.04494779e-04, 1.16423839e-04,
        1.24763554e-05, 3.73529672e-07, 1.99530753e-11, 0.0, 0.0]),
    ("Seattle WA", -122.30, 47.60, [
        2.69671478e-01, 2.30162962e-01, 1.85618866e-01, 1.46901945e-01, 1.10435218e-01,
        7.85153992e-02, 5.26618453e-02, 3.33893493e-02, 1.98538443e-02, 1.08676865e-02,
        5.36030565e-03, 2.34281054e-03, 8.87134086e-04, 2.76822930e-04, 6.71347073e-05,
        1.14010802e-05, 1.34458466e-06, 9.12484497e-08, 3.14297684e-09, 0.0]),
    ("Salt Lake City UT", -111.90, 40.75, [
        1.18372651e-01, 9.26583008e-02, 6.79587911e-02, 4.97197671e-02, 3.48310659e-02,
        2.33579362e-02, 1.50498993e-02, 9.46729372e-03, 5.91766902e-03, 3.74488527e-03,
        2.42836494e-03, 1.57813005e-03, 9.53003203e-04, 4.81412575e-04, 1.85472023e-04,
        4.97447528e-05, 8.14238060e-06, 5.88373967e-07, 1.73749728e-09, 0.0]),
]
YEARS = 50.0

lines = ["#,,,,,\"generated_by='blockfrag configs/hazard/make_usgs_2008_sites.py from the USGS "
         "2008 NSHM (WUS, Vs30 760 m/s) rates of nshmp-haz example 7', kind='mean', "
         "investigation_time=%.1f, imt='PGA'\"" % YEARS,
         "custom_site_id,lon,lat,depth," + ",".join("poe-%.7f" % x for x in LEVELS)]
for name, lon, lat, rates in SITES:
    site_id = name.split()[0][:3].upper() + name.split()[-1]
    lines.append("%s,%.5f,%.5f,0.00000," % (site_id, lon, lat) +
                 ",".join("%.6E" % -math.expm1(-YEARS * rate) for rate in rates))
Path(__file__).with_name("usgs_2008_wus_pga_sites.csv").write_text("\n".join(lines) + "\n")
