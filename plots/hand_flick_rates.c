// hand_flick_rates.c — data for the flick across frame rates (1999 paper, Experiment 1 (3),
// Fig. 9; the paper ran at 12-17 frames/s): runs scenarios/hand/flick_pyramid.yaml with its dt
// replaced (hs_scenario_load_with) by 1/12, 1/17, 1/30, 1/60 and 1/120 s and records, every frame,
// the pyramid's centre G, its contact state and the angle it has turned since frame 0.
//
// usage: hand_flick_rates OUTDIR [SCENARIO] — writes OUTDIR/hand_flick_rates.csv (header row
// fps,frame,t,x,z,contact,turned_deg,floor_contacts, then the rates' rows one after another in the
// order above, told apart by fps), OUTDIR/hand_flick_rates.txt (what the columns are) and
// OUTDIR/hand_flick_rates.vars (gnuplot assignments per rate
// i = 1..5: fps<i>, push_t<i> (first frame pushed), max_turn<i> (deg), end_turn<i> (deg),
// end_x<i>, end_z<i>, end_floor<i> (vertices on the floor at the end: 4 its base, 3 a side face),
// end_resting<i>, fails<i> (the scenario's expectations that fail at that rate)).
// Exit status 0 whether or not a rate tips the pyramid over: the figure shows it.
#include <math.h>
#include <stdio.h>

#include "hs_harness.h"
#include "plot_run.h"


// OUTDIR/hand_flick_rates.txt, the CSV's sidecar
static int write_about(const char *dir, const char *scenario) {
	char rates[64];
	return plot_run_about(dir, "hand_flick_rates",
	                      "hand_flick_rates.csv: %s at dt = 1/fps s for fps = %s\n"
	                      "one row per frame, the rates one after another; column fps tells them apart\n"
	                      "fps: frames per second\n"
	                      "frame: frame number, 0 before the first step\n"
	                      "t: time, s\n"
	                      "x, z: the pyramid's centre G, m\n"
	                      "contact: hand contact state, 0 none, 1 push at one point, 2 grasp, 3 push at several points\n"
	                      "turned_deg: the angle the pyramid has turned since frame 0, deg\n"
	                      "floor_contacts: its vertices on the floor\n",
	                      scenario, plot_run_rates_text(rates, sizeof rates));
}

int main(int argc, char **argv) {
	const char *path;
	FILE *out, *vars;
	int status = plot_run_outputs(argc, argv, "hand_flick_rates", "scenarios/hand/flick_pyramid.yaml", &path, &out, &vars);
	if (status)
		return status;
	for (int i = 0; i < PLOT_RUN_RATES && status == 0; ++i) {
		hs_scenario *s = plot_run_load(path, 1.0 / plot_run_fps[i], false, 0);
		if (!s) {
			status = 2;
			break;
		}
		if (i == 0 && (write_about(argv[1], hs_scenario_name(s)) != 0 ||
		               fprintf(out, "fps,frame,t,x,z,contact,turned_deg,floor_contacts\n") < 0)) {
			hs_scenario_destroy(s);
			status = 1;
			break;
		}
		hs_world *w = hs_scenario_world(s);
		hs_object_id id = hs_world_object_at(w, 0);
		hs_object_state st;
		hs_world_object_state(w, id, &st);
		hs_quat q0 = st.orientation;
		long frame = 0;
		double push_t = NAN, max_turn = 0.0, turned = 0.0;
		do {
			hs_world_object_state(w, id, &st);
			turned = plot_run_turned_deg(q0, st.orientation);
			if (turned > max_turn)
				max_turn = turned;
			if (isnan(push_t) && st.contact != HS_CONTACT_NONE)
				push_t = hs_world_time(w);
			fprintf(out, "%d,%ld,%.9g,%.9g,%.9g,%d,%.9g,%d\n", plot_run_fps[i], frame, hs_world_time(w), st.position.x,
			        st.position.z, (int)st.contact, turned, st.floor_contacts);
			++frame;
		} while (hs_scenario_step(s));
		hs_world_object_state(w, id, &st);
		int n = i + 1;
		plot_run_var(vars, "fps", n, plot_run_fps[i]);
		plot_run_var(vars, "push_t", n, push_t);
		plot_run_var(vars, "max_turn", n, max_turn);
		plot_run_var(vars, "end_turn", n, plot_run_turned_deg(q0, st.orientation));
		plot_run_var(vars, "end_x", n, st.position.x);
		plot_run_var(vars, "end_z", n, st.position.z);
		plot_run_var(vars, "end_floor", n, st.floor_contacts);
		plot_run_var(vars, "end_resting", n, st.resting);
		plot_run_var(vars, "fails", n, hs_scenario_check(s, NULL));
		fprintf(vars, "\n");
		hs_scenario_destroy(s);
	}
	if (fclose(out) != 0 || fclose(vars) != 0)
		status = status ? status : 1;
	return status;
}
