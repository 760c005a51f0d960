#!/usr/bin/env python3
"""Closed-form reference of cantilever_force.inp (paper Fig. 13).

Usage: cantilever_force_ref.py RUNDIR > cantilever_force.ref
The step schedule (the imposed tip displacements v, step cutting included) is
read from the run's time column; every other number is the closed form of the
discretized cantilever (see the deck header). The row of the located peak is
checked against the closed-form v_u, so a run that misplaces it fails here.
"""
import csv
import sys

L, EI, GA = 2.5, 77650.0, 1.25e6
Mc, My, Mu, Kh1, Kh2, Ks = 37.9, 268.0, 374.0, 29400.0, 272.0, -18000.0
MESHES = [10, 15, 20, 25]


def kappa(M):
    k = M / EI
    if M > Mc:
        k += (min(M, My) - Mc) / Kh1
    if M > My:
        k += (M - My) / Kh2
    return k


def mesh(n):
    l = L / n
    arms = [L - (i + 0.5) * l for i in range(n)]  # L - x_i
    Pu = Mu / (L - l / 2)
    vpre = lambda P: P * L / GA + l * sum(kappa(P * a) * a for a in arms)
    vu = vpre(Pu)
    C = L / GA + l * sum(a * a for a in arms) / EI
    slope = 1.0 / (C + (L - l / 2) ** 2 / Ks)
    vf = vu - Pu / slope
    return l, Pu, vu, slope, vf, vpre


def force(n, v, post):
    l, Pu, vu, slope, vf, vpre = mesh(n)
    if not post:
        lo, hi = 0.0, Pu
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if vpre(mid) < v else (lo, mid)
        return 0.5 * (lo + hi)
    return max(0.0, Pu + slope * (v - vu))


def main():
    rundir = sys.argv[1]
    print("# Closed form of the discretized cantilever (see the deck): pre-peak by")
    print("# inverting v(P), the located peak row (P_u, v_u), the post-peak line, P = 0")
    print("# from v_f on. The times are the run's step schedule; the numbers below are")
    print("# the closed form, not a run (written by cantilever_force_ref.py).")
    for k, n in enumerate(MESHES, 1):
        l, Pu, vu, slope, vf, _ = mesh(n)
        print(f"#   n = {n}: P_u = {Pu:.6f} kN, v_u = {vu:.6f} m, slope = {slope:.2f} kN/m, v_f = {vf:.6f} m")
    print("# rtol 1e-7")
    print("# atol 1e-6")
    for k, n in enumerate(MESHES, 1):
        l, Pu, vu, slope, vf, _ = mesh(n)
        name = f"cantilever_force_{k}_tplot.csv"
        with open(f"{rundir}/{name}") as f:
            rows = list(csv.reader(f))
        print(f"== {name} ==")
        print(",".join(rows[0]))
        times = [float(r[0]) for r in rows[1:]]
        peak = [i for i, t in enumerate(times) if abs(t - vu) < 1e-9]
        if len(peak) != 2:
            sys.exit(f"mesh {n}: the run has no located peak row at v_u = {vu:.10f}")
        for i, t in enumerate(times):
            P = Pu if i in peak else force(n, t, t > vu)
            if i in peak:
                t = vu
            print(",".join(f"{x:.10e}" for x in (t, t, t, P, P * (L - l / 2))))


main()
