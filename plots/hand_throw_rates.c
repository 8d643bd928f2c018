// hand_throw_rates.c — data for the throw across frame rates (1999 paper, Experiment 2, Fig. 10;
// the paper ran at 12-17 frames/s): runs scenarios/hand/throw_at_target.yaml with its dt replaced
// (hs_scenario_load_with) by 1/12, 1/17, 1/30, 1/60 and 1/120 s and records the block's centre G
// every frame. The script's keys are times, so every rate sees the same hand motion sampled
// differently; the release and the landing fall where the frames do.
//
// usage: hand_throw_rates OUTDIR [SCENARIO] — writes OUTDIR/hand_throw_rates.csv (header row
// fps,frame,t,x,y,z,contact,floor_contacts, then the rates' rows one after another in the order
// above, told apart by fps), OUTDIR/hand_throw_rates.txt (what the columns are) and
// OUTDIR/hand_throw_rates.vars (gnuplot assignments per rate i = 1..5:
// fps<i>, release_t<i>, release_x<i>, release_z<i>, land_t<i>, land_x<i>, end_x<i>, end_y<i>,
// miss<i> (m from the target centre (2, 0)), hit<i> (miss <= 0.15 m), fails<i> (the scenario's
// expectations that fail at that rate)).
// Exit status 0 whether or not a rate hits: the figure shows it.
#include <math.h>
#include <stdio.h>

#include "hs_harness.h"
#include "plot_run.h"


// OUTDIR/hand_throw_rates.txt, the CSV's sidecar
static int write_about(const char *dir, const char *scenario) {
	char rates[64];
	return plot_run_about(dir, "hand_throw_rates",
	                      "hand_throw_rates.csv: %s at dt = 1/fps s for fps = %s\n"
	                      "one row per frame, the rates one after another; column fps tells them apart\n"
	                      "fps: frames per second\n"
	                      "frame: frame number, 0 before the first step\n"
	                      "t: time, s\n"
	                      "x, y, z: the block's centre G, m\n"
	                      "contact: hand contact state, 0 none, 1 push at one point, 2 grasp, 3 push at several points\n"
	                      "floor_contacts: its vertices on the floor\n",
	                      scenario, plot_run_rates_text(rates, sizeof rates));
}

int main(int argc, char **argv) {
	const char *path;
	FILE *out, *vars;
	int status = plot_run_outputs(argc, argv, "hand_throw_rates", "scenarios/hand/throw_at_target.yaml", &path, &out, &vars);
	if (status)
		return status;
	for (int i = 0; i < PLOT_RUN_RATES && status == 0; ++i) {
		hs_scenario *s = plot_run_load(path, 1.0 / plot_run_fps[i], false, 0);
		if (!s) {
			status = 2;
			break;
		}
		if (i == 0 && (write_about(argv[1], hs_scenario_name(s)) != 0 ||
		               fprintf(out, "fps,frame,t,x,y,z,contact,floor_contacts\n") < 0)) {
			hs_scenario_destroy(s);
			status = 1;
			break;
		}
		hs_world *w = hs_scenario_world(s);
		hs_object_id id = hs_world_object_at(w, 0);
		long frame = 0;
		double release_t = NAN, release_x = NAN, release_z = NAN, land_t = NAN, land_x = NAN;
		hs_object_state prev = {0};
		do {
			hs_object_state st;
			hs_world_object_state(w, id, &st);
			fprintf(out, "%d,%ld,%.9g,%.9g,%.9g,%.9g,%d,%d\n", plot_run_fps[i], frame, hs_world_time(w), st.position.x,
			        st.position.y, st.position.z, (int)st.contact, st.floor_contacts);
			if (frame > 0) {
				// the release: the last held frame (2) before a frame without contact
				if (isnan(release_t) && prev.contact == HS_CONTACT_GRASP && st.contact == HS_CONTACT_NONE) {
					release_t = hs_world_time(w) - hs_world_dt(w);
					release_x = prev.position.x;
					release_z = prev.position.z;
				}
				// the landing (as lands_at): the first frame with floor contacts after one without
				if (!isnan(release_t) && isnan(land_t) && prev.floor_contacts == 0 && st.floor_contacts > 0) {
					land_t = hs_world_time(w);
					land_x = st.position.x;
				}
			}
			prev = st;
			++frame;
		} while (hs_scenario_step(s));
		hs_object_state end;
		hs_world_object_state(w, id, &end);
		double miss = hypot(end.position.x - 2.0, end.position.y);
		int fails = hs_scenario_check(s, NULL);
		int n = i + 1;
		plot_run_var(vars, "fps", n, plot_run_fps[i]);
		plot_run_var(vars, "release_t", n, release_t);
		plot_run_var(vars, "release_x", n, release_x);
		plot_run_var(vars, "release_z", n, release_z);
		plot_run_var(vars, "land_t", n, land_t);
		plot_run_var(vars, "land_x", n, land_x);
		plot_run_var(vars, "end_x", n, end.position.x);
		plot_run_var(vars, "end_y", n, end.position.y);
		plot_run_var(vars, "miss", n, miss);
		plot_run_var(vars, "hit", n, miss <= 0.15);
		plot_run_var(vars, "fails", n, fails);
		fprintf(vars, "\n");
		hs_scenario_destroy(s);
	}
	if (fclose(out) != 0 || fclose(vars) != 0)
		status = status ? status : 1;
	return status;
}
