// hands.c — a scenario's hands driven per frame from their scripts (hand_script.c), with the
// input noise, and freed; reading the `hands` section is hands_section.c's.
#include <stdlib.h>
#include <string.h>

#include "hands.h"

void hs_hands_drive(hs_world *world, const hs_hands *hands, double t, hs_noise *noise,
                    const hs_noise_options *options) {
	for (int h = 0; h < hands->count; ++h) {
		hs_vec3 wrist;
		hs_quat rot;
		uint8_t sensors[HS_GLOVE_SENSORS];
		bool tracked = hands->thrower.active && hands->thrower.hand == h
		                   ? hs_thrower_sample(&hands->thrower, &hands->scripts[h], t, &wrist, &rot, sensors)
		                   : hs_hand_script_sample(&hands->scripts[h], t, &wrist, &rot, sensors);
		// what a real glove and tracker report (hands in order: one generator, one sequence); a hand
		// the tracker does not see is held where it was last seen, without new noise
		bool joints_driven = hands->defs[h].joint_driven;
		if (noise && tracked) { // a hand driven by its joints has no glove: no sensor noise is drawn
			hs_noise_options o = *options;
			o.glove_units = joints_driven ? 0 : o.glove_units;
			hs_noise_hand(noise, &o, &wrist, &rot, sensors);
		}
		if (joints_driven) { // its joints, with the tracker's jitter on each
			hs_vec3 joints[HS_HAND_POINTS];
			hs_hand_script_joints(&hands->scripts[h], t, joints);
			if (noise && tracked)
				hs_noise_joints(noise, options, joints);
			hs_world_set_hand_joints(world, hands->ids[h], wrist, rot, joints);
		} else {
			hs_world_set_hand(world, hands->ids[h], wrist, rot, sensors);
		}
		hs_world_set_hand_tracked(world, hands->ids[h], tracked);
	}
}

void hs_hands_free(hs_hands *hands) {
	for (int h = 0; h < hands->count; ++h) {
		free(hands->names ? hands->names[h] : NULL);
		free(hands->scripts ? hands->scripts[h].keys : NULL);
		free(hands->fits ? hands->fits[h].record : NULL);
	}
	free(hands->fits);
	free(hands->names);
	free(hands->ids);
	free(hands->scripts);
	free(hands->defs);
	memset(hands, 0, sizeof *hands);
}
