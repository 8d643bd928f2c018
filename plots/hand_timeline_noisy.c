// hand_timeline_noisy.c — data for the contact-state timeline (1999 paper, Fig. 12) of a grasp
// under realistic input noise: runs scenarios/hand/grasp_adjoining_faces.yaml once as written
// (noise-free) and once per noise seed 1..5 (hs_scenario_load_with with noise on: the glove's
// +-4 units per sensor and the tracker's 0.762 mm and 0.15 deg on the wrist, unless the file says
// other levels) and records the cube's contact state and centre G every frame.
//
// usage: hand_timeline_noisy OUTDIR [SCENARIO] — writes OUTDIR/hand_timeline_noisy.csv (header
// row seed,frame,t,contact,x,y,z, then the runs' rows one after another: noise-free first, then
// seeds 1..5, told apart by seed, 0 the noise-free run), OUTDIR/hand_timeline_noisy.txt (what the
// columns are) and OUTDIR/hand_timeline_noisy.vars
// (gnuplot assignments per run i = 1..6: seed<i>, seq<i> (the state sequence, repeats collapsed,
// a string), grasp_t<i> (first frame in state 2), lost_t<i> (first frame after that not in
// state 2), lost_state<i> (its state), max_z<i>, end_x<i>, end_y<i>, end_z<i>, holds<i> (1 when
// it grasps and keeps the grasp at least as long as the noise-free run), fails<i> (the scenario's
// expectations that fail in that run)). The first object of the scenario is the one recorded.
// Exit status 0 whether or not a noisy grasp holds: the figure shows it.
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hs_harness.h"
#include "plot_run.h"

enum { RUNS = 6 }; // noise-free, then seeds 1..5

// OUTDIR/hand_timeline_noisy.txt, the CSV's sidecar
static int write_about(const char *dir, const char *scenario) {
	return plot_run_about(dir, "hand_timeline_noisy",
	                      "hand_timeline_noisy.csv: %s noise-free (seed 0) and with realistic input noise from seeds\n"
	                      "1-%d (the glove's +-4 units per sensor and the tracker's 0.762 mm and 0.15 deg on the wrist,\n"
	                      "unless the scenario says other levels)\n"
	                      "one row per frame, the runs one after another; column seed tells them apart\n"
	                      "seed: the input noise seed, 0 the noise-free run\n"
	                      "frame: frame number, 0 before the first step\n"
	                      "t: time, s\n"
	                      "contact: the scenario's first object's hand contact state, 0 none, 1 push at one point,\n"
	                      "  2 grasp, 3 push at several points\n"
	                      "x, y, z: its centre G, m\n",
	                      scenario, RUNS - 1);
}

int main(int argc, char **argv) {
	const char *path;
	FILE *out, *vars;
	int status = plot_run_outputs(argc, argv, "hand_timeline_noisy", "scenarios/hand/grasp_adjoining_faces.yaml", &path, &out, &vars);
	if (status)
		return status;
	double lost_t0 = NAN; // the noise-free run's
	for (int i = 0; i < RUNS && status == 0; ++i) {
		unsigned long seed = (unsigned long)i;
		hs_scenario *s = plot_run_load(path, 0.0, i > 0, seed);
		if (!s) {
			status = 2;
			break;
		}
		if (i == 0 && (write_about(argv[1], hs_scenario_name(s)) != 0 ||
		               fprintf(out, "seed,frame,t,contact,x,y,z\n") < 0)) {
			hs_scenario_destroy(s);
			status = 1;
			break;
		}
		hs_world *w = hs_scenario_world(s);
		hs_object_id id = hs_world_object_at(w, 0);
		char seq[256] = "[";
		size_t len = 1;
		int last = -1;
		double grasp_t = NAN, lost_t = NAN, lost_state = NAN, max_z = -INFINITY;
		long frame = 0;
		hs_object_state st;
		do {
			hs_world_object_state(w, id, &st);
			int c = (int)st.contact;
			double t = hs_world_time(w);
			fprintf(out, "%lu,%ld,%.9g,%d,%.9g,%.9g,%.9g\n", seed, frame, t, c, st.position.x, st.position.y,
			        st.position.z);
			if (c != last && len + 8 < sizeof seq)
				len += (size_t)snprintf(seq + len, sizeof seq - len, "%s%d", last < 0 ? "" : ", ", c);
			last = c;
			if (isnan(grasp_t) && c == HS_CONTACT_GRASP)
				grasp_t = t;
			else if (!isnan(grasp_t) && isnan(lost_t) && c != HS_CONTACT_GRASP) {
				lost_t = t;
				lost_state = c;
			}
			if (st.position.z > max_z)
				max_z = st.position.z;
			++frame;
		} while (hs_scenario_step(s));
		snprintf(seq + len, sizeof seq - len, "]");
		if (i == 0)
			lost_t0 = lost_t;
		hs_world_object_state(w, id, &st);
		bool holds = !isnan(grasp_t) && (isnan(lost_t) || lost_t >= lost_t0 - 0.5 * hs_scenario_dt(s));
		int n = i + 1;
		plot_run_var(vars, "seed", n, (double)seed);
		fprintf(vars, "seq%d = \"%s\"; ", n, seq);
		plot_run_var(vars, "grasp_t", n, grasp_t);
		plot_run_var(vars, "lost_t", n, lost_t);
		plot_run_var(vars, "lost_state", n, lost_state);
		plot_run_var(vars, "max_z", n, max_z);
		plot_run_var(vars, "end_x", n, st.position.x);
		plot_run_var(vars, "end_y", n, st.position.y);
		plot_run_var(vars, "end_z", n, st.position.z);
		plot_run_var(vars, "holds", n, holds);
		plot_run_var(vars, "fails", n, hs_scenario_check(s, NULL));
		fprintf(vars, "\n");
		hs_scenario_destroy(s);
	}
	if (fclose(out) != 0 || fclose(vars) != 0)
		status = status ? status : 1;
	return status;
}
