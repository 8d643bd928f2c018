// spring_lift.c — data for the lift–swing–drop figure (workbench paper Fig. 7–8): runs the catalog
// scenario scenarios/spring/lift_swing_drop.yaml through hs_scenario_load / hs_scenario_step and
// records, every frame, the stylus, the object, the spring's extension (hs_world_spring_state) and
// the horizontal offset of the object from the stylus (the swing).
//
// usage: spring_lift OUTDIR [SCENARIO] — writes OUTDIR/spring_lift.csv and its sidecar
// OUTDIR/spring_lift.txt (the scenario, the object's spring and what the columns are)
// (run from the top folder; SCENARIO defaults to scenarios/spring/lift_swing_drop.yaml).
#include <math.h>
#include <stdio.h>

#include "hs_harness.h"
#include "plot_run.h"

int main(int argc, char **argv) {
	hs_scenario *s;
	FILE *out;
	int status = plot_run_open(argc, argv, "spring_lift", "scenarios/spring/lift_swing_drop.yaml", &s, &out);
	if (status)
		return status;
	hs_world *w = hs_scenario_world(s);
	hs_object_id id = hs_world_object_at(w, 0);
	hs_spring_object info;
	if (hs_world_spring_object(w, id, &info) != HS_OK) {
		fprintf(stderr, "%s: not a spring scenario\n", hs_scenario_name(s));
		fclose(out);
		hs_scenario_destroy(s);
		return 2;
	}
	if (plot_run_about(argv[1], "spring_lift",
	                   "spring_lift.csv: %s: %s\n"
	                   "object '%s': mass %.6g kg, x0 = %.6g m, k = %.6g N/m\n"
	                   "one row per frame\n"
	                   "t: time, s\n"
	                   "stylus_x, stylus_y, stylus_z: the stylus, m\n"
	                   "x, y, z: the object's centre G, m\n"
	                   "attached: 1 while the object is on the spring\n"
	                   "button: 1 while the stylus button is pressed\n"
	                   "length, extension: the spring's length and extension, m (nan when not attached)\n"
	                   "extension_ratio: extension / x0 (nan when not attached)\n"
	                   "swing: the horizontal distance of G from the stylus, m\n",
	                   hs_scenario_name(s), hs_scenario_description(s), hs_scenario_object_name(s, 0), info.mass,
	                   info.rest_length, info.stiffness) != 0) {
		fclose(out);
		hs_scenario_destroy(s);
		return 1;
	}
	fprintf(out, "t,stylus_x,stylus_y,stylus_z,x,y,z,attached,button,length,extension,extension_ratio,swing\n");
	do {
		hs_spring_state ss;
		hs_object_state st;
		hs_world_spring_state(w, &ss);
		hs_world_object_state(w, id, &st);
		bool on = ss.attached.index1 == id.index1;
		double swing = hypot(st.position.x - ss.stylus.x, st.position.y - ss.stylus.y);
		fprintf(out, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d,%.9g,%.9g,%.9g,%.9g\n", hs_world_time(w), ss.stylus.x,
		        ss.stylus.y, ss.stylus.z, st.position.x, st.position.y, st.position.z, on ? 1 : 0, ss.button ? 1 : 0,
		        on ? ss.length : NAN, on ? ss.extension : NAN, on ? ss.extension / info.rest_length : NAN, swing);
	} while (hs_scenario_step(s));
	return plot_run_close(s, out);
}
