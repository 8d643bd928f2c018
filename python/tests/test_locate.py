"""Where the library is found: $HANDSPRING_LIB, the package's folder, the build folders, the system."""

import os
import shutil
import subprocess
import sys

import pytest

import handspring
from conftest import REPO
from handspring import _lib

NAME = "libhandspring-harness.so.0"


def folder(tmp_path, name):
    d = tmp_path / name
    d.mkdir()
    (d / NAME).write_bytes(b"")
    return str(d)


def test_order(tmp_path, monkeypatch):
    env, pkg, b1, b2 = (folder(tmp_path, n) for n in ("env", "pkg", "b1", "b2"))
    empty = str(tmp_path / "empty")
    os.mkdir(empty)
    monkeypatch.setattr(_lib.ctypes.util, "find_library", lambda name: "lib%s.so.0" % name)
    find = _lib.find_library
    assert find({"HANDSPRING_LIB": env}, pkg, [b1, b2]) == (os.path.join(env, NAME), "HANDSPRING_LIB")
    assert find({"HANDSPRING_LIB": os.path.join(env, NAME)}, pkg, [b1]) == (os.path.join(env, NAME), "HANDSPRING_LIB")
    assert find({}, pkg, [b1, b2]) == (os.path.join(pkg, NAME), "package")
    assert find({}, empty, [empty, b2]) == (os.path.join(b2, NAME), "build")
    assert find({}, empty, [empty]) == ("libhandspring-harness.so.0", "system")
    with pytest.raises(handspring.HandspringError, match="HANDSPRING_LIB=.*empty: no libhandspring-harness"):
        find({"HANDSPRING_LIB": empty}, pkg, [b1])  # set but wrong: an error, not the next place
    monkeypatch.setattr(_lib.ctypes.util, "find_library", lambda name: None)
    with pytest.raises(handspring.HandspringError, match="not found"):
        find({}, empty, [empty])


def test_loads_from_build_folder_of_cwd(tmp_path):
    # no HANDSPRING_LIB and nothing beside the package: a notebook started in a folder whose build/
    # holds the libraries (the source tree's build/ put out of the way)
    lib = os.path.dirname(os.path.realpath(handspring.library_path()))
    os.symlink(lib, tmp_path / "build")
    env = {k: v for k, v in os.environ.items() if k != "HANDSPRING_LIB"}
    env["PYTHONPATH"] = os.path.dirname(os.path.dirname(handspring.__file__))
    code = ("import handspring, handspring._lib as l; l.SOURCE_BUILD_DIR = '/nonexistent'; "
            "print(handspring.library_path()); print('%016x' % handspring.run('drop.yaml').final_hash)")
    (tmp_path / "drop.yaml").write_bytes(open("scenarios/drop_cube.yaml", "rb").read().replace(b"name: drop_cube", b"name: drop"))
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == [str(tmp_path / "build" / NAME), "%016x" % handspring.run("scenarios/drop_cube.yaml").final_hash]


@pytest.mark.skipif(os.environ.get("HS_PYTHON_INSTALLED") != "1", reason="make check-python sets it")
def test_installed_package_under_test():
    # make check-python tests the copy pip installed, not the source folder
    assert "site-packages" in handspring.__file__ and not handspring.__file__.startswith(str(REPO / "python"))


def test_loads_from_package_folder(tmp_path):
    # both libraries copied beside the package: found there, with nothing else to go by
    pkg = tmp_path / "site" / "handspring"
    shutil.copytree(os.path.dirname(handspring.__file__), pkg, ignore=shutil.ignore_patterns("__pycache__"))
    lib = os.path.dirname(os.path.realpath(handspring.library_path()))
    for name in (NAME, "libhandspring.so.0"):
        shutil.copy(os.path.join(lib, name), pkg / name)
    env = {k: v for k, v in os.environ.items() if k not in ("HANDSPRING_LIB", "LD_LIBRARY_PATH")}
    env["PYTHONPATH"] = str(tmp_path / "site")
    code = "import handspring; print(handspring.library_path()); print(handspring.run(%r).final_hash)"
    drop = os.path.abspath("scenarios/drop_cube.yaml")
    out = subprocess.run([sys.executable, "-c", code % drop], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == [str(pkg / NAME), str(handspring.run(drop).final_hash)]
