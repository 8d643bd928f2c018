// peers.c — item 5 of `make bench`: the seed scene in ODE and MuJoCo beside handspring.
//
// Each peer builds the seed scene through its own API (bench/peer_ode.c, bench/peer_mujoco.c):
// the ten 5 cm cubes of scenarios/seed_scene.yaml on a floor plane, the two that handspring's
// hand grasps driven as kinematic (ODE) or mocap (MuJoCo) bodies along the same loop, the other
// eight dynamic and resting, stepped at the same dt (1/60 s). handspring is timed again here,
// next to them, so the ratios come from one run on one machine state. Each peer also flies the
// projectile of item 3 at that dt (its own integrator, no contacts) and reports its range error.
#include <string.h>

#include "bench.h"

// The 1999 world's projectile at BENCH_DT (eq. 3): its range error as the peers measure theirs.
static double handspring_projectile_error(void) {
	hs_world_def wd = hs_default_world_def();
	wd.dt = BENCH_DT;
	wd.max_objects = 1;
	wd.max_hands = 0;
	hs_world *w = hs_world_create(&wd, NULL);
	hs_shape *cube = hs_shape_box(hs_v3(BENCH_CUBE, BENCH_CUBE, BENCH_CUBE), NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, cube, NULL);
	hs_shape_destroy(cube);
	od.position = hs_v3(0.0, 0.0, BENCH_PROJ_Z0);
	od.velocity = hs_v3(BENCH_PROJ_VX, 0.0, BENCH_PROJ_VZ);
	hs_object_id id = hs_world_add_object(w, &od, NULL);
	double xs[256], zs[256];
	int n = 0;
	hs_object_state os;
	hs_world_object_state(w, id, &os);
	xs[n] = os.position.x;
	zs[n++] = os.position.z;
	while (n < 256 && zs[n - 1] >= BENCH_PROJ_PLANE) {
		hs_world_step(w);
		hs_world_object_state(w, id, &os);
		xs[n] = os.position.x;
		zs[n++] = os.position.z;
	}
	hs_world_destroy(w);
	return fabs(bench_crossing_x(xs, zs, n, BENCH_PROJ_PLANE) - bench_projectile_range());
}

static void print_peer(const char *name, const char *version, double us, double us_min, double us_max, double hs_us,
                       double proj, const char *setup) {
	printf("%-11s %-22s %9.3f (%.3f-%.3f) %12.1fx %13.2e   %s\n", name, version, us, us_min, us_max, us / hs_us, proj,
	       setup);
}

void bench_peers(const bench_opts *opts, bench_shared *shared) {
	bench_stats hs = bench_seed_measure(opts, true);
	double hs_us = 1e6 * hs.median;
	double hs_proj = handspring_projectile_error();
	bench_progress("[peers] handspring seed scene: %.3f us/frame\n", hs_us);

	bench_peer_result peers[3];
	memset(peers, 0, sizeof peers);
	int n = 0;
#ifdef HS_BENCH_ODE
	n += bench_peer_ode(opts, &peers[n]);
#endif
#ifdef HS_BENCH_MUJOCO
	peers[n++] = bench_peer_mujoco(opts);
#endif

	printf("\n== 5. Peers: the seed scene (10 cubes, 2 moved along the hand's loop), dt = 1/60 s, same run ==\n");
	printf("%-11s %-22s %27s %13s %13s   %s\n", "engine", "version", "us/step median (min-max)", "peer/handspring",
	       "proj. error m", "setup");
	print_peer("handspring", HS_VERSION, hs_us, 1e6 * hs.min, 1e6 * hs.max, hs_us, hs_proj,
	           "1999 hand model: hand kinematics + full hand-object check + eq. 3 motion, skip_work on");
	FILE *csv = bench_csv(opts, "peers.csv", "the peers on the seed scene, microseconds per step, same run");
	fprintf(csv, "engine,version,us_per_step,us_min,us_max,peer_over_handspring,projectile_error_m,resting_drift_m\n");
	fprintf(csv, "handspring,%s,%.4f,%.4f,%.4f,1,%.3e,0\n", HS_VERSION, hs_us, 1e6 * hs.min, 1e6 * hs.max, hs_proj);
	for (int i = 0; i < n; ++i) {
		const bench_peer_result *p = &peers[i];
		if (!p->ran)
			continue;
		print_peer(p->name, p->version, 1e6 * p->step.median, 1e6 * p->step.min, 1e6 * p->step.max, hs_us,
		           p->projectile_error, p->setup);
		fprintf(csv, "%s,%s,%.4f,%.4f,%.4f,%.3f,%.3e,%.3e\n", p->name, p->version, 1e6 * p->step.median, 1e6 * p->step.min,
		        1e6 * p->step.max, 1e6 * p->step.median / hs_us, p->projectile_error, p->resting_drift);
		shared->checksum ^= p->checksum;
	}
	fclose(csv);
	printf("projectile: range to the z = 0.5 m plane from (0,0,1) m at (2,0,1) m/s, closed form %.6f m\n",
	       bench_projectile_range());

	char value[128];
	bool have_ode = false, have_mujoco = false;
	double worst = INFINITY;
	const char *worst_name = "";
	for (int i = 0; i < n; ++i) {
		if (!peers[i].ran)
			continue;
		have_ode = have_ode || strncmp(peers[i].name, "ODE", 3) == 0;
		have_mujoco = have_mujoco || strcmp(peers[i].name, "MuJoCo") == 0;
		double ratio = 1e6 * peers[i].step.median / hs_us;
		if (ratio < worst) {
			worst = ratio;
			worst_name = peers[i].name;
		}
		snprintf(value, sizeof value, "%.2f us/step = %.2fx handspring's; projectile error %.1e m",
		         1e6 * peers[i].step.median, ratio, peers[i].projectile_error);
		bench_summary_add("5 peers", peers[i].name, value, BENCH_INFO);
	}
	if (n > 0)
		snprintf(value, sizeof value, "%.2e m (peers %.1e m)", hs_proj, peers[0].projectile_error);
	else
		snprintf(value, sizeof value, "%.2e m", hs_proj);
	bench_summary_add("5 peers", "handspring projectile error at 1/60 s", value, BENCH_INFO);
	if (!have_ode || !have_mujoco) {
		printf("peers missing:%s%s: install them with 'sh scripts/deps.sh bench' (as root), or\n"
		       "  sudo apt-get install -y libode-dev libmujoco-dev   and run 'make bench' again\n",
		       have_ode ? "" : " ODE", have_mujoco ? "" : " MuJoCo");
		bench_summary_add("5 peers", have_ode ? "MuJoCo" : (have_mujoco ? "ODE" : "ODE, MuJoCo"),
		                  "not built: sh scripts/deps.sh bench", BENCH_INFO);
	}
	if (have_ode && have_mujoco)
		snprintf(value, sizeof value, "worst: %s %.2fx (handspring %.2f us/step)", worst_name, worst, hs_us);
	else
		snprintf(value, sizeof value, "peers not built");
	bench_summary_add("target", ">= 10x fewer us per step than ODE and MuJoCo", value,
	                  have_ode && have_mujoco ? (worst >= 10.0 ? BENCH_MET : BENCH_NOT_MET) : BENCH_UNKNOWN);
}
