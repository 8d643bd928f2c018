// hand_throw.c — data for the throw figure (1999 paper, Experiment 2, Fig. 10): runs the catalog
// scenario scenarios/hand/throw_at_target.yaml through hs_scenario_load / hs_scenario_step and
// records, every frame, the block's centre G and hand contact state, and where the hand is: the
// mean of its 20 check points and its index fingertip (check point 7), from hs_world_hand_points.
// The catalog trajectory (build/traj/hand/throw_at_target.csv) has the block but not the hand.
//
// usage: hand_throw OUTDIR [SCENARIO] — writes OUTDIR/hand_throw.csv and its sidecar
// OUTDIR/hand_throw.txt (the scenario and what the columns are)
// (run from the top folder; SCENARIO defaults to scenarios/hand/throw_at_target.yaml).
#include <math.h>
#include <stdio.h>

#include "hs_harness.h"
#include "plot_run.h"

int main(int argc, char **argv) {
	hs_scenario *s;
	FILE *out;
	int status = plot_run_open(argc, argv, "hand_throw", "scenarios/hand/throw_at_target.yaml", &s, &out);
	if (status)
		return status;
	hs_world *w = hs_scenario_world(s);
	hs_object_id id = hs_world_object_at(w, 0);
	hs_hand_id hand = hs_world_hand_at(w, 0);
	if (plot_run_about(argv[1], "hand_throw",
	                   "hand_throw.csv: %s: %s\n"
	                   "object '%s'; hand = mean of the 20 check points, tip = index fingertip\n"
	                   "one row per frame\n"
	                   "frame: frame number, 0 before the first step\n"
	                   "t: time, s\n"
	                   "x, y, z: the object's centre G, m\n"
	                   "contact: hand contact state, 0 none, 1 push at one point, 2 grasp, 3 push at several points\n"
	                   "hand_x, hand_y, hand_z: the mean of the hand's 20 check points, m (nan in frame 0)\n"
	                   "tip_x, tip_y, tip_z: the index fingertip (check point 7), m (nan in frame 0)\n",
	                   hs_scenario_name(s), hs_scenario_description(s), hs_scenario_object_name(s, 0)) != 0) {
		fclose(out);
		hs_scenario_destroy(s);
		return 1;
	}
	fprintf(out, "frame,t,x,y,z,contact,hand_x,hand_y,hand_z,tip_x,tip_y,tip_z\n");
	long frame = 0;
	do {
		hs_object_state st;
		hs_world_object_state(w, id, &st);
		hs_vec3 p[HS_HAND_POINTS];
		// the check points exist once the world has stepped (frame 0 is the state before any step)
		bool have_hand = frame > 0 && hs_world_hand_points(w, hand, p) == HS_OK;
		hs_vec3 mean = hs_v3(NAN, NAN, NAN), tip = mean;
		if (have_hand) {
			mean = hs_v3(0.0, 0.0, 0.0);
			for (int i = 0; i < HS_HAND_POINTS; ++i)
				mean = hs_add(mean, p[i]);
			mean = hs_scale(mean, 1.0 / HS_HAND_POINTS);
			tip = p[7];
		}
		fprintf(out, "%ld,%.9g,%.9g,%.9g,%.9g,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", frame, hs_world_time(w),
		        st.position.x, st.position.y, st.position.z, (int)st.contact, mean.x, mean.y, mean.z, tip.x, tip.y,
		        tip.z);
		++frame;
	} while (hs_scenario_step(s));
	return plot_run_close(s, out);
}
