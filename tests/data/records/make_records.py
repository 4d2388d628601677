#!/usr/bin/env python3
"""Writes the synthetic records of tests/data/records/ (not earthquakes: formulas the tests know).

Run from anywhere: python3 make_records.py. tests/unit/engine/accelerogram_test.cpp checks the values
against the same formulas, so a change here must change them there.
  decaying_sine.AT2  PEER NGA (NGA-West2 header), a(t) = 0.3 exp(-t) sin(4 pi t) g, DT 0.005 s,
                     NPTS 400 (2 s), 5 values per line in Fortran's 1P5E15.7 style.
  old_header.at2     the older PEER header ("NPTS, DT" after the numbers), lower-case extension,
                     plain notation, 3 values per line: a(t) = 0.1 - 0.5 t g, DT 0.01 s, NPTS 11.
  cosine_pulse.txt   two columns, a(t) = -0.4 cos(2 pi t / 0.5) g at t = 0, 0.01, ..., 0.5 s,
                     with comments, a blank line, and comma- as well as blank-separated lines.
"""
import math
import os

here = os.path.dirname(os.path.abspath(__file__))


def write(name, text):
    with open(os.path.join(here, name), "w", newline="\n") as f:
        f.write(text)


def decaying_sine(t):
    return 0.3 * math.exp(-t) * math.sin(4 * math.pi * t)


values = [decaying_sine(k * 0.005) for k in range(400)]
lines = ["PEER NGA STRONG MOTION DATABASE RECORD",
         "Synthetic decaying sine (blockfrag test data, not an earthquake), H1",
         "ACCELERATION TIME SERIES IN UNITS OF G",
         "NPTS=   400, DT=   .0050 SEC"]
for i in range(0, len(values), 5):
    lines.append("".join("%15.7E" % v for v in values[i:i + 5]))
write("decaying_sine.AT2", "\n".join(lines) + "\n")

values = [0.1 - 0.5 * k * 0.01 for k in range(11)]
lines = ["PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.",
         "Synthetic ramp, blockfrag test data",
         "ACCELERATION TIME HISTORY IN UNITS OF G",
         "   11    .0100    NPTS, DT"]
for i in range(0, len(values), 3):
    lines.append("  ".join("%.6f" % v for v in values[i:i + 3]))
write("old_header.at2", "\r\n".join(lines) + "\r\n")  # DOS line ends, as some old files have

lines = ["# time_s acceleration_g: a(t) = -0.4 cos(2 pi t / 0.5)", ""]
for k in range(51):
    t = k * 0.01
    separator = ", " if k % 2 else "\t"
    lines.append("%.2f%s%.10f" % (t, separator, -0.4 * math.cos(2 * math.pi * t / 0.5)))
    if k == 25:
        lines.append("# halfway")
write("cosine_pulse.txt", "\n".join(lines) + "\n")
