"""The arrays have the documented shapes and types (python/README.md, "Arrays")."""

import numpy as np

import handspring


def test_now_arrays():
    with handspring.Scenario("scenarios/seed_scene.yaml") as s:
        n = len(s.object_names)
        assert n == 10
        for _ in range(2):
            p, q, c = s.positions(), s.orientations(), s.contacts()
            assert p.shape == (n, 3) and p.dtype == np.float64
            assert q.shape == (n, 4) and q.dtype == np.float64
            assert c.shape == (n,) and c.dtype == np.uint8
            assert np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-12)
            assert isinstance(s.hash(), int) and 0 <= s.hash() < 2**64
            s.step()


def test_trajectory_arrays():
    r = handspring.run("scenarios/hand/throw_at_target.yaml")
    tr = r.trajectory
    f, n = r.frames + 1, r.objects
    assert len(tr) == f == 181 and n == 1
    shapes = {"frame": ((f,), np.int64), "t": ((f,), np.float64), "position": ((f, n, 3), np.float64),
              "orientation": ((f, n, 4), np.float64), "contact": ((f, n), np.uint8),
              "floor_contacts": ((f, n), np.int32), "resting": ((f, n), np.bool_), "hash": ((f,), np.uint64)}
    for key, (shape, dtype) in shapes.items():
        a = getattr(tr, key)
        assert a.shape == shape and a.dtype == dtype, key
    assert np.array_equal(tr.frame, np.arange(f)) and np.array_equal(tr.t, tr.frame * r.dt)
    assert set(np.unique(tr.contact)) == {0, 2}  # the throw: grasped, then let go
    assert r.trajectory.hash[-1] == r.final_hash


def test_record_part_way():
    with handspring.Scenario("scenarios/drop_cube.yaml") as s:
        a = s.record(10)
        b = s.record(0)
        c = s.record(1000)  # stops at the end
        assert (len(a), len(b), len(c)) == (11, 1, 81)
        assert a.frame[-1] == b.frame[0] == c.frame[0] == 10 and c.frame[-1] == s.frame_count == 90
        assert a.hash[-1] == b.hash[0] == c.hash[0]
