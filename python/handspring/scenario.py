"""A scenario file loaded into a world: step it, read its objects, hash, save and load its state."""

import ctypes
import os

import numpy as np

from . import _capi, _cfile
from ._capi import text
from ._errors import HandspringError

SEED_MAX = 4294967295


def _model_text(model):
    """A `model:` override as the YAML mapping text the loader reads ({key: value, ...})."""
    if isinstance(model, str):
        return model
    items = []
    for key, value in model.items():
        value = ("true" if value else "false") if isinstance(value, bool) else repr(value)
        items.append("%s: %s" % (key, value))
    return "{%s}" % ", ".join(items)


def _options(lib, dt, noise_seed, noise_scale, phase, model):
    """hs_scenario_options from the keywords (None: the file's), checked as the tool checks them."""
    o = _capi.ScenarioOptions()
    keep = []  # what the struct points at lives as long as the load
    if dt is not None:
        value = ctypes.c_double()
        if not lib.hs_scenario_parse_dt(str(dt).encode(), ctypes.byref(value)):
            raise ValueError("dt needs a frame time within [1/2000, 1/12] s (e.g. 1/60 or '1/60'), got %r" % (dt,))
        o.dt = value.value
    if noise_seed is not None:
        if not (isinstance(noise_seed, int) and 0 <= noise_seed <= SEED_MAX):
            raise ValueError("noise_seed needs a seed within [0, %d], got %r" % (SEED_MAX, noise_seed))
        o.noise, o.noise_seed = True, noise_seed
    if noise_scale is not None:
        if noise_seed is None:
            raise ValueError("noise_scale goes with noise_seed")
        o.noise_scale = float(noise_scale)
    if phase is not None:
        if not 0.0 <= phase < 1.0:
            raise ValueError("phase needs a fraction of a frame within [0, 1), got %r" % (phase,))
        o.phase = float(phase)
    if model:
        texts = [_model_text(m).encode() for m in (model if isinstance(model, (list, tuple)) else [model])]
        array = (ctypes.c_char_p * len(texts))(*texts)
        keep += [texts, array]
        o.model_count, o.model_texts, o.model_path = len(texts), array, b"model"
    return o, keep


class Trajectory:
    """What `Scenario.record` saw, one row per frame (frame 0 included for a fresh scenario), the
    objects in the order of the file: `frame` (F,) int64, `t` (F,) float64 s, `position` (F, N, 3)
    float64 m, `orientation` (F, N, 4) float64 (w, x, y, z), `contact` (F, N) uint8 (0 none, 1 push
    at one point, 2 grasp, 3 push at several points), `floor_contacts` (F, N) int32, `resting`
    (F, N) bool, `hash` (F,) uint64: the state hash of each frame (the trajectory CSV's columns)."""

    def __init__(self, frames, objects):
        self.frame = np.zeros(frames, np.int64)
        self.t = np.zeros(frames, np.float64)
        self.position = np.zeros((frames, objects, 3), np.float64)
        self.orientation = np.zeros((frames, objects, 4), np.float64)
        self.contact = np.zeros((frames, objects), np.uint8)
        self.floor_contacts = np.zeros((frames, objects), np.int32)
        self.resting = np.zeros((frames, objects), np.bool_)
        self.hash = np.zeros(frames, np.uint64)

    def __len__(self):
        return len(self.frame)

    def _trim(self, n):
        for key in ("frame", "t", "position", "orientation", "contact", "floor_contacts", "resting", "hash"):
            setattr(self, key, getattr(self, key)[:n])
        return self


class Scenario:
    """A scenario file (YAML, scenarios/README.md) loaded and built: hs_scenario_load_with.

    Keywords as `handspring run`'s options: dt (a number or text such as "1/12"), noise_seed,
    noise_scale (with noise_seed), phase, model (a dict or YAML mapping text of model options, or
    a list of them). A bad file raises HandspringError with the loader's `file:line:` text.
    """

    def __init__(self, path, *, dt=None, noise_seed=None, noise_scale=None, phase=None, model=None):
        self._lib = _capi.api()
        self._ptr = None
        self.path = os.fspath(path)
        options, keep = _options(self._lib, dt, noise_seed, noise_scale, phase, model)
        err = _capi.Error()
        ptr = self._lib.hs_scenario_load_with(self.path.encode(), ctypes.byref(options), ctypes.byref(err))
        del keep
        if not ptr:
            raise HandspringError(text(err.message))
        self._ptr = ptr
        self._world = self._lib.hs_scenario_world(ptr)
        n = self._lib.hs_scenario_object_count(ptr)
        self._ids = [self._lib.hs_world_object_at(self._world, i) for i in range(n)]
        self.object_names = tuple(text(self._lib.hs_scenario_object_name(ptr, i)) for i in range(n))
        self.hand_names = tuple(text(self._lib.hs_scenario_hand_name(ptr, h))
                                for h in range(self._lib.hs_scenario_hand_count(ptr)))
        self.name = text(self._lib.hs_scenario_name(ptr))
        self.description = text(self._lib.hs_scenario_description(ptr))
        self.dt = self._lib.hs_scenario_dt(ptr)
        self.frame_count = self._lib.hs_scenario_frame_count(ptr)
        self.warnings = text(self._lib.hs_scenario_warnings(ptr))

    def close(self):
        """Frees the C scenario (also when garbage-collected); the object is unusable after."""
        if self._ptr:
            self._lib.hs_scenario_destroy(self._ptr)
            self._ptr = None

    def __del__(self):
        if getattr(self, "_ptr", None):
            self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _p(self):
        if not self._ptr:
            raise HandspringError("the scenario is closed")
        return self._ptr

    @property
    def frame(self):
        """Frames stepped so far (0 before the first step)."""
        self._p()
        return self._lib.hs_world_frame(self._world)

    @property
    def time(self):
        self._p()
        return self._lib.hs_world_time(self._world)

    def step(self):
        """One frame (inputs, then the world). False, stepping nothing, once every frame has run."""
        return bool(self._lib.hs_scenario_step(self._p()))

    def hash(self):
        """The 64-bit hash of the world's whole state now (hs_world_hash), as an int."""
        self._p()
        return int(self._lib.hs_world_hash(self._world))

    def _states(self):
        self._p()
        out = []
        for oid in self._ids:
            st = _capi.ObjectState()
            self._lib.hs_world_object_state(self._world, oid, ctypes.byref(st))
            out.append(st)
        return out

    def positions(self):
        """(N, 3) float64, m: every object's centre of gravity now."""
        return np.array([[s.position.x, s.position.y, s.position.z] for s in self._states()], np.float64).reshape(-1, 3)

    def orientations(self):
        """(N, 4) float64: every object's unit quaternion (w, x, y, z) now."""
        return np.array([[s.orientation.w, s.orientation.x, s.orientation.y, s.orientation.z]
                         for s in self._states()], np.float64).reshape(-1, 4)

    def contacts(self):
        """(N,) uint8: every object's hand contact state now (0 none, 1 push, 2 grasp, 3 push at several)."""
        return np.array([s.contact for s in self._states()], np.uint8)

    def _fill(self, traj, row):
        traj.frame[row] = self._lib.hs_world_frame(self._world)
        traj.t[row] = self._lib.hs_world_time(self._world)
        for i, s in enumerate(self._states()):
            traj.position[row, i] = (s.position.x, s.position.y, s.position.z)
            traj.orientation[row, i] = (s.orientation.w, s.orientation.x, s.orientation.y, s.orientation.z)
            traj.contact[row, i], traj.floor_contacts[row, i], traj.resting[row, i] = s.contact, s.floor_contacts, s.resting
        traj.hash[row] = self._lib.hs_world_hash(self._world)

    def record(self, frames=None):
        """Steps `frames` frames (None: to the end) and returns a Trajectory of the frame it starts
        at and every frame stepped."""
        left = self.frame_count - self.frame
        n = left if frames is None else max(0, min(int(frames), left))
        traj = Trajectory(n + 1, len(self._ids))
        self._fill(traj, 0)
        rows = 1
        while rows <= n and self.step():
            self._fill(traj, rows)
            rows += 1
        return traj._trim(rows)

    def check(self):
        """Judges every `expect` clause now: (failed count, the report lines hs_scenario_check writes)."""
        with _cfile.writer() as (stream, sink):
            failed = self._lib.hs_scenario_check(self._p(), stream)
        return failed, sink.data.decode("utf-8", "replace").splitlines()

    @property
    def expectation_count(self):
        return self._lib.hs_scenario_expectation_count(self._p())

    def hand_fit(self, hand):
        """(RMS mm, samples, recording) of a hand fitted to a joint recording; None for other hands."""
        rms, samples, record = ctypes.c_double(), ctypes.c_long(), ctypes.c_char_p()
        if not self._lib.hs_scenario_hand_fit(self._p(), hand, ctypes.byref(rms), ctypes.byref(samples),
                                              ctypes.byref(record)):
            return None
        return rms.value, samples.value, text(record.value)

    def save_state(self):
        """The run's whole state now as bytes (hs_scenario_save: the world's state block, the input
        noise generator, what the expectations captured): the bytes `handspring run --save-at F
        --state-out FILE` writes at frame F."""
        err = _capi.Error()
        with _cfile.writer() as (stream, sink):
            status = self._lib.hs_scenario_save(self._p(), stream, ctypes.byref(err))
        if status != 0:
            raise HandspringError(text(err.message), status)
        return sink.data

    def load_state(self, data):
        """Restores a state from save_state (or a --state-out file's bytes) of the same scenario
        file (hs_scenario_resume); stepping then continues that run bit for bit. A refused state
        raises HandspringError with the C text and leaves the scenario unchanged."""
        err = _capi.Error()
        with _cfile.reader(data) as stream:
            status = self._lib.hs_scenario_resume(self._p(), stream, ctypes.byref(err))
        if status != 0:
            raise HandspringError(text(err.message), status)
