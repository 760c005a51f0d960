#!/usr/bin/env python3
"""Writes the parametric mesh of a plane frame with S storeys and B bays as a
collapse2d include file (frame_<S>x<B>.inc): nc elements per column storey,
nb >= 4 per beam bay, storey height hs and bay width bw, all deck parameters
set by the including deck. Materials: 1 columns, 2 beams; with L > 0, 3 the
columns of the lower L storeys (a building whose columns carry more below).
With --core b, bay b (from 1) is a core: its column lines are the core's
flange walls (material 4), a web wall on the bay's axis (material 5, two
elements a storey, its base clamped) is tied at every floor to the bay's beam
middle node (nb even), and the bay's beams are the arms between web and
flanges (material 6).

Usage: make_frame.py S B [L] [--core b] > frame_SxB[_core].inc
"""
import sys


def main():
    argv = sys.argv[1:]
    core = 0
    if "--core" in argv:
        k = argv.index("--core")
        core = int(argv[k + 1])
        del argv[k:k + 2]
    S, B = int(argv[0]), int(argv[1])
    lower = int(argv[2]) if len(argv) > 2 else 0
    if core and not 1 <= core <= B:
        sys.exit(f"make_frame.py: --core {core} is not a bay of 1..{B}")
    args = f"{S} {B}" + (f" {lower}" if lower else "") + (f" --core {core}" if core else "")
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
    nodes = f"{B + 1}*{line}+{S}*{B}*(nb-1)"  # column and beam nodes
    elems = f"{B + 1}*{S}*nc+{S}*{B}*nb"  # column and beam elements
    if core:
        w(f"! Bay {core} is a core: lines {core - 1} and {core} are its flange walls (material 4),")
        w(f"! its beams the arms between web and flanges (material 6); the web")
        w(f"! (material 5) on x = {core - 1}.5 bw: base node {nodes}+1, the node at")
        w(f"! mid-storey i {nodes}+1+i, the beams' middle nodes at the floors;")
        w(f"! storey i: elements {elems}+2 i-1 and {elems}+2 i.")
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
    if core:
        xc = f"{core - 1}*bw+bw/2"
        w(f"  {nodes}+1 1 {xc} 0")
        w(f"  {nodes}+1+{S} 0 {xc} {S}*hs-hs/2")
        w(f"  {nodes}+2 1 {xc} hs/2")
    w("")
    w("ELEMents")
    for j in range(B + 1):
        e = f"1+{j}*{S}*nc"
        if core and j in (core - 1, core):
            w(f"  {e} 1 4 1+{j}*{line} 2+{j}*{line}")
            w(f"  {e}+{S}*nc-1 0 4 {j + 1}*{line}-1 {j + 1}*{line}")
            continue
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
            m = 6 if b + 1 == core else 2
            w(f"  {e} 0 {m} {left} {first}")
            w(f"  {e}+1 1 {m} {first} {first}+1")
            w(f"  {e}+nb-2 0 {m} {first}+nb-3 {first}+nb-2")
            w(f"  {e}+nb-1 0 {m} {first}+nb-2 {right}")
    if core:
        for i in range(1, S + 1):
            below = f"{nodes}+1" if i == 1 else middle(B, core, i - 1, base)
            mid = f"{nodes}+{i + 1}"
            w(f"  {elems}+{2 * i - 1} 0 5 {below} {mid}")
            w(f"  {elems}+{2 * i} 0 5 {mid} {middle(B, core, i, base)}")
    w("")
    w("BOUNdary")
    for j in range(B + 1):
        w(f"  1+{j}*{line} 0 1 1 1")
    if core:
        w(f"  {nodes}+1 0 1 1 1")
    w("")
    print("\n".join(out))


def middle(B, core, i, base):
    """The middle node of the core bay's beam at floor i (nb even)."""
    k = (i - 1) * B + core - 1
    return f"{base}+1+{k}*(nb-1)+nb/2-1"


main()
