#!/usr/bin/env python3
"""Writes docs/figures.md from the tables of the studies docs/figures/renew.sh ran.

usage: tables.py OUTDIR STEM... > docs/figures.md

For each study STEM (its <STEM>_ensemble.csv and <STEM>_plans.csv in OUTDIR,
as `collapse2d run` writes them) one section: per plan, its swept values,
the runs and failures, the debris figures as median (p10-p90) over the runs,
p_outside and p_felled with their 95 % Wilson intervals, and the CPU seconds
a run took (<STEM>_timing.csv). Distances in m, masses in t.
"""
import csv
import os
import statistics
import sys


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def spread(rows, column, digits=2):
    """median (p10-p90) of a plan's runs, as the plans table gives them."""
    med = num(rows.get(column + "_median"))
    lo, hi = num(rows.get(column + "_p10")), num(rows.get(column + "_p90"))
    if med is None:
        return "-"
    return f"{med:.{digits}f} ({lo:.{digits}f}-{hi:.{digits}f})"


def interval(row, name):
    p, lo, hi = num(row.get(name)), num(row.get(name + "_lo")), num(row.get(name + "_hi"))
    if p is None:
        return "-"
    return f"{p:.2f} [{lo:.2f}, {hi:.2f}]"


def swept(ensemble, plan):
    """The plan's swept values: the columns between stem and dt_factor."""
    header = list(ensemble[0].keys())
    names = header[header.index("stem") + 1 : header.index("dt_factor")]
    row = next(r for r in ensemble if r["plan"] == plan)
    return ", ".join(f"{n} = {row[n]}" for n in names) or "the deck's"


def section(outdir, stem):
    ensemble = read(os.path.join(outdir, stem + "_ensemble.csv"))
    plans = read(os.path.join(outdir, stem + "_plans.csv"))
    timing_path = os.path.join(outdir, stem + "_timing.csv")
    cpu = {}
    if os.path.exists(timing_path):
        for r in read(timing_path):
            vals = [num(v) for k, v in r.items() if k not in ("run", "plan", "sample")]
            cpu.setdefault(r.get("plan", "1"), []).append(vals[-1])
    lines = [f"## {stem}", ""]
    lines.append("| plan | runs (failed) | verdicts | furthest left | furthest right | "
                 "95 % left | 95 % right | centroid | pile height | mass beyond the site (t) | "
                 "p_outside | p_felled | CPU s a run |")
    lines.append("|" + "---|" * 13)
    for p in plans:
        runs = [r for r in ensemble if r["plan"] == p["plan"]]
        verdicts = {}
        for r in runs:
            v = r.get("verdict") or r.get("status")
            verdicts[v] = verdicts.get(v, 0) + 1
        v_text = ", ".join(f"{k} {n}" for k, n in sorted(verdicts.items()))
        c = cpu.get(p["plan"], [])
        c_text = f"{min(c):.1f}-{max(c):.1f}" if c else "-"
        lines.append(
            f"| {p['plan']}: {swept(ensemble, p['plan'])} | {p['samples']} ({p['failed']}) | {v_text} | "
            f"{spread(p, 'left')} | {spread(p, 'right')} | {spread(p, 'left95')} | "
            f"{spread(p, 'right95')} | {spread(p, 'centroid')} | {spread(p, 'height')} | "
            f"{spread(p, 'outside_mass')} | {interval(p, 'p_outside')} | "
            f"{interval(p, 'p_felled')} | {c_text} |")
    lines.append("")
    return lines


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    outdir, stems = sys.argv[1], sys.argv[2:]
    out = ["# Figures of the studies", "",
           "Written by `sh docs/figures/renew.sh` (do not edit): each study deck run",
           "whole, its plans' debris figures over their jittered runs, median",
           "(p10-p90), and the shares with their 95 % Wilson intervals. The",
           "documents quote their ranges from here. Distances in m from the",
           "footprint's edges (the centroid in the deck's x), masses in t.", ""]
    for stem in stems:
        out += section(outdir, stem)
    print("\n".join(out))


if __name__ == "__main__":
    main()
