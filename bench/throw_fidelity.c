// throw_fidelity.c — item 4 of `make bench`: one continuous throw sampled at 12 … 120 frames/s.
//
// The 1999 paper's Experiment 2 game: throw a block at a target of radius 0.15 m, 2 m away. The
// hand path is continuous: an underarm swing of the block's centre on a circle (shoulder at
// (0, 0, 1.4) m, radius 0.7 m) from 60° behind the vertical, from rest, with constant angular
// acceleration, released at t = 1 s at 45° forward — the speed is chosen so the continuous-time
// release lands the block (G at rest height 0.025 m) exactly on the target centre x = 2 m. The
// release time is a frame time at every rate, so each rate sees the exact release point and only
// the velocity estimate differs.
//
// Estimators of the release velocity from the sampled hand positions P_k (frame k at k/F):
//  - eq. 3 (the paper): the object continues P(t) = 2P(t − Δt) − P(t − 2Δt) + gΔt², i.e. it leaves
//    P_K with (P_K − P_{K−1})/Δt (+ gΔt/2 from the Verlet step itself);
//  - window: the mean frame velocity over the last 0.1 s (at least 2 frames), (P_K − P_{K−n})/(nΔt);
//  - lsq: a quadratic least-squares fit over the last 0.16 s of frames (at least 3), its slope at P_K;
//  - tracker: the library's own 50 Hz tracker (the spring model's, hs_world_tracker_state: a
//    quadratic fit over its 9-sample buffer), fed the sampled path through hs_world_set_stylus.
// Landing = where the parabola from P_K with that velocity meets z = 0.025 m; error = distance to
// the continuous-time landing point. Each is given noise-free and as the RMS over trials with the
// Fastrak's 0.762 mm RMS position noise (seeded gsl_rng_mt19937): the same noisy frames for every
// estimator, the tracker included (noise is input: the library adds none). Last column: the
// library end to end — a hand world whose hand grasps the block, follows the sampled path and
// opens after frame K; the block's rest point (landing is frame-quantised: it stops in the first
// frame after touching down) and whether the grasp held.
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define SHOULDER_Z 1.4
#define ARM 0.7
#define PHI0 (-60.0 * HS_PI / 180.0)
#define PHI_R (45.0 * HS_PI / 180.0)
#define T_RELEASE 1.0
// The grasp posture's width: 5 mm less than the cube, the fingertips pressing into its faces (a
// grasp of exactly the cube's width leaves them on the faces, and the glove deadband 1.5 deg short).
#define BENCH_SQUEEZE (BENCH_CUBE - 0.005)
#define TARGET_X 2.0
#define TARGET_R 0.15
#define REST_Z (0.5 * BENCH_CUBE)
#define NOISE 0.762e-3 // m RMS per axis: the Fastrak's 0.03 inch

enum { E_EQ3 = 0, E_WINDOW, E_LSQ, E_TRACKER, N_EST };
static const char *const est_names[N_EST] = {"eq3-2frame", "window-0.1s", "lsq-0.16s", "tracker-50Hz"};

static const int frame_rates[] = {12, 17, 24, 30, 60, 90, 120};
#define N_FR ((int)(sizeof frame_rates / sizeof frame_rates[0]))

// The swing: φ(t) with constant angular acceleration from rest, φ(T_RELEASE) = φ_r at ω_r.
typedef struct swing {
	double omega_r; // rad/s at release
	double t_start; // s: the swing starts from rest
	double alpha;   // rad/s²
} swing;

static hs_vec3 landing(hs_vec3 p, hs_vec3 v) {
	double t = (v.z + sqrt(v.z * v.z + 2.0 * BENCH_G * (p.z - REST_Z))) / BENCH_G;
	return hs_v3(p.x + v.x * t, p.y + v.y * t, REST_Z);
}

static swing make_swing(void) {
	// release point and direction, then the speed that lands on the target (45°: v² = g Δx² / (h + Δx))
	double xr = ARM * sin(PHI_R), zr = SHOULDER_Z - ARM * cos(PHI_R);
	double dx = TARGET_X - xr, h = zr - REST_Z;
	double v = sqrt(BENCH_G * dx * dx / (h + dx));
	swing s;
	s.omega_r = v / ARM;
	double duration = 2.0 * (PHI_R - PHI0) / s.omega_r;
	s.t_start = T_RELEASE - duration;
	s.alpha = s.omega_r / duration;
	return s;
}

static double phi_at(const swing *s, double t) {
	if (t <= s->t_start)
		return PHI0;
	if (t <= T_RELEASE) {
		double u = t - s->t_start;
		return PHI0 + 0.5 * s->alpha * u * u;
	}
	return PHI_R + s->omega_r * (t - T_RELEASE); // the arm swings on after the release
}

static hs_vec3 path_at(const swing *s, double t) {
	double phi = phi_at(s, t);
	return hs_v3(ARM * sin(phi), 0.0, SHOULDER_Z - ARM * cos(phi));
}

// ---------------------------------------------------------------------------------------------
// The estimators

static hs_vec3 est_eq3(const hs_vec3 *p, int k, double dt) {
	hs_vec3 v = hs_scale(hs_sub(p[k], p[k - 1]), 1.0 / dt);
	return hs_add(v, hs_v3(0.0, 0.0, -0.5 * BENCH_G * dt)); // the Verlet parabola through P_{K−1}, P_K
}

static int window_frames(int fps) {
	int n = (int)lround(0.1 * fps);
	return n < 2 ? 2 : n;
}

static hs_vec3 est_window(const hs_vec3 *p, int k, double dt, int fps) {
	int n = window_frames(fps);
	return hs_scale(hs_sub(p[k], p[k - n]), 1.0 / ((double)n * dt));
}

static int lsq_frames(int fps) {
	int n = (int)lround(0.16 * fps) + 1;
	return n < 3 ? 3 : n;
}

// slope at τ = 0 of the least-squares quadratic through (τ_j = −j Δt, p[k − j]), j < n
static hs_vec3 est_lsq(const hs_vec3 *p, int k, double dt, int fps) {
	int n = lsq_frames(fps);
	double m[5] = {0, 0, 0, 0, 0};
	hs_vec3 r0 = hs_v3(0, 0, 0), r1 = r0, r2 = r0;
	for (int j = 0; j < n; ++j) {
		double tau = -(double)j, t2 = tau * tau;
		hs_vec3 y = hs_sub(p[k - j], p[k]);
		m[0] += 1.0;
		m[1] += tau;
		m[2] += t2;
		m[3] += t2 * tau;
		m[4] += t2 * t2;
		r0 = hs_add(r0, y);
		r1 = hs_mul_add(r1, tau, y);
		r2 = hs_mul_add(r2, t2, y);
	}
	double a12 = m[2] * m[3] - m[1] * m[4], a22 = m[0] * m[4] - m[2] * m[2], a23 = m[1] * m[2] - m[0] * m[3];
	double a11 = m[2] * m[4] - m[3] * m[3], a13 = m[1] * m[3] - m[2] * m[2];
	double det = m[0] * a11 + m[1] * a12 + m[2] * a13;
	hs_vec3 c1 = hs_scale(hs_add(hs_add(hs_scale(r0, a12), hs_scale(r1, a22)), hs_scale(r2, a23)), 1.0 / det);
	return hs_scale(c1, 1.0 / dt);
}

// The library's tracker (spring model, 50 Hz, 9-sample quadratic fit) fed the frames 0 … k.
static hs_vec3 est_tracker(const hs_vec3 *p, int k, double dt) {
	hs_world_def wd = hs_default_world_def();
	wd.dt = dt;
	wd.max_objects = 1;
	wd.max_hands = 0;
	wd.kind = HS_WORLD_SPRING; // the default spring definition
	hs_world *w = hs_world_create(&wd, NULL);
	hs_world_set_stylus(w, p[0], hs_quat_identity(), false);
	for (int j = 1; j <= k; ++j) { // the stylus pose at the end of frame j
		hs_world_set_stylus(w, p[j], hs_quat_identity(), false);
		hs_world_step(w);
	}
	hs_tracker_state ts;
	hs_world_tracker_state(w, &ts);
	hs_world_destroy(w);
	return ts.velocity;
}

// ---------------------------------------------------------------------------------------------
// The library end to end: a hand grasps the block, swings it, opens after the release frame

typedef struct e2e_result {
	hs_vec3 rest;       // where the block came to rest
	long lost_frame;    // first frame ≤ K without GRASP (−1: held to the release)
	bool touched_after; // the open hand touched the flying block
	bool rested;
	hs_vec3 release_velocity; // m/s, the block's first free frame
} e2e_result;

static e2e_result end_to_end(const swing *s, int fps, uint64_t *checksum) {
	e2e_result r;
	memset(&r, 0, sizeof r);
	r.lost_frame = -1;
	double dt = 1.0 / fps;
	int K = (int)lround(T_RELEASE * fps);
	hs_world_def wd = hs_default_world_def();
	wd.dt = dt;
	wd.max_objects = 1;
	wd.max_hands = 1;
	hs_status st;
	hs_world *w = hs_world_create(&wd, &st);
	hs_shape *cube = hs_shape_box(hs_v3(BENCH_CUBE, BENCH_CUBE, BENCH_CUBE), &st);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, cube, &st);
	hs_shape_destroy(cube);
	od.position = path_at(s, 0.0);
	hs_object_id id = hs_world_add_object(w, &od, &st);
	hs_hand_def hd = hs_default_hand_def();
	hs_hand_id hand = hs_world_add_hand(w, &hd, &st);
	uint8_t grasp[HS_GLOVE_SENSORS], open[HS_GLOVE_SENSORS];
	hs_hand_posture(&hd, HS_POSTURE_GRASP, BENCH_SQUEEZE, grasp);
	hs_hand_posture(&hd, HS_POSTURE_OPEN, 0.0, open);
	hs_vec3 grip, axis;
	hs_hand_grip(&hd, grasp, &grip, &axis);
	// placed open at the start, it closes on the cube in the first frame (a hand placed around an
	// object touches nothing until it has come out of it: docs/model.md §3)
	hs_world_set_hand(w, hand, hs_sub(path_at(s, 0.0), grip), hs_quat_identity(), open);
	long max_frames = (long)(4.0 * fps);
	hs_object_state os;
	for (long f = 1; f <= max_frames; ++f) {
		double t = (double)f * dt;
		bool held = f <= K;
		hs_world_set_hand(w, hand, hs_sub(path_at(s, t), grip), hs_quat_identity(), held ? grasp : open);
		hs_world_step(w);
		hs_world_object_state(w, id, &os);
		if (held && os.contact != HS_CONTACT_GRASP && r.lost_frame < 0)
			r.lost_frame = f;
		if (!held && os.contact != HS_CONTACT_NONE)
			r.touched_after = true;
		if (f == K + 1)
			r.release_velocity = os.velocity;
		if (f > K && os.resting) {
			r.rested = true;
			break;
		}
	}
	r.rest = os.position;
	*checksum = bench_mix(*checksum, os.position.x) ^ hs_world_hash(w);
	hs_world_destroy(w);
	return r;
}

// The largest per-frame hand displacement (mm, 1 mm steps) along `dir` for which a 5 cm cube held
// in the grasp posture stays GRASP for 5 frames — every smaller displacement holding too.
static int hold_limit_mm(hs_vec3 dir) {
	hs_hand_def hd = hs_default_hand_def();
	uint8_t grasp[HS_GLOVE_SENSORS], open[HS_GLOVE_SENSORS];
	hs_hand_posture(&hd, HS_POSTURE_GRASP, BENCH_SQUEEZE, grasp);
	hs_hand_posture(&hd, HS_POSTURE_OPEN, 0.0, open);
	hs_vec3 grip, axis;
	hs_hand_grip(&hd, grasp, &grip, &axis);
	for (int mm = 1; mm <= 200; ++mm) {
		hs_world_def wd = hs_default_world_def();
		wd.max_objects = 1;
		wd.max_hands = 1;
		hs_world *w = hs_world_create(&wd, NULL);
		hs_shape *cube = hs_shape_box(hs_v3(BENCH_CUBE, BENCH_CUBE, BENCH_CUBE), NULL);
		hs_object_def od = hs_default_object_def();
		od.shape = hs_world_add_shape(w, cube, NULL);
		hs_shape_destroy(cube);
		od.position = hs_v3(0.0, 0.0, 1.0);
		hs_object_id id = hs_world_add_object(w, &od, NULL);
		hs_hand_id hand = hs_world_add_hand(w, &hd, NULL);
		hs_world_set_hand(w, hand, hs_sub(od.position, grip), hs_quat_identity(), open); // closes in frame 0
		bool held = true;
		for (int f = 0; f <= 5 && held; ++f) {
			hs_vec3 wrist = hs_add(hs_sub(od.position, grip), hs_scale(dir, 1e-3 * mm * f));
			hs_world_set_hand(w, hand, wrist, hs_quat_identity(), grasp);
			hs_world_step(w);
			hs_object_state os;
			hs_world_object_state(w, id, &os);
			held = os.contact == HS_CONTACT_GRASP;
		}
		hs_world_destroy(w);
		if (!held)
			return mm - 1;
	}
	return 200;
}

// ---------------------------------------------------------------------------------------------

void bench_throw(const bench_opts *opts, bench_shared *shared) {
	swing s = make_swing();
	hs_vec3 pr = path_at(&s, T_RELEASE);
	hs_vec3 vr = hs_scale(hs_v3(cos(PHI_R), 0.0, sin(PHI_R)), s.omega_r * ARM);
	hs_vec3 exact = landing(pr, vr);
	int trials = opts->quick ? 40 : 400;
	uint64_t checksum = 14695981039346656037ull;
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(rng, 1);

	double err[N_FR][N_EST], land[N_FR][N_EST], rms[N_FR][N_EST];
	e2e_result e2e[N_FR];
	for (int f = 0; f < N_FR; ++f) {
		int fps = frame_rates[f], K = (int)lround(T_RELEASE * fps);
		double dt = 1.0 / fps;
		hs_vec3 *p = malloc((size_t)(K + 1) * sizeof *p), *q = malloc((size_t)(K + 1) * sizeof *q);
		if (!p || !q) {
			fprintf(stderr, "bench: throw: out of memory\n");
			exit(2);
		}
		for (int k = 0; k <= K; ++k)
			p[k] = path_at(&s, (double)k * dt);
		// noise-free
		hs_vec3 v[N_EST] = {est_eq3(p, K, dt), est_window(p, K, dt, fps), est_lsq(p, K, dt, fps),
		                    est_tracker(p, K, dt)};
		for (int e = 0; e < N_EST; ++e) {
			hs_vec3 l = landing(p[K], v[e]);
			land[f][e] = l.x;
			err[f][e] = hs_distance(l, exact);
		}
		// with the Fastrak's noise
		double sum[N_EST] = {0, 0, 0, 0};
		for (int trial = 0; trial < trials; ++trial) {
			for (int k = 0; k <= K; ++k)
				q[k] = hs_add(p[k], hs_v3(gsl_ran_gaussian(rng, NOISE), gsl_ran_gaussian(rng, NOISE),
				                          gsl_ran_gaussian(rng, NOISE)));
			hs_vec3 vn[N_EST] = {est_eq3(q, K, dt), est_window(q, K, dt, fps), est_lsq(q, K, dt, fps),
			                     est_tracker(q, K, dt)};
			for (int e = 0; e < N_EST; ++e) {
				double d = hs_distance(landing(q[K], vn[e]), exact);
				sum[e] += d * d;
				checksum = bench_mix(checksum, d);
			}
		}
		for (int e = 0; e < N_EST; ++e)
			rms[f][e] = sqrt(sum[e] / trials);
		e2e[f] = end_to_end(&s, fps, &checksum);
		bench_progress("[throw] %3d frames/s: eq. 3 lands %.3f m off, lsq %.3f m, library end to end rests at x = %.3f m%s\n",
		               fps, err[f][E_EQ3], err[f][E_LSQ], e2e[f].rest.x,
		               e2e[f].lost_frame >= 0 ? " (grasp lost before the release)" : "");
		free(p);
		free(q);
	}
	gsl_rng_free(rng);
	shared->checksum ^= checksum;

	char about[200];
	snprintf(about, sizeof about,
	         "throw at a %.2f m target %.1f m away; continuous-time landing x = %.6f m; errors in m; noisy = RMS of %d "
	         "trials at %.3f mm RMS",
	         TARGET_R, TARGET_X, exact.x, trials, 1e3 * NOISE);
	FILE *csv = bench_csv(opts, "throw.csv", about);
	fprintf(csv, "fps");
	for (int e = 0; e < N_EST; ++e)
		fprintf(csv, ",%s_x,%s_err,%s_noisy_rms", est_names[e], est_names[e], est_names[e]);
	fprintf(csv, ",library_rest_x,library_err,library_grasp_lost_frame\n");
	for (int f = 0; f < N_FR; ++f) {
		fprintf(csv, "%d", frame_rates[f]);
		for (int e = 0; e < N_EST; ++e)
			fprintf(csv, ",%.6f,%.6e,%.6e", land[f][e], fmax(err[f][e], 1e-9), rms[f][e]);
		fprintf(csv, ",%.6f,%.6e,%ld\n", e2e[f].rest.x, fabs(e2e[f].rest.x - exact.x), e2e[f].lost_frame);
	}
	fclose(csv);

	printf("\n== 4. Throw fidelity: one continuous swing sampled at 12-120 frames/s ==\n");
	printf("target: r = %.2f m at x = %.1f m; release at t = 1 s, %.3f m/s at 45 deg from (%.3f, %.3f) m; continuous "
	       "landing x = %.4f m\n",
	       TARGET_R, TARGET_X, s.omega_r * ARM, pr.x, pr.z, exact.x);
	printf("landing x (error) per release-velocity estimator, noise-free | RMS error with %.3f mm noise (%d trials) | "
	       "library end to end\n",
	       1e3 * NOISE, trials);
	printf("%5s", "fps");
	for (int e = 0; e < N_EST; ++e)
		printf(" | %18s", est_names[e]);
	printf(" || %7s %7s %7s %7s || %s\n", "eq3", "window", "lsq", "tracker", "library: rest x (err), grasp");
	for (int f = 0; f < N_FR; ++f) {
		printf("%5d", frame_rates[f]);
		for (int e = 0; e < N_EST; ++e)
			printf(" | %7.3f (%8.2e)", land[f][e], err[f][e]);
		char note[64];
		if (e2e[f].lost_frame >= 0)
			snprintf(note, sizeof note, "grasp LOST at frame %ld/%d", e2e[f].lost_frame,
			         (int)lround(T_RELEASE * frame_rates[f]));
		else
			snprintf(note, sizeof note, "held%s", e2e[f].touched_after ? ", touched after release" : "");
		printf(" || %7.4f %7.4f %7.4f %7.4f || %6.3f (%.3f) %s\n", rms[f][E_EQ3], rms[f][E_WINDOW], rms[f][E_LSQ],
		       rms[f][E_TRACKER], e2e[f].rest.x, fabs(e2e[f].rest.x - exact.x), note);
	}

	// why the low rates lose the block: how far the hand may move in one frame and keep it
	static const struct {
		const char *name;
		hs_vec3 dir;
	} dirs[] = {{"+x (toward the fingertips)", {1, 0, 0}}, {"-x (toward the thumb)", {-1, 0, 0}}, {"+z (up)", {0, 0, 1}},
	            {"-z (down)", {0, 0, -1}}, {"45 deg forward-up, the throw", {0.70710678118654752, 0, 0.70710678118654752}}};
	int limits[5];
	printf("largest hand displacement per frame that keeps a 5 cm cube GRASP (1 mm steps, 200 = no limit found):\n ");
	for (int d = 0; d < 5; ++d) {
		limits[d] = hold_limit_mm(dirs[d].dir);
		printf("%s %s %d mm", d ? "," : "", dirs[d].name, limits[d]);
	}
	printf("\n the swing moves the hand up to %.0f mm per frame at 12 frames/s, %.0f at 30, %.0f at 60\n",
	       1e3 * s.omega_r * ARM / 12.0, 1e3 * s.omega_r * ARM / 30.0, 1e3 * s.omega_r * ARM / 60.0);

	char value[96];
	int f12 = 0, f60 = 4;
	snprintf(value, sizeof value, "%.3f / %.3f m at 12 / 60 frames/s (lsq %.3f / %.3f)", err[f12][E_EQ3],
	         err[f60][E_EQ3], err[f12][E_LSQ], err[f60][E_LSQ]);
	bench_summary_add("4 throw", "eq. 3 landing error, noise-free", value, BENCH_INFO);
	snprintf(value, sizeof value, "%.3f / %.3f m at 12 / 120 frames/s (lsq %.3f / %.3f)", rms[f12][E_EQ3],
	         rms[N_FR - 1][E_EQ3], rms[f12][E_LSQ], rms[N_FR - 1][E_LSQ]);
	bench_summary_add("4 throw", "eq. 3 landing RMS error, 0.76 mm noise", value, BENCH_INFO);
	int held = 0;
	for (int f = 0; f < N_FR; ++f)
		held += e2e[f].lost_frame < 0 && fabs(e2e[f].rest.x - exact.x) <= TARGET_R;
	snprintf(value, sizeof value, "%d of %d frame rates hit the %.2f m target", held, N_FR, TARGET_R);
	bench_summary_add("4 throw", "library end to end (grasp, swing, open)", value, BENCH_INFO);
	snprintf(value, sizeof value, "%d mm up, %d mm forward-up (5 cm cube)", limits[2], limits[4]);
	bench_summary_add("4 throw", "largest hand motion per frame that keeps a grasp", value, BENCH_INFO);
}
