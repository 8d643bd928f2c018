#!/bin/sh
# Writes scenarios/hand/throw_underarm.yaml: the Expo throw with a smooth underarm swing, whose keys
# sample the closed-form swing every 20 ms (a keyframed swing has corners, where a hand's velocity
# jumps; a release-velocity estimator over more than one frame then averages across them).
#   sh scripts/throw_underarm.sh > scenarios/hand/throw_underarm.yaml
set -eu
awk 'BEGIN {
	pi = atan2(0, -1); g = 9.81
	sz = 1.4; arm = 0.7; phi0 = -60 * pi / 180; phir = 45 * pi / 180; tr = 2.0; rest = 0.025; lift = 0.018
	xr = arm * sin(phir); zr = sz - arm * cos(phir)
	dx = 2.0 - xr; h = zr - rest
	v = sqrt(g * dx * dx / (h + dx)); w = v / arm
	dur = 2 * (phir - phi0) / w; ts = tr - dur; alpha = w / dur
	vx = v * cos(phir); vz = v * sin(phir)
	# the grasp posture grip centre in the wrist frame (throw_at_target.yaml, to the last bit)
	cx = 0.10335079165147579; cy = 0.015009860920833271; cz = -0.062623575352331096
	printf "# Throw a block at a target 2 m away (1999 paper, Experiment 2) with a smooth underarm swing.\n"
	printf "# Written by scripts/throw_underarm.sh: edit that, not this.\n#\n"
	printf "# The hand grasps the 5 cm block as in throw_at_target, lifts it to the start of the swing and\n"
	printf "# swings it on a circle about a shoulder at (0, 0, %.1f) m, radius %.1f m, from %d deg behind the\n", sz, arm, -phi0 * 180 / pi
	printf "# vertical, from rest, with constant angular acceleration, to %d deg forward at t = %.1f s (a frame\n", phir * 180 / pi, tr
	printf "# time at 12, 17, 30, 60 and 120 frames/s), at %.4f m/s: the speed whose parabola from there\n", v
	printf "# lands the block (G at its rest height 0.025 m) on the target centre x = 2 m. From t = %.1f s the\n", tr
	printf "# hand goes straight on at that velocity and opens (by t = %.2f s), then stops. The keys sample the\n", tr + 0.01
	printf "# swing every 20 ms (the grip 18 mm above the block centre, the wrist not turning): unlike\n"
	printf "# throw_at_target, whose swing starts at 3.9 m/s from rest, nothing jumps, so release-velocity\n"
	printf "# estimators over 0.1-0.16 s see a hand as a real arm moves it (campaigns/exp2.yaml).\n"
	printf "# Swing: t0 = %.6f s, omega = %.6f rad/s at release, alpha = %.6f rad/s^2.\n", ts, w, alpha
	printf "name: throw_underarm\n"
	printf "description: an underarm swing on a circle, smooth from rest, releases the block at 45 deg; it lands in the 0.15 m target 2 m away\n"
	# closed form at the scenario dt 1/12 s: held at R at t = 2 (frame 24), the hand open by the next
	# frame, which it leaves where the hand carried it at v + g dt / 2 (let go mid-frame):
	# P(24 + n) = R + n dt v + g dt^2 (n - 1) n / 2; it lands in the first frame below z = 0.025,
	# back along the motion of that frame to where its base met the floor
	dt = 1 / 12; nl = 0; z = zr; zb = zr
	while (z >= rest) { ++nl; zb = z; z = zr + nl * dt * vz - 0.5 * g * dt * dt * (nl - 1) * nl }
	f = (z - rest) / (z - zb)
	land_x = xr + (nl - f) * dt * vx; land_t = (24 + nl) * dt
	printf "# Closed form at the scenario 12 frames/s: held at R = (%.6f, 0, %.6f) at t = 2 (frame 24) and let go\n", xr, zr
	printf "# in the next frame, which it leaves where the hand carried it, at v + g dt / 2 (let go mid-frame):\n"
	printf "# P(24 + n) = R + n dt v + g dt^2 (n - 1) n / 2, first below z = 0.025 at n = %d (t = %.7f s), where\n", nl, land_t
	printf "# it lands back along the motion of that frame, at x = %.7f (docs/model.md §4 \"Release\", §5 \"Landing\").\n", land_x
	printf "dt: 1/12\nduration: 3.5\nmodel: { grasp_threshold_deg: 90, stacking: paper }\n"
	printf "objects:\n  - { name: block, shape: cube, size: 0.05, position: [0, 0, 0.025] }\n"
	printf "hands:\n  - name: right\n    keys:\n"
	printf "      - { t: 0.0, grip: [0.004, 0, 0.193], rpy_deg: [0, 0, 0], posture: { grasp: 0.12 } }\n"
	printf "      - { t: 0.5, grip: [0.004, 0, 0.058] }\n      - { t: 0.6 }\n"
	printf "      - { t: 0.605, grip: [0, 0, 0.043], posture: { grasp: 0.035 } }\n      - { t: 0.7 }\n"
	x0 = arm * sin(phi0); z0 = sz - arm * cos(phi0)
	printf "      - { t: 1.0, grip: [%.17g, 0, %.17g] }   # the start of the swing, at rest\n", x0, z0 + lift
	n = int((tr - ts) / 0.02)
	for (k = 0; k <= n; ++k) {
		t = tr - (n - k) * 0.02
		if (k == 0) t = ts
		u = t - ts; phi = phi0 + 0.5 * alpha * u * u
		printf "      - { t: %.17g, grip: [%.17g, 0, %.17g] }\n", t, arm * sin(phi), sz - arm * cos(phi) + lift
	}
	split("0.01 0.2 0.25", ks, " ")
	for (i = 1; i <= 3; ++i) {
		k = ks[i]; t = tr + (i == 3 ? 0.4 : k)
		if (i == 3) t = tr + 0.4
		printf "      - { t: %.17g, wrist: [%.17g, %.17g, %.17g]%s }\n", tr + (i == 1 ? 0.01 : i == 2 ? 0.2 : 0.4), \
			xr + k * vx - cx, -cy, zr + lift + k * vz - cz, i == 1 ? ", posture: open" : ""
	}
	printf "robust: { phases: true, dt: [1/12, 1/17, 1/30, 1/60, 1/72, 1/90, 1/120, 1/144], seeds: 10, glove_units: 4, wrist_mm: 0.762, wrist_deg: 0.15 }\n"
	printf "expect:\n"
	printf "  - { object: block, contact_sequence: [0, 2, 0], robust: true }\n"
	printf "  - { object: block, grasped: true, from: 0.8, to: 1.95, robust: true }   # (0.7: a script a frame late at 12 frames/s grasps at 0.75 s)\n"
	printf "  - { object: block, at: 2.0, near: [%.17g, 0, %.17g], tolerance: 1e-9 }   # R\n", xr, zr
	printf "  - { object: block, lands_at: %.7f, tolerance: 0.001 }\n", land_t
	printf "  - { object: block, at: end, near: [%.7f, 0, 0.025], tolerance: 1e-7 }   # where eq. 3 puts it\n", land_x
	printf "  - { object: block, at: end, near: [2, 0, 0.025], tolerance: 0.15, axes: xy, robust: true }   # inside the target\n"
	printf "  - { object: block, at: end, floor_contacts: 4, robust: true }\n"
	printf "  - { object: block, at: end, resting: true, robust: true }\n"
	printf "  - { object: block, still: true, from: %.4f }\n", land_t + 0.1
}'
