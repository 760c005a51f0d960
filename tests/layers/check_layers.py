#!/usr/bin/env python3
"""The house's one-way rule as a check: every #include "..." of the library's
sources points down or sideways, never up.

Floors, top to bottom: macro > solvers > elements > materials > core (a floor
includes its own and the ones below it). Inside macro/ the wings stack the
same way: python > the deck runner and main (macro/*.{h,cpp}) > batch >
studies > solution > run > mesh > draws > deck > output. The includes listed in
KNOWN_UPWARD would be upward arrows the tree still has (none now); the list may
only shrink: an upward include that is not on it fails the check, and an entry
that no longer exists fails it too (so that a mended arrow is taken off the
list).

    python3 tests/layers/check_layers.py [ROOT]      # check the tree (default: the repository)
    python3 tests/layers/check_layers.py --self-test # shows that a planted upward include fails
"""
import os
import re
import sys
import tempfile

FLOORS = ["core", "materials", "elements", "solvers", "macro"]
MACRO_WINGS = ["macro/output", "macro/deck", "macro/draws", "macro/mesh", "macro/run",
               "macro/solution", "macro/studies", "macro/batch", "macro", "macro/python"]

# (including file, included file): upward includes inside macro/ the tree still has.
KNOWN_UPWARD = set()

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def rank(path):
    """(floor, wing) of a repository-relative path; None outside the library."""
    parts = path.split("/")
    if parts[0] not in FLOORS:
        return None
    floor = FLOORS.index(parts[0])
    wing = 0
    if parts[0] == "macro":
        folder = "/".join(parts[:2]) if len(parts) > 2 else "macro"
        wing = MACRO_WINGS.index(folder) if folder in MACRO_WINGS else len(MACRO_WINGS)
    return floor, wing


def upward_includes(root):
    found = set()
    for floor in FLOORS:
        for dirpath, _, files in os.walk(os.path.join(root, floor)):
            for name in files:
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.relpath(os.path.join(dirpath, name), root).replace(os.sep, "/")
                with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                    text = f.read()
                here = rank(path)
                for inc in INCLUDE.findall(text):
                    there = rank(inc)
                    if there is not None and there > here:
                        found.add((path, inc))
    return found


def check(root, known):
    found = upward_includes(root)
    bad = sorted(found - known)
    gone = sorted(known - found)
    for path, inc in bad:
        print(f"{path}: includes {inc}, a file of a higher floor or wing")
    for path, inc in gone:
        print(f"{path} no longer includes {inc}: take it off KNOWN_UPWARD in {__file__}")
    if bad:
        print(f"the order: {' < '.join(FLOORS)}; inside macro: {' < '.join(MACRO_WINGS)}")
    print(f"layers: {len(found)} upward includes, {len(known)} known, "
          f"{len(bad)} new, {len(gone)} mended")
    return not bad and not gone


def self_test():
    with tempfile.TemporaryDirectory() as root:
        for folder in ["core", "solvers"]:
            os.makedirs(os.path.join(root, folder))
        with open(os.path.join(root, "solvers", "S.h"), "w") as f:
            f.write('#pragma once\n#include "core/C.h"\n')
        with open(os.path.join(root, "core", "C.h"), "w") as f:
            f.write("#pragma once\n")
        if not check(root, set()):
            print("self-test: a tree with only downward includes failed")
            return False
        with open(os.path.join(root, "core", "C.h"), "a") as f:
            f.write('#include "solvers/S.h"\n')
        if check(root, set()):
            print("self-test: a planted upward include (core -> solvers) passed")
            return False
    print("self-test: a planted upward include fails the check")
    return True


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(0 if self_test() else 1)
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    sys.exit(0 if check(os.path.abspath(root), KNOWN_UPWARD) else 1)
