"""The Python module against the command line: the same tables to the bit,
deck errors with their location, parameters given from Python, and the
README's study across two decks."""

import os
import re
import signal
import subprocess
import sys
import time

import numpy as np
import pandas as pd
import pytest

import collapse2d

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXE = os.environ.get("C2D_EXE", os.path.join(ROOT, "build", "collapse2d"))
BLOCK = os.path.join(HERE, "block.inp")
STUDY = os.path.join(HERE, "block_study.inp")


def command_line(deck, out, *given):
    args = [EXE, "-q", "-o", str(out)]
    for name, value in given:
        args += ["--set", "%s=%r" % (name, value)]
    done = subprocess.run(args + [deck], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return out


def read(path):
    return pd.read_csv(path, float_precision="round_trip")


def reach(a, mu, g=9.81, t1=0.5):
    """Where the sliding block stops beyond its footprint (block.inp)."""
    v0 = a * g * t1
    return a * g * t1 ** 2 / 2 + v0 ** 2 / (2 * mu * g)


def test_a_run_gives_the_command_lines_tables_to_the_bit(tmp_path):
    cli = command_line(BLOCK, tmp_path / "cli", ("mu", 0.3))
    r = collapse2d.run(BLOCK, params={"mu": 0.3}, out=tmp_path / "py")
    assert r.runs == ["block"]
    for name in ("block_tplot.csv", "block_debris.csv"):
        assert (cli / name).read_bytes() == (tmp_path / "py" / name).read_bytes()
    pd.testing.assert_frame_equal(r.tplot, read(cli / "block_tplot.csv"), check_exact=True)
    pd.testing.assert_frame_equal(r.debris.reset_index(drop=True), read(cli / "block_debris.csv"),
                                  check_exact=True)
    assert isinstance(r.column("time"), np.ndarray)
    # The given mu took the deck's place: the reach is the closed form's for mu = 0.3
    # (the friction spring and the stopping step leave less than 1e-3 m).
    assert r.debris.loc["block", "right"] == pytest.approx(reach(0.4, 0.3), abs=1e-3)
    assert "given: mu = 0.3" in r.log
    assert r.summary["steps"] > 0 and r.summary["runs"] == 1
    assert r.summary["text"] in r.console


def test_a_study_gives_the_command_lines_tables_to_the_bit(tmp_path):
    cli = command_line(STUDY, tmp_path / "cli", ("n", 2))
    r = collapse2d.run(STUDY, params={"n": 2})
    assert len(r.runs) == 4 and len(r.tplots) == 4
    for table, name in ((r.ensemble, "ensemble"), (r.plans, "plans"), (r.sensitivity, "sensitivity")):
        expected = read(cli / ("block_study_%s.csv" % name))
        timing = [c for c in expected.columns if c in ("cpu_seconds",)]
        pd.testing.assert_frame_equal(table.drop(columns=timing), expected.drop(columns=timing),
                                      check_exact=True)
    for stem in r.runs:
        pd.testing.assert_frame_equal(r.tplots[stem], read(cli / (stem + "_tplot.csv")),
                                      check_exact=True)
    # Each run reaches the closed form's figure for its plan's a, its drawn mu and
    # its incline time (500 steps scaled by the drawn dt_factor).
    for _, row in r.ensemble.iterrows():
        a = 0.3 if row.plan == 1 else 0.4
        assert row.right == pytest.approx(reach(a, row.mu, t1=0.5 * row.dt_factor), abs=1e-3)


def test_a_deck_error_carries_its_location(tmp_path):
    deck = tmp_path / "bad.inp"
    text = open(BLOCK).read().replace("INCLude,../../decks", "INCLude," + ROOT + "/decks")
    deck.write_text(text.replace("  mu = 0.4 ", "  mu = 0.4 * nosuch "))
    with pytest.raises(collapse2d.DeckError) as e:
        collapse2d.run(deck)
    line = text.splitlines().index("  mu = 0.4            ! the ground's Coulomb coefficient") + 1
    assert (e.value.file, e.value.line, e.value.column) == (str(deck), line, 14)
    assert str(e.value).startswith("%s:%d:14: error:" % (deck, line))
    assert "nosuch" in str(e.value)


def test_a_name_the_deck_does_not_assign_is_refused(tmp_path):
    with pytest.raises(ValueError, match=r"'mux' is given .* did you mean 'mu'"):
        collapse2d.run(BLOCK, params={"mux": 0.3}, out=tmp_path)
    with pytest.raises(ValueError, match="finite"):
        collapse2d.run(BLOCK, params={"mu": float("nan")}, out=tmp_path)


def test_a_swept_name_is_refused_at_its_record(tmp_path):
    with pytest.raises(collapse2d.DeckError, match="swept by this study") as e:
        collapse2d.run(STUDY, params={"a": 0.2}, out=tmp_path)
    assert e.value.line == open(STUDY).read().splitlines().index("  a = 0.3 0.4") + 1


def readme_example():
    text = open(os.path.join(ROOT, "README.md")).read()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "the README shows a Python example"
    return blocks[0]


def test_the_readmes_study_across_two_decks(capsys):
    code = readme_example()
    assert len(code.strip().splitlines()) <= 15
    cwd = os.getcwd()
    os.chdir(ROOT)
    try:
        scope = {}
        exec(compile(code, "README.md", "exec"), scope)
    finally:
        os.chdir(cwd)
    table = scope["table"]
    assert isinstance(table, pd.DataFrame)
    assert set(table["deck"]) == {"first_felling", "gsa_strong"}
    assert table.notna().all().all()
    assert "first_felling" in capsys.readouterr().out


def test_sigint_stops_a_run_and_keeps_its_outputs(tmp_path):
    # A run that never ends by itself (tests/cli/endless.inp), in a Python of
    # its own: SIGINT stops it at its next step as KeyboardInterrupt.
    deck = os.path.join(ROOT, "tests", "cli", "endless.inp")
    script = ("import collapse2d\n"
              "try:\n"
              "    collapse2d.run(%r, out=%r)\n"
              "except KeyboardInterrupt as e:\n"
              "    print('stopped:', e)\n" % (deck, str(tmp_path)))
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    first = tmp_path / "endless_0001.vtu"
    for _ in range(600):
        if first.exists():
            break
        time.sleep(0.1)
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=60)
    assert child.returncode == 0
    assert "stopped:" in out and "interrupted by SIGINT at step" in out
    assert (tmp_path / "endless.interrupted.out").exists()
    assert not (tmp_path / "endless.out").exists()
