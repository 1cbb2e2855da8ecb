#!/usr/bin/env python3
"""Where in the Couette annulus the velocity error sits: |v_theta - v_theta,exact| / (omega R_i)
binned in rings between R_i and R_o (rms and mean per ring), from couette_profile.csv files.

    /usr/bin/python3 scripts/couette_rings.py [--rings 6] LABEL=RUN_DIR [LABEL=RUN_DIR ...]

R_i = 0.025, R_o = 0.040, omega R_i = 0.025 m/s: cases/couette.yaml.
"""
import csv
import math
import os
import sys

RI, RO, UREF = 0.025, 0.040, 0.025
args = sys.argv[1:]
rings = 6
if args and args[0] == "--rings":
    rings, args = int(args[1]), args[2:]
for arg in args:
    label, run = arg.split("=", 1)
    acc = [[0.0, 0.0, 0] for _ in range(rings)]
    tot, n = 0.0, 0
    for r in csv.DictReader(open(os.path.join(run, "couette_profile.csv"))):
        e = (float(r["v_theta"]) - float(r["v_theta_exact"])) / UREF
        k = min(rings - 1, max(0, int((float(r["r"]) - RI) / (RO - RI) * rings)))
        acc[k][0] += e
        acc[k][1] += e * e
        acc[k][2] += 1
        tot += e * e
        n += 1
    print(f"{label}: L2 = {math.sqrt(tot / n):.5f}")
    print("  rms : " + " ".join(f"{math.sqrt(a[1] / a[2]):.4f}" for a in acc))
    print("  mean: " + " ".join(f"{a[0] / a[2]:+.4f}" for a in acc))
