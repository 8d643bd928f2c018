"""Finding and loading the shared libraries, and the C declarations the package calls.

The harness library (libhandspring-harness.so.0) is loaded; the physics library it links
(libhandspring.so.0) comes with it, found beside it through the harness's run path ($ORIGIN) or
by the system's loader. Symbols of both are looked up through the harness's handle: dlsym on a
handle searches the library and the libraries it depends on.
"""

import ctypes
import ctypes.util
import os

from ._errors import HandspringError

ENV_VAR = "HANDSPRING_LIB"
HARNESS_NAMES = ("libhandspring-harness.so.0", "libhandspring-harness.so")
PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
# the repository's build folder, when the package runs from its source tree (python/handspring)
SOURCE_BUILD_DIR = os.path.normpath(os.path.join(PACKAGE_DIR, os.pardir, os.pardir, "build"))


def _in_dir(folder):
    for name in HARNESS_NAMES:
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            return path
    return None


def find_library(environ=None, package_dir=PACKAGE_DIR, build_dirs=None):
    """Where the harness library is: (path or loader name, how it was found).

    In order: $HANDSPRING_LIB (the library file, or a folder holding it; set but wrong is an
    error, never skipped), the package's own folder, the build folders (the source tree's
    build/ beside python/, then ./build of the current folder), then the system
    (ctypes.util.find_library, i.e. the loader's cache after `make install`).
    """
    environ = os.environ if environ is None else environ
    given = environ.get(ENV_VAR)
    if given:
        path = _in_dir(given) if os.path.isdir(given) else given if os.path.isfile(given) else None
        if path is None:
            raise HandspringError(
                "%s=%s: no %s there (set it to the library file or its folder)" % (ENV_VAR, given, HARNESS_NAMES[0]))
        return os.path.abspath(path), ENV_VAR
    if build_dirs is None:
        build_dirs = (SOURCE_BUILD_DIR, os.path.join(os.getcwd(), "build"))
    for where, folder in [("package", package_dir)] + [("build", d) for d in build_dirs]:
        path = _in_dir(folder) if folder else None
        if path:
            return path, where
    name = ctypes.util.find_library("handspring-harness")
    if name:
        return name, "system"
    raise HandspringError(
        "libhandspring-harness not found: build it (make shared) and set %s to build/, or make install" % ENV_VAR)
