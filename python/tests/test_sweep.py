"""sweep(path) against `handspring sweep FILE`: the same table, status and cells."""

import numpy as np
import pytest

import handspring
from conftest import REPO, tool

FAILING = """name: sweep_fails
description: a cube dropped; a robust clause only some frame times meet
dt: 1/60
duration: 1.0
objects:
  - { name: cube, shape: cube, size: 0.1, position: [0, 0, 0.55] }
robust: { dt: [1/12, 1/17], seeds: 2 }
expect:
  - { object: cube, lands_at: 0.3333, tolerance: 0.001, robust: true }
  - { object: cube, at: end, resting: true, robust: true }
"""


@pytest.mark.parametrize("path", ["scenarios/hand/throw_at_target.yaml", "scenarios/spring/fast_ball_12fps.yaml"])
def test_sweep_matches_tool(path):
    t = tool("sweep", path)
    s = handspring.sweep(path)
    assert s.text == t.stdout and s.status == t.returncode == 0 and s.ok
    assert s.cells.shape == (len(s.dts), len(s.seeds)) and s.cells.dtype.kind == "U"
    assert s.total == s.cells.size and s.passed == int((s.cells == "ok").sum()) and s.nominal == "ok"


def test_sweep_failing_cells(tmp_path):
    path = tmp_path / "sweep_fails.yaml"
    path.write_text(FAILING)
    t = tool("sweep", path)
    s = handspring.sweep(path)
    assert s.text == t.stdout and s.status == t.returncode == 1 and not s.ok
    assert s.dts == ["1/12", "1/17"] and s.seeds == [1, 2]
    assert np.array_equal(s.cells, [["ok", "ok"], ["L9", "L9"]])
    assert (s.passed, s.total, s.nominal) == (2, 4, "ok")


def test_sweep_bad_input():
    for path in ["scenarios/drop_cube.yaml", "no/such.yaml"]:  # no robust block; no file
        t = tool("sweep", path)
        with pytest.raises(handspring.HandspringError) as e:
            handspring.sweep(path)
        assert t.returncode == 2 and str(e.value) == t.stderr.strip()
