#!/usr/bin/env python3
"""Closed-form reference of cantilever_moment_axial.inp (paper Fig. 11).

Usage: cantilever_moment_axial_ref.py RUNDIR > cantilever_moment_axial.ref
The step schedule (time t, tip rotation t theta_f) is read from the run's time
column, the factors of the load tables (prop_1, prop_2) from the run's too; every other number is the closed form (see the deck header): the
moment-rotation curve of Fig. 8, the tip shortening N L/EA, the axial force -N.
The located row at Mu is checked against the closed-form time.
"""
import csv
import sys

L, EI, EA, N = 2.5, 77650.0, 3.6e6, 100.0
SETS = [  # Mc, My, Mu, Kh1, Kh2, Ks
    (37.9, 268.0, 274.0, 29400.0, 272.0, -18000.0),
    (55.0, 395.0, 401.0, 35000.0, 352.0, -26000.0),
]


def curve(Mc, My, Mu, Kh1, Kh2, Ks):
    kp_u = (My - Mc) / Kh1 + (Mu - My) / Kh2
    thf = L * kp_u + Mu / -Ks
    # pre-peak theta(M) = L kappa(M): piecewise linear, inverted branch by branch
    th_c, th_y = L * Mc / EI, L * (My / EI + (My - Mc) / Kh1)
    th_u = L * (Mu / EI + kp_u)

    def moment(th, post):
        if post:
            return max(0.0, (th - L * kp_u + Mu / Ks) / (L / EI + 1 / Ks))
        if th <= th_c:
            return EI * th / L
        if th <= th_y:
            return Mc + (th - th_c) / (L * (1 / EI + 1 / Kh1))
        return My + (th - th_y) / (L * (1 / EI + 1 / Kh2))

    return thf, th_u, moment


def main():
    rundir = sys.argv[1]
    print("# Closed form (see the deck): the moment-rotation curve of Fig. 8 for each data")
    print("# set, unchanged by the axial force; tip axial displacement -N L/EA =")
    print(f"# {-N * L / EA:.6e} m and axial force -N = {-N:g} kN in every row. The times are the")
    print("# run's step schedule; the numbers are the closed form, not a run (written by")
    print("# cantilever_moment_axial_ref.py).")
    print("# rtol 1e-7")
    print("# atol 1e-6")
    for k, s in enumerate(SETS, 1):
        thf, th_u, moment = curve(*s)
        tu = th_u / thf
        name = f"cantilever_moment_axial_{k}_tplot.csv"
        with open(f"{rundir}/{name}") as f:
            rows = list(csv.reader(f))
        print(f"== {name} ==")
        print(",".join(rows[0]))
        times = [float(r[0]) for r in rows[1:]]
        tables = [i for i, c in enumerate(rows[0]) if c.startswith("prop_")]
        peak = [i for i, t in enumerate(times) if abs(t - tu) < 1e-9]
        if len(peak) != 2:
            sys.exit(f"set {k}: no located row at t = {tu:.10f}")
        for i, t in enumerate(times):
            if i in peak:
                t, M = tu, s[2]
            else:
                M = moment(t * thf, t > tu)
            factors = tuple(float(rows[i + 1][c]) for c in tables)
            values = (t, t) + factors + (-N * L / EA, t * thf, M, -N, M)
            print(",".join(f"{x:.10e}" for x in values))


main()
