"""Bad input raises HandspringError carrying the C library's text: the line the tool prints."""

from pathlib import Path

import pytest

import handspring
from conftest import REPO, tool

BAD = sorted(str(p.relative_to(REPO)) for p in (REPO / "tests" / "bad").glob("*.yaml"))


def test_missing_file():
    t = tool("run", "no/such/file.yaml")
    with pytest.raises(handspring.HandspringError) as e:
        handspring.Scenario("no/such/file.yaml")
    assert t.returncode == 2 and t.stderr == str(e.value) + "\n"
    assert str(e.value) == e.value.message == "no/such/file.yaml:1: cannot read: No such file or directory"
    with pytest.raises(handspring.HandspringError):
        handspring.run(Path("no/such/file.yaml"))


def test_every_bad_scenario_as_the_tool():
    assert len(BAD) > 200
    refused = 0
    for path in BAD:
        t = tool("run", path)
        if t.returncode != 2:  # refused by the tool's own checks only, or loads and fails its clauses
            continue
        with pytest.raises(handspring.HandspringError) as e:
            handspring.Scenario(path)
        assert t.stderr == str(e.value) + "\n", path
        refused += 1
    assert refused > 200


@pytest.mark.parametrize("kw,what", [({"dt": "1/5"}, "dt"), ({"dt": 0.0}, "dt"), ({"dt": "fast"}, "dt"),
                                     ({"noise_seed": -1}, "noise_seed"), ({"noise_seed": 2**32}, "noise_seed"),
                                     ({"phase": 1.0}, "phase"), ({"noise_scale": 2.0}, "noise_scale")])
def test_bad_options(kw, what):
    with pytest.raises(ValueError, match=what):
        handspring.Scenario("scenarios/drop_cube.yaml", **kw)


def test_bad_model_option_names_it():
    with pytest.raises(handspring.HandspringError, match="^model:1:.*grasp_threshold_deg"):
        handspring.Scenario("scenarios/drop_cube.yaml", model={"grasp_threshold_deg": "wide"})


def test_closed_scenario():
    s = handspring.Scenario("scenarios/drop_cube.yaml")
    s.close()
    s.close()  # twice is harmless
    with pytest.raises(handspring.HandspringError, match="closed"):
        s.step()


def test_run_refuses_what_the_tool_refuses():
    with pytest.raises(ValueError, match="save_at must be within"):
        handspring.run("scenarios/drop_cube.yaml", save_at=91)
    with pytest.raises(ValueError, match="do not go with"):
        handspring.run("scenarios/drop_cube.yaml", save_at=3, dt="1/30")
