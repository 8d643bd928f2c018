"""`run` and `sweep`: what `handspring run FILE` and `handspring sweep FILE` compute, in process
through the harness library (hs_scenario_* and hs_scenario_sweep); nothing is shelled out."""

import ctypes
import os

import numpy as np

from . import _capi, _cfile
from ._capi import text
from ._errors import HandspringError
from .scenario import Scenario, Trajectory


class RunResult:
    """One run to its end. `status` 0 when every expectation passed, else 1 (the tool's exit
    status; bad input raises HandspringError instead of 2). `report`: hs_scenario_check's lines;
    `failed`, `total`: expectation lines failed and judged; `final_hash`: the state hash after
    the last frame (int); `trajectory`: a Trajectory from the first frame run (0, or the frame a
    `resume` state is at) to the end; `state`: the bytes saved at `save_at` (else None)."""

    def __init__(self, scenario, trajectory, state, resumed):
        s = scenario
        self.name, self.description, self.dt = s.name, s.description, s.dt
        self.frames, self.objects, self.warnings = s.frame, len(s.object_names), s.warnings
        fits = [(h, s.hand_fit(i)) for i, h in enumerate(s.hand_names)]
        self.hand_fits = [(h, fit) for h, fit in fits if fit]  # hands fitted to a joint recording
        self.failed, self.report = s.check()
        self.total = s.expectation_count
        self.final_hash = s.hash()
        self.status = 1 if self.failed else 0
        self.trajectory, self.state, self.resumed = trajectory, state, resumed

    @property
    def passed(self):
        return self.status == 0

    @property
    def summary(self):
        """The text `handspring run FILE` prints on stdout (as run without --out, --state-out or
        --resume, whose lines name files)."""
        lines = ["scenario: %s" % self.name, "  %s" % self.description,
                 "frames:   %d (dt %.9g s, %.9g s)" % (self.frames, self.dt, self.frames * self.dt),
                 "objects:  %d" % self.objects]
        lines += ["hand %s: fitted from %d samples of %s: RMS %.1f mm" % (h, n, rec, rms)
                  for h, (rms, n, rec) in self.hand_fits]
        lines += self.report
        lines += ["expectations: %d/%d passed" % (self.total - self.failed, self.total),
                  "final hash: %016x" % self.final_hash, "FAIL" if self.failed else "PASS"]
        return "\n".join(lines) + "\n"


def _state_bytes(resume):
    if isinstance(resume, (bytes, bytearray, memoryview)):
        return bytes(resume)
    with open(os.fspath(resume), "rb") as f:
        return f.read()


def run(path, *, dt=None, noise_seed=None, phase=None, model=None, save_at=None, resume=None):
    """`handspring run FILE`: loads the scenario, runs it to its end recording every frame, and
    judges its `expect` clauses. `save_at=F` keeps the whole state at frame F (result.state, the
    bytes --state-out writes); `resume` (bytes or a state file's path) continues a saved run
    from its frame. dt, noise_seed, phase and model as Scenario's; like the tool's, they do not go
    with save_at or resume."""
    if (save_at is not None or resume is not None) and (dt is not None or noise_seed is not None or phase or model):
        raise ValueError("dt, noise_seed, phase and model do not go with save_at or resume")
    with Scenario(path, dt=dt, noise_seed=noise_seed, phase=phase, model=model) as s:
        if resume is not None:
            s.load_state(_state_bytes(resume))
        if save_at is not None and not s.frame <= save_at <= s.frame_count:
            raise ValueError("save_at must be within [%d, %d] (the scenario's frames), got %r"
                             % (s.frame, s.frame_count, save_at))
        start = s.frame
        state = None
        if save_at is not None:
            first = s.record(save_at - start)
            state = s.save_state()
            traj = _join(first, s.record())
        else:
            traj = s.record()
        return RunResult(s, traj, state, resume is not None)


def _join(a, b):
    """a then b without b's first row (the frame a ends on)."""
    out = Trajectory(0, a.position.shape[1])
    for key in ("frame", "t", "position", "orientation", "contact", "floor_contacts", "resting", "hash"):
        setattr(out, key, np.concatenate([getattr(a, key), getattr(b, key)[1:]]))
    return out


class SweepResult:
    """A scenario's robust matrix (hs_scenario_sweep). `text`: the table the tool prints; `dts`:
    the frame times as written in the file (rows); `seeds`: the noise seeds 1..S (columns);
    `cells`: (rows, S) array of str, each `ok`, `L<line>` (the first failing robust clause) or
    `fault`; `nominal`: the nominal run's cell; `passed`, `total`: cells that pass and cells;
    `status`: 0 when every cell and the nominal run pass, else 1."""

    def __init__(self, status, table):
        self.status, self.text = status, table
        lines = table.splitlines()
        header = lines[1].split()
        self.seeds = [int(k) for k in header[1:]]
        rows = [ln.split() for ln in lines[2:] if not ln.startswith(("nominal ", "sweep: "))]
        self.dts = [r[0] for r in rows]
        self.cells = np.array([r[1:] for r in rows], dtype=str).reshape(len(rows), len(self.seeds))
        self.nominal = lines[-2].rsplit(": ", 1)[1]
        words = lines[-1].split()  # sweep: N of M cells pass
        self.passed, self.total = int(words[1]), int(words[3])

    @property
    def ok(self):
        return self.status == 0


def sweep(path):
    """`handspring sweep FILE`: the nominal run, then every dt of the `robust` block x seeds with
    the input noise on. Bad input (a missing file, no robust block) raises HandspringError."""
    lib = _capi.api()
    err = _capi.Error()
    with _cfile.writer() as (stream, sink):
        status = lib.hs_scenario_sweep(os.fspath(path).encode(), stream, ctypes.byref(err))
    if status == 2:
        raise HandspringError(text(err.message))
    return SweepResult(status, sink.data.decode("utf-8", "replace"))
