#!/usr/bin/env python3
"""Numbers for the header of six_story_schemes*.ref (paper Figs 25-28).

Usage: six_story_schemes_ref.py RUNDIR STEM T0 T1
Reads RUNDIR/STEM_*_tplot.csv (each scheme's run) and prints, for the
collapse-phase window T0 <= t <= T1 of each run, the reaction force H at the
top left node: its mean, its range (max - min) and the high-frequency
amplitude max |H_k - (H_k-1 + H_k+1)/2| / 2 (half the largest second
difference of consecutive output rows: zero for a smooth curve, the amplitude
for an oscillation that flips sign from one output row to the next), and the
first time the ground carries a force (contact energy above zero).
"""
import csv
import glob
import os
import sys


def main():
    rundir, stem, t0, t1 = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    files = sorted(glob.glob(os.path.join(rundir, stem + "_*_tplot.csv")))
    order = {"1": 0, "2": 1}
    files.sort(key=lambda f: (order.get(f[len(os.path.join(rundir, stem)) + 1:-10], 2), f))
    print("# window %g <= t <= %g: H mean, range max-min, high-frequency amplitude (kN); first contact" % (t0, t1))
    for f in files:
        run = f[len(os.path.join(rundir, stem)) + 1:-10]
        name = {"1": "Newmark (1/4, 1/2)", "2": "conserving"}.get(run, "decaying " + run)
        rows = list(csv.DictReader(open(f)))
        reac = [k for k in rows[0] if k.startswith("reac_")][0]
        th = [(float(r["time"]), float(r[reac])) for r in rows]
        w = [h for t, h in th if t0 <= t <= t1]
        hf = max(abs(w[k] - 0.5 * (w[k - 1] + w[k + 1])) / 2 for k in range(1, len(w) - 1))
        touch = next((float(r["time"]) for r in rows if float(r["contact"]) > 0), None)
        print("#   %-22s mean %9.2f  range %8.2f  hf %8.2f%s" %
              (name, sum(w) / len(w), max(w) - min(w), hf,
               "" if touch is None else "  contact from t = %.2f" % touch))


main()
