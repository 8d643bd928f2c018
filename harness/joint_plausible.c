// joint_plausible.c — a joint recording that cannot be where it says it is is refused, after its
// frame, units and placement (scenarios/README.md, "Recorded joint positions"): a wrist under the
// floor in most tracked samples means the frame is probably wrong (a y-up recording read as z-up
// has its hand below the floor as often as not), and a wrist beyond 10 m means the units or the
// placement are. The floor's test is the library's (docs/model.md §5: the floor is z = 0), with
// 2 cm for a tracker's noise and a hand resting on the table's edge.
#include <stdio.h>

#include "joint_plausible.h"
#include "joint_pose.h"

static const double FLOOR_Z = -HS_HAND_FLOOR_SLACK; // m
static const double MAX_REACH = 10.0; // m

// Tracked samples whose wrist, fitted to the points placed by `place`, is under the floor.
static long under_floor(const hs_joint_file *f, const hs_joint_place *place, const hs_hand_def *def) {
	long n = 0;
	for (long k = 0; k < f->count; ++k) {
		const hs_joint_sample *s = &f->samples[k];
		if (!s->tracked)
			continue;
		hs_vec3 world[HS_HAND_POINTS] = {{0.0, 0.0, 0.0}}, pos;
		hs_quat rot;
		for (int i = 0; i < HS_HAND_POINTS; ++i)
			if (HS_JOINT_RIGID_MASK >> i & 1u)
				world[i] = hs_joint_place_point(place, s->points[i]);
		n += hs_joint_fit_wrist(def, world, &rot, &pos) && pos.z < FLOOR_Z;
	}
	return n;
}

// The frames, other than the file's, that would put the wrist above the floor in at least half
// the tracked samples: "y_up or unity would put it above the floor", or that none would.
static void other_frames(const hs_joint_file *f, const hs_hand_def *def, long tracked, char *out, size_t size) {
	int found[HS_JOINT_FRAMES], count = 0;
	for (int frame = 0; frame < HS_JOINT_FRAMES; ++frame) {
		hs_joint_place place = f->place;
		place.frame = (hs_joint_frame)frame;
		if (place.frame != f->place.frame && 2 * under_floor(f, &place, def) <= tracked)
			found[count++] = frame;
	}
	size_t n = 0;
	for (int i = 0; i < count && n < size; ++i)
		n += (size_t)snprintf(out + n, size - n, "%s%s", i == 0 ? "" : i == count - 1 ? " or " : ", ",
		                      hs_joint_frame_names[found[i]]);
	if (count == 0)
		snprintf(out, size, "no other frame puts it above the floor either: is the placement (origin) right?");
	else if (n < size)
		snprintf(out + n, size - n, " would put it above the floor");
}

bool hs_joint_check_plausible(const char *path, const hs_joint_file *f, const hs_hand_def *def,
                              const hs_hand_key *keys, long tracked, hs_error *err) {
	long under = 0, first = -1, far = -1;
	for (long k = 0; k < f->count; ++k) {
		if (!f->samples[k].tracked)
			continue;
		if (keys[k].wrist.z < FLOOR_Z && under++ == 0)
			first = k;
		if (far < 0 && !(hs_length(keys[k].wrist) <= MAX_REACH))
			far = k;
	}
	if (2 * under > tracked) {
		char others[160];
		other_frames(f, def, tracked, others, sizeof others);
		return hs_set_error(err, path, (unsigned long)f->samples[first].line,
		                    "the wrist is under the floor (z < -0.02 m) in %ld of %ld tracked samples, here at z = %.3f "
		                    "m: the frame is probably wrong (%s, %s); %s",
		                    under, tracked, keys[first].wrist.z, hs_joint_frame_names[f->place.frame],
		                    f->frame_assumed ? "assumed: the file says no @frame" : "as said", others);
	}
	static const char *const other_units[HS_JOINT_UNIT_COUNT] = {"cm or mm", "m or mm", "m or cm"};
	if (far >= 0)
		return hs_set_error(err, path, (unsigned long)f->samples[far].line,
		                    "the wrist is %.4g m from the origin (at most 10 m): are the units right (read as %s: are they "
		                    "%s?), or the placement (origin)?",
		                    hs_length(keys[far].wrist), hs_joint_unit_names[f->place.units], other_units[f->place.units]);
	return true;
}
