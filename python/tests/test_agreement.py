"""The bindings against the tool: every catalog scenario run through Python prints what
`handspring run` prints (the final hash included) and records exactly the trajectory CSV's rows."""

import csv

import numpy as np
import pytest

import handspring
from conftest import catalog, tool


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


@pytest.mark.parametrize("path", catalog())
def test_run_matches_tool(path, tmp_path):
    out = tmp_path / "traj.csv"
    t = tool("run", path, "--out", out)
    r = handspring.run(path)
    # the tool's summary names the trajectory file it wrote; the rest is the same text
    assert t.stdout.replace("trajectory: %s\n" % out, "") == r.summary
    assert r.status == t.returncode
    assert "final hash: %016x\n" % r.final_hash in t.stdout
    rows = read_csv(out)
    tr, n = r.trajectory, len(r.trajectory.position[0])
    assert len(rows) == len(tr) * n and int(tr.hash[-1]) == r.final_hash
    def col(name, kind=float, dtype=None):
        return np.array([kind(row[name]) for row in rows], dtype).reshape(len(tr), n)

    # numbers written with 17 significant digits parse back to the same doubles: exact equality
    assert np.array_equal(col("frame", int)[:, 0], tr.frame) and np.array_equal(col("t")[:, 0], tr.t)
    assert all(list(col("object", str)[f]) == list(r_names(path)) for f in range(len(tr)))
    assert np.array_equal(np.stack([col(c) for c in "xyz"], axis=-1), tr.position)
    assert np.array_equal(np.stack([col(c) for c in ("qw", "qx", "qy", "qz")], axis=-1), tr.orientation)
    assert np.array_equal(col("contact", int), tr.contact) and np.array_equal(col("floor", int), tr.floor_contacts)
    assert np.array_equal(col("resting", int).astype(bool), tr.resting)
    assert np.array_equal(col("hash", lambda v: int(v, 16), np.uint64)[:, 0], tr.hash)


_names = {}


def r_names(path):
    if path not in _names:
        with handspring.Scenario(path) as s:
            _names[path] = s.object_names
    return _names[path]


@pytest.mark.parametrize("args,kw", [
    (["--dt", "1/12"], {"dt": "1/12"}),
    (["--dt", "0.0125"], {"dt": 0.0125}),
    (["--noise-seed", "7"], {"noise_seed": 7}),
    (["--noise-seed", "3", "--phase", "0.5", "--dt", "1/30"], {"noise_seed": 3, "phase": 0.5, "dt": "1/30"}),
    (["--letter", "hand1999", "--dt", "1/12"], {"model": {"letter": "hand1999"}, "dt": "1/12"}),
])
def test_run_options_match_tool(args, kw):
    path = "scenarios/hand/throw_at_target.yaml"
    t = tool("run", path, *args)
    r = handspring.run(path, **kw)
    assert t.stdout == r.summary and t.returncode == r.status
    assert r.final_hash != handspring.run(path).final_hash  # the option changed the run


def test_step_by_step_is_run():
    path = "scenarios/hand/two_hands_pass.yaml"
    r = handspring.run(path)
    hashes = []
    with handspring.Scenario(path) as s:
        hashes.append(s.hash())
        while s.step():
            hashes.append(s.hash())
        assert s.frame == s.frame_count == r.frames
        assert np.array_equal(s.positions(), r.trajectory.position[-1])
        assert np.array_equal(s.orientations(), r.trajectory.orientation[-1])
        assert np.array_equal(s.contacts(), r.trajectory.contact[-1])
        assert not s.step() and s.frame == s.frame_count  # past the end: nothing steps
    assert np.array_equal(np.array(hashes, np.uint64), r.trajectory.hash)
    assert len(set(hashes)) > len(hashes) // 2  # the hash follows the state


def test_model_option_is_the_files(tmp_path):
    # a model option runs as the file with that option written in its `model:`
    path = "scenarios/hand/throw_at_target.yaml"
    line = "model: { grasp_threshold_deg: 90, stacking: paper }"
    text = open(path).read()
    assert line in text
    edited = tmp_path / "throw_at_target.yaml"
    edited.write_text(text.replace(line, line[:-2] + ", release_window_s: 0.2 }"))
    want = handspring.run(edited)
    assert want.final_hash != handspring.run(path).final_hash
    for model in ({"release_window_s": 0.2}, "{release_window_s: 0.2}", ["{glove_deadband: 0}", "{glove_deadband: 3, release_window_s: 0.2}"]):
        got = handspring.run(path, model=model)
        assert np.array_equal(got.trajectory.hash, want.trajectory.hash)
