# Drive catalog scenarios from Python (run it from the repository's top folder).
import handspring

r = handspring.run("scenarios/drop_cube.yaml")  # what `handspring run` does, in process
z = r.trajectory.position[:, 0, 2]  # the cube's height at every frame, m
print(f"{r.name}: {r.total - r.failed}/{r.total} expectations pass, rests at z = {z[-1]:.4f} m")
print(f"final hash {r.final_hash:016x}")  # as the tool's `final hash:` line

s = handspring.Scenario("scenarios/hand/throw_at_target.yaml")
s.record(40)  # step 40 frames
saved = s.save_state()  # the whole run: world, input noise, expectation captures
rest = s.record().hash  # the state hash of frame 40 and every frame after
s.load_state(saved)  # back to frame 40
print(f"frame {s.frame}: contact {s.contacts()} (2: grasp), replay identical: {(s.record().hash == rest).all()}")
