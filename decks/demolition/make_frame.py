#!/usr/bin/env python3
"""Writes the parametric mesh of a plane frame with S storeys and B bays as a
collapse2d include file (frame_<S>x<B>.inc): nc elements per column storey,
nb >= 4 per beam bay, storey height hs and bay width bw, all deck parameters
set by the including deck. Materials: 1 columns, 2 beams; with L > 0, 3 the
columns of the lower L storeys (a building whose columns carry more below).

Usage: make_frame.py S B [L] > frame_SxB.inc
"""
import sys


def main():
    S, B = int(sys.argv[1]), int(sys.argv[2])
    lower = int(sys.argv[3]) if len(sys.argv) > 3 else 0
    args = f"{S} {B}" + (f" {lower}" if lower else "")
    line = f"(S*nc+1)".replace("S", str(S))  # nodes per column line
    out = []
    w = out.append
    w(f"! Plane frame, {S} storeys, {B} bays (written by make_frame.py {args}):")
    w("! storeys hs, bays bw, clamped column bases; nc elements per column storey,")
    w("! nb >= 4 per beam bay. Column line j (j = 0 .. %d, at x = j bw) has the" % B)
    w(f"! nodes 1 + j{line} ... from the base up: level i of line j is node")
    w(f"! 1 + j{line} + i nc. The beams' interior nodes follow. Elements:")
    w(f"! column line j, storey i (from 1): j {S} nc + (i-1) nc + 1 ... + nc;")
    w(f"! beams of level i, bay b (from 1): {B + 1}*{S}*nc + ((i-1) {B} + b - 1) nb + 1 ... + nb.")
    if lower:
        w(f"! Materials: 1 columns, 3 the columns of storeys 1-{lower}, 2 beams (set by the deck).")
    else:
        w("! Materials: 1 columns, 2 beams (set by the deck).")
    w("COORdinates")
    for j in range(B + 1):
        w(f"  1+{j}*{line} 1 {j}*bw 0")
        w(f"  {j + 1}*{line} 0 {j}*bw {S}*hs")
    base = f"{B + 1}*{line}"
    for i in range(1, S + 1):
        for b in range(B):
            k = (i - 1) * B + b
            first = f"{base}+1+{k}*(nb-1)"
            w(f"  {first} 1 {b}*bw+bw/nb {i}*hs")
            w(f"  {first}+nb-2 0 {b + 1}*bw-bw/nb {i}*hs")
    w("")
    w("ELEMents")
    for j in range(B + 1):
        e = f"1+{j}*{S}*nc"
        if lower:
            w(f"  {e} 1 3 1+{j}*{line} 2+{j}*{line}")
            w(f"  {e}+{lower}*nc-1 0 3 {lower}*nc+{j}*{line} {lower}*nc+1+{j}*{line}")
            w(f"  {e}+{lower}*nc 1 1 {lower}*nc+1+{j}*{line} {lower}*nc+2+{j}*{line}")
        else:
            w(f"  {e} 1 1 1+{j}*{line} 2+{j}*{line}")
        w(f"  {e}+{S}*nc-1 0 1 {j + 1}*{line}-1 {j + 1}*{line}")
    for i in range(1, S + 1):
        for b in range(B):
            k = (i - 1) * B + b
            e = f"{B + 1}*{S}*nc+1+{k}*nb"
            first = f"{base}+1+{k}*(nb-1)"
            left = f"1+{b}*{line}+{i}*nc"
            right = f"1+{b + 1}*{line}+{i}*nc"
            w(f"  {e} 0 2 {left} {first}")
            w(f"  {e}+1 1 2 {first} {first}+1")
            w(f"  {e}+nb-2 0 2 {first}+nb-3 {first}+nb-2")
            w(f"  {e}+nb-1 0 2 {first}+nb-2 {right}")
    w("")
    w("BOUNdary")
    for j in range(B + 1):
        w(f"  1+{j}*{line} 0 1 1 1")
    w("")
    print("\n".join(out))


main()
