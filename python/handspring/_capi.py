"""The C API as ctypes sees it: the structs and function signatures of handspring.h and
hs_harness.h that the package calls, bound once to the loaded library (`api()`)."""

import ctypes
from ctypes import POINTER, c_bool, c_char, c_char_p, c_double, c_int, c_long, c_size_t, c_uint16, c_uint32
from ctypes import c_uint64, c_ulong, c_void_p

from . import _lib


class Vec3(ctypes.Structure):
    _fields_ = [("x", c_double), ("y", c_double), ("z", c_double)]


class Quat(ctypes.Structure):
    _fields_ = [("w", c_double), ("x", c_double), ("y", c_double), ("z", c_double)]


class ObjectId(ctypes.Structure):
    _fields_ = [("index1", c_uint32), ("world", c_uint16), ("generation", c_uint16)]


class ObjectState(ctypes.Structure):
    _fields_ = [("position", Vec3), ("orientation", Quat), ("velocity", Vec3), ("contact", c_int),
                ("floor_contacts", c_int), ("resting", c_bool)]


class Error(ctypes.Structure):
    _fields_ = [("message", c_char * 512)]


class ScenarioOptions(ctypes.Structure):
    _fields_ = [("dt", c_double), ("noise", c_bool), ("noise_seed", c_ulong), ("noise_scale", c_double),
                ("model_count", c_int), ("model_texts", POINTER(c_char_p)), ("model_path", c_char_p),
                ("throw_error", c_void_p), ("phase", c_double)]


P = c_void_p  # hs_scenario *, hs_world *, FILE *: opaque
# name: (result, arguments)
SIGNATURES = {
    "hs_scenario_load_with": (P, [c_char_p, POINTER(ScenarioOptions), POINTER(Error)]),
    "hs_scenario_parse_dt": (c_bool, [c_char_p, POINTER(c_double)]),
    "hs_scenario_destroy": (None, [P]),
    "hs_scenario_name": (c_char_p, [P]),
    "hs_scenario_description": (c_char_p, [P]),
    "hs_scenario_world": (P, [P]),
    "hs_scenario_object_count": (c_int, [P]),
    "hs_scenario_object_name": (c_char_p, [P, c_int]),
    "hs_scenario_hand_count": (c_int, [P]),
    "hs_scenario_hand_name": (c_char_p, [P, c_int]),
    "hs_scenario_hand_fit": (c_bool, [P, c_int, POINTER(c_double), POINTER(c_long), POINTER(c_char_p)]),
    "hs_scenario_frame_count": (c_long, [P]),
    "hs_scenario_dt": (c_double, [P]),
    "hs_scenario_warnings": (c_char_p, [P]),
    "hs_scenario_step": (c_bool, [P]),
    "hs_scenario_check": (c_int, [P, P]),
    "hs_scenario_expectation_count": (c_int, [P]),
    "hs_scenario_save": (c_int, [P, P, POINTER(Error)]),
    "hs_scenario_resume": (c_int, [P, P, POINTER(Error)]),
    "hs_scenario_sweep": (c_int, [c_char_p, P, POINTER(Error)]),
    "hs_world_object_at": (ObjectId, [P, c_int]),
    "hs_world_object_state": (c_int, [P, ObjectId, POINTER(ObjectState)]),
    "hs_world_frame": (c_long, [P]),
    "hs_world_time": (c_double, [P]),
    "hs_world_hash": (c_uint64, [P]),
    "hs_world_state_size": (c_size_t, [P]),
    "hs_status_string": (c_char_p, [c_int]),
}

_api = None


def api():
    """The loaded library with every signature set (loaded on first use)."""
    global _api
    if _api is None:
        path, _ = _lib.find_library()
        lib = ctypes.CDLL(path)
        for name, (restype, argtypes) in SIGNATURES.items():
            fn = getattr(lib, name)
            fn.restype, fn.argtypes = restype, argtypes
        lib.handspring_path = path
        _api = lib
    return _api


def text(value):
    """A C string as str (None stays None)."""
    return None if value is None else value.decode("utf-8", "replace")
