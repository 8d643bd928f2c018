// spring_tracker.c — data for the tracker figure (workbench paper §5.1, Fig. 6: "Tracker positions
// during lifting and throwing manipulations"): runs the catalog scenario
// scenarios/spring/recorded_throw.yaml (a recorded 50 Hz stylus file: lift, then a throw) and writes
// every sample the tracker daemon took, with its velocity estimate and rest state at that sample.
//
// usage: spring_tracker OUTDIR [SCENARIO] — writes OUTDIR/spring_tracker.csv and its sidecar
// OUTDIR/spring_tracker.txt (the scenario and what the columns are) (run from the top folder).
#include <stdio.h>

#include "hs_harness.h"
#include "plot_run.h"

int main(int argc, char **argv) {
	hs_scenario *s;
	FILE *out;
	int status = plot_run_open(argc, argv, "spring_tracker", "scenarios/spring/recorded_throw.yaml", &s, &out);
	if (status)
		return status;
	hs_world *w = hs_scenario_world(s);
	hs_tracker_state tr;
	if (hs_world_tracker_state(w, &tr) != HS_OK) {
		fprintf(stderr, "%s: not a spring scenario\n", hs_scenario_name(s));
		fclose(out);
		hs_scenario_destroy(s);
		return 2;
	}
	if (plot_run_about(argv[1], "spring_tracker",
	                   "spring_tracker.csv: %s: %s\n"
	                   "tracker samples (50 Hz) with the estimates made at each, one row per sample\n"
	                   "t: the sample's time, s\n"
	                   "x, y, z: the stylus as sampled, m\n"
	                   "button: 1 while the stylus button is pressed\n"
	                   "vx, vy, vz, speed: the daemon's velocity estimate and its size, m/s\n"
	                   "at_rest: 1 while the daemon sees the hand at rest\n"
	                   "attached: 1 while an object is on the spring\n"
	                   "release: 1 drop, 2 throw on the sample of the frame that released the object, else 0\n"
	                   "(a sample that was not its frame's newest has nan estimates, at_rest and attached)\n",
	                   hs_scenario_name(s), hs_scenario_description(s)) != 0) {
		fclose(out);
		hs_scenario_destroy(s);
		return 1;
	}
	fprintf(out, "t,x,y,z,button,vx,vy,vz,speed,at_rest,attached,release\n");
	long seen = 0;
	int released = 0;
	do {
		hs_spring_state ss;
		hs_release rel;
		hs_world_tracker_state(w, &tr);
		hs_world_spring_state(w, &ss);
		hs_world_spring_last_release(w, &rel);
		int release = rel.kind != HS_RELEASE_NONE && !released ? (int)rel.kind : 0; // 1 drop, 2 throw
		released = released || rel.kind != HS_RELEASE_NONE;
		// at most one sample per frame at 50 Hz and dt <= 1/50 s; older ones, if any, without estimates
		for (long n = tr.sample_count; seen < n; ++seen) {
			hs_tracker_sample smp;
			int age = (int)(n - 1 - seen);
			if (age >= HS_TRACKER_CAPACITY || hs_world_tracker_sample(w, age, &smp) != HS_OK)
				continue;
			bool newest = age == 0;
			fprintf(out, "%.9g,%.9g,%.9g,%.9g,%d,", smp.time, smp.position.x, smp.position.y, smp.position.z,
			        smp.button ? 1 : 0);
			if (newest)
				fprintf(out, "%.9g,%.9g,%.9g,%.9g,%d,%d,%d\n", tr.velocity.x, tr.velocity.y, tr.velocity.z, tr.speed,
				        tr.at_rest ? 1 : 0, ss.attached.index1 ? 1 : 0, release);
			else
				fprintf(out, "nan,nan,nan,nan,nan,nan,0\n");
		}
	} while (hs_scenario_step(s));
	return plot_run_close(s, out);
}
