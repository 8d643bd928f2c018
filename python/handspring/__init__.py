"""handspring from Python: the scenario harness of libhandspring-harness through ctypes.

    import handspring
    r = handspring.run("scenarios/drop_cube.yaml")      # as `handspring run FILE`
    r.trajectory.position                               # (frames + 1, objects, 3) float64

The library is found through $HANDSPRING_LIB, the package's folder, the build folder, then the
system (handspring.library_path() says which); python/README.md in the repository.
"""

from ._errors import HandspringError
from .commands import RunResult, SweepResult, run, sweep
from .scenario import Scenario, Trajectory

__version__ = "0.1.0"
__all__ = ["HandspringError", "RunResult", "Scenario", "SweepResult", "Trajectory", "library_path", "run", "sweep"]


def library_path():
    """The harness library the package loaded (a path, or the loader's name for a system one)."""
    from . import _capi
    return _capi.api().handspring_path
