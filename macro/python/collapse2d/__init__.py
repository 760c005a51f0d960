"""collapse2d from Python: run a deck or a study, get its tables as pandas.

    import collapse2d
    r = collapse2d.run("decks/demolition/first_felling.inp", params={"delay": 0.2})
    r.debris                # the debris row of each run (DataFrame, one row a run)
    r.tplot["time"]         # the time history of the (first) run
    r.summary["steps"]      # the run's summary, as the log gives it

run() calls the command line's deck runner in this process (collapse2d._core):
the run writes the files `collapse2d -o OUT --set NAME=VALUE DECK` writes,
and the tables are read back from them with every digit they carry, so a
number here is the command line's number to the bit.
"""

import math
import os
import re
import signal
import tempfile
from collections.abc import Mapping

import numpy as np
import pandas as pd

from . import _core

__all__ = ["run", "Result", "Error", "DeckError", "AnalysisError"]


class Error(RuntimeError):
    """A run that could not be made or finished (the message says why)."""


class DeckError(Error):
    """A mistake in the deck, found before anything is computed.

    .file, .line, .column: where it is (1-based), as the command line's
    "file:line:col: error: ..." says.
    """

    def __init__(self, message, file, line, column):
        super().__init__(message)
        self.file, self.line, self.column = file, line, column


class AnalysisError(Error):
    """A failed analysis (no convergence, a singular tangent), or runs of a study
    that failed: .result holds the study's tables then (None otherwise)."""

    def __init__(self, message, result=None):
        super().__init__(message)
        self.result = result


def _read_csv(path):
    # round_trip: the text's shortest digits back to the very double written.
    return pd.read_csv(path, float_precision="round_trip")


_RUN_LINE = re.compile(r"^  run (\d+) of (\d+), outputs (\S+)", re.M)


class _Tables(Mapping):
    """{run stem: DataFrame} of a per-run table (<stem><suffix>), each read when
    first asked for: a study of hundreds of runs reads only what is used."""

    def __init__(self, out, stems, suffix):
        self._paths = {s: os.path.join(out, s + suffix) for s in stems}
        self._paths = {s: p for s, p in self._paths.items() if os.path.exists(p)}
        self._read = {}

    def __getitem__(self, stem):
        if stem not in self._read:
            self._read[stem] = _read_csv(self._paths[stem])
        return self._read[stem]

    def __iter__(self):
        return iter(self._paths)

    def __len__(self):
        return len(self._paths)


class Result:
    """What a deck's run wrote, as tables.

    out      the folder of the outputs (a temporary one, removed with this
             object, when run() was given none)
    stem     the deck's stem; runs: the output stems of its runs, in run order
    tplot    the time history (TPLOt) of the first run: DataFrame, or None
    tplots   {run stem: DataFrame} of every run that wrote one (read when asked)
    debris   the debris row of every run that has one: DataFrame indexed by
             run stem, or None
    ensemble the ensemble's table (<stem>_ensemble.csv), plans: the plans table
             (<stem>_plans.csv), sensitivity (<stem>_sensitivity.csv): DataFrame
             or None when the deck wrote none
    summary  the summary of the deck (over all its runs): dict of its counts and
             figures, "text" as the log prints it, "runs", "failed_runs"
    console  what the command line prints on standard output (summaries,
             the study's verdict); warnings: the deck's warnings
    log      the text of the log <stem>.out
    """

    def __init__(self, deck, out, outcome, keep=None):
        self.deck = deck
        self.out = out
        self._keep = keep  # the temporary folder, removed with this object
        self.stem = os.path.splitext(os.path.basename(deck))[0]
        self.console = outcome["console"]
        self.warnings = list(outcome["warnings"])
        self.summary = dict(outcome["summary"])
        self.summary["runs"] = outcome["runs"]
        self.summary["failed_runs"] = outcome["failed_runs"]
        self.log = self._text(self.stem + ".out")
        self.runs = [m.group(3) for m in _RUN_LINE.finditer(self.log or "")]
        self.tplots = _Tables(out, self.runs, "_tplot.csv")
        self.ensemble = self._table("_ensemble.csv")
        self.plans = self._table("_plans.csv")
        self.sensitivity = self._table("_sensitivity.csv")
        self.debris = self._debris()

    @property
    def tplot(self):
        return next(iter(self.tplots.values()), None)

    def _text(self, name):
        path = os.path.join(self.out, name)
        if not os.path.exists(path):
            return None
        with open(path, encoding="utf-8") as f:
            return f.read()

    def _table(self, suffix):
        path = os.path.join(self.out, self.stem + suffix)
        return _read_csv(path) if os.path.exists(path) else None

    def _debris(self):
        rows = _Tables(self.out, self.runs, "_debris.csv")
        stems = list(rows)
        if not stems:
            return None
        table = pd.concat([rows[s] for s in stems], ignore_index=True)
        table.index = pd.Index(stems, name="stem")
        return table

    def column(self, name):
        """A column of the first run's time history as a numpy array."""
        return np.asarray(self.tplot[name])

    def __repr__(self):
        return "<collapse2d.Result %s: %d run%s in %s>" % (
            self.stem, len(self.runs), "" if len(self.runs) == 1 else "s", self.out)


def _given(params):
    given = {}
    for name, value in (params or {}).items():
        if not isinstance(name, str):
            raise TypeError("params: a name is a string, not %r" % (name,))
        x = float(value)
        if not math.isfinite(x):
            raise ValueError("params: %s = %r is not a finite number" % (name, value))
        given[name] = x
    return given


def run(deck, params=None, out=None, solver="auto"):
    """Runs a deck (a lone run, a SWEEp, an ENSEmble) as the command line does.

    params: {name: value} given in place of the values the deck's PARAmeter
    records assign (the command line's --set NAME=VALUE); a name no record
    assigns is a ValueError, a name the deck's SWEEp or ENSEmble sets for each
    run a DeckError. out: the folder for the outputs (created), or None for a
    temporary one. Raises DeckError (with .file .line .column) for a mistake in
    the deck, AnalysisError for a failed analysis, KeyboardInterrupt when
    SIGINT stopped the run (its outputs kept as <stem>.interrupted.*).
    """
    deck = os.fspath(deck)
    keep = None
    if out is None:
        keep = tempfile.TemporaryDirectory(prefix="collapse2d-")
        out = keep.name
    out = os.fspath(out)
    o = _core.run_deck(deck, _given(params), out, solver)
    code, message = o["exit_code"], o["message"]
    if o["interrupted"]:
        if o["interrupted"] == signal.SIGINT:
            raise KeyboardInterrupt(message)
        signal.raise_signal(o["interrupted"])  # SIGTERM: as Python's own handler would
        raise Error(message)
    if code == 1 and "error_at" in o:
        file, line, column = o["error_at"]
        raise DeckError(message, file, line, column)
    if code == 64:
        raise ValueError(message)
    if code == 2:
        result = Result(deck, out, o, keep) if o["failed_runs"] else None
        raise AnalysisError(message, result)
    if code != 0:
        raise Error(message)
    return Result(deck, out, o, keep)
