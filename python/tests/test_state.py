"""Saving and loading the whole state (hs_scenario_save / hs_scenario_resume) through Python."""

import numpy as np
import pytest

import handspring
from conftest import tool

THROW = "scenarios/hand/throw_at_target.yaml"
SPRING = "scenarios/spring/throw_and_catch.yaml"


@pytest.mark.parametrize("path,frame", [(THROW, 40), (SPRING, 25), ("scenarios/seed_scene.yaml", 0)])
def test_saved_bytes_are_the_tools(path, frame, tmp_path):
    state = tmp_path / "s.state"
    assert tool("run", path, "--save-at", frame, "--state-out", state).returncode == 0
    with handspring.Scenario(path) as s:
        s.record(frame)
        assert s.frame == frame
        assert s.save_state() == state.read_bytes()


@pytest.mark.parametrize("path,frame", [(THROW, 40), (THROW, 100), (SPRING, 25)])
def test_round_trip_same_hashes(path, frame):
    with handspring.Scenario(path) as s:
        s.record(frame)
        saved, at = s.save_state(), s.hash()
        rest = s.record()
    assert len(rest) == rest.frame[-1] - frame + 1 > 1 and len(set(rest.hash.tolist())) > 1
    with handspring.Scenario(path) as fresh:  # a fresh load of the same file
        fresh.load_state(saved)
        assert (fresh.frame, fresh.hash()) == (frame, at)
        again = fresh.record()
        assert np.array_equal(again.hash, rest.hash) and np.array_equal(again.position, rest.position)
        assert fresh.check()[1] == handspring.run(path).report  # the full run's report
    with handspring.Scenario(path) as s:  # the same scenario, run to its end, put back
        s.record()
        s.load_state(saved)
        assert np.array_equal(s.record().hash, rest.hash)


def test_run_resume_matches_tool(tmp_path):
    state, rest = tmp_path / "s.state", tmp_path / "rest.csv"
    assert tool("run", THROW, "--save-at", 90, "--state-out", state).returncode == 0
    t = tool("run", THROW, "--resume", state, "--out", rest)
    full = handspring.run(THROW, save_at=90)
    assert full.state == state.read_bytes()
    resumed = handspring.run(THROW, resume=state)
    assert handspring.run(THROW, resume=full.state).final_hash == resumed.final_hash == full.final_hash
    assert "final hash: %016x\n" % resumed.final_hash in t.stdout and resumed.report == full.report
    hashes = [int(line.rsplit(",", 1)[1], 16) for line in rest.read_text().splitlines()[1:]]
    assert hashes == resumed.trajectory.hash[1:].tolist() == full.trajectory.hash[91:].tolist()
    assert resumed.trajectory.frame[0] == 90 and np.array_equal(full.trajectory.frame, np.arange(len(full.trajectory)))


def test_refused_state_raises_with_c_text(tmp_path):
    bad = tmp_path / "bad.state"
    with handspring.Scenario(THROW) as s:
        s.record(10)
        good = s.save_state()
        before = (s.frame, s.hash())
        for data in [b"", b"not a state", good[:-1], good[:-8] + bytes(8)]:
            bad.write_bytes(data)
            t = tool("run", THROW, "--resume", bad)
            with pytest.raises(handspring.HandspringError) as e:
                s.load_state(data)
            assert t.returncode == 2 and t.stderr == "%s: %s\n" % (bad, e.value)
            assert str(e.value).startswith("state file: ") and e.value.status is not None
            assert (s.frame, s.hash()) == before  # refused: unchanged
    with handspring.Scenario("scenarios/hand/flick_pyramid.yaml") as other:
        with pytest.raises(handspring.HandspringError, match="state file"):
            other.load_state(good)
    with handspring.Scenario(THROW, dt="1/30") as s:  # an overridden run cannot be saved
        with pytest.raises(handspring.HandspringError, match="dt or noise"):
            s.save_state()
