// race.c — section `race` of `make bench`: a fair race. ODE and MuJoCo do handspring's job —
// finding where a moving hand touches the objects — on the same frames, and nothing else.
//
// The frames: one loop of the honest seed scene (bench/frame_rate.c: ten 5 cm cubes in a row, two
// of them grasped and carried along the hand's path, noisy glove readings, the wrist turning),
// recorded from handspring: per frame the hand's 20 check points and the cubes' poses. Each peer
// builds the hand as its closest shape — 15 capsules, one per finger segment (check point s to
// s + 1 of a finger) of handspring's finger_radius — and the ten cubes as boxes, then per frame
// moves the capsules and the two carried cubes to the recorded poses and generates contacts:
//  - ODE: dSpaceCollide2 of a simple space of the capsules against a hash space of the boxes, and
//    dCollide (up to 4 contacts) on each pair it reports;
//  - MuJoCo: every body free (mocap bodies, welded to the world, are never collided with each
//    other), qpos set, mj_kinematics + mj_collision; contype/conaffinity so that only capsule-box
//    pairs are tested.
// The same sleeping on both sides: the eight resting cubes are never moved, nor tested against the
// floor or each other (handspring's resting cubes are asleep). Each peer's capsule radius is
// searched so that its (finger, cube) pairs over the loop match handspring's count, and each peer is
// timed in interleaved pairs of batches with handspring's whole honest frame (glove kinematics, the
// full check, the grasp, the carrying, the state hash: more than contact generation), on CPU time;
// with valgrind on PATH, callgrind counts both sides' instructions (--profile-race,
// --profile-seed-honest). The output says what differs between the sides.
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#ifdef HS_BENCH_ODE
#include <ode/ode.h>
#endif
#ifdef HS_BENCH_MUJOCO
#include <mujoco/mujoco.h>
#endif

#define RACE_SEGMENTS 15

typedef struct race_job {
	bench_race_frame *frames;
	double radius; // m: the capsules' radius
	int k;         // frame within the loop
	long frames_run;
	long touches;  // (finger, cube) pairs in contact, summed over the frames run
	long agree;    // frames whose pairs are exactly handspring's
	long extra, missing; // pairs only this engine finds, pairs only handspring finds
	long contacts; // contact points the engine generated
	uint64_t touch; // this frame's pairs
} race_job;

// Finger segment g (finger g / 3, segment g % 3): from check point g / 3 · 4 + g % 3 to the next.
#if defined(HS_BENCH_ODE) || defined(HS_BENCH_MUJOCO)
static void segment(const bench_race_frame *f, int g, hs_vec3 *a, hs_vec3 *b) {
	int p = g / 3 * 4 + g % 3;
	*a = f->points[p];
	*b = f->points[p + 1];
}

// The rotation taking +z to the unit direction d (the capsules' axis in both peers).
static hs_quat z_to(hs_vec3 d) {
	double w = 1.0 + d.z;
	if (w < 1e-12)
		return hs_quat_from_axis_angle(hs_v3(1, 0, 0), HS_PI);
	return hs_quat_normalize((hs_quat){w, -d.y, d.x, 0.0}); // (1 + z·d, z × d)
}

static void tally(race_job *job, const bench_race_frame *f) {
	job->touches += __builtin_popcountll(job->touch);
	job->agree += job->touch == f->touch;
	job->extra += __builtin_popcountll(job->touch & ~f->touch);
	job->missing += __builtin_popcountll(f->touch & ~job->touch);
	job->frames_run++;
}
#endif // the peers' shared helpers

#ifdef HS_BENCH_ODE
typedef struct ode_race {
	race_job job;
	dSpaceID hand, cubes;
	dGeomID capsule[RACE_SEGMENTS], cube[10];
} ode_race;

static void ode_near(void *data, dGeomID a, dGeomID b) {
	ode_race *r = data;
	if (dGeomIsSpace(a) || dGeomIsSpace(b)) {
		dSpaceCollide2(a, b, data, ode_near);
		return;
	}
	dContactGeom c[4];
	int n = dCollide(a, b, 4, c, sizeof c[0]);
	if (n <= 0)
		return;
	r->job.contacts += n;
	intptr_t ia = (intptr_t)dGeomGetData(a), ib = (intptr_t)dGeomGetData(b); // capsules 100 + g, cubes i
	intptr_t g = ia >= 100 ? ia - 100 : ib - 100, cube = ia >= 100 ? ib : ia;
	r->job.touch |= 1ull << ((g / 3) * 10 + cube);
}

static void ode_place(dGeomID geom, hs_vec3 p, hs_quat q) {
	dQuaternion dq = {q.w, q.x, q.y, q.z};
	dGeomSetPosition(geom, p.x, p.y, p.z);
	dGeomSetQuaternion(geom, dq);
}

static void ode_frame(void *state, long frames) {
	ode_race *r = state;
	for (long n = 0; n < frames; ++n) {
		const bench_race_frame *f = &r->job.frames[r->job.k];
		for (int g = 0; g < RACE_SEGMENTS; ++g) {
			hs_vec3 a, b;
			segment(f, g, &a, &b);
			hs_vec3 d = hs_sub(b, a);
			double len = hs_length(d);
			dGeomCapsuleSetParams(r->capsule[g], r->job.radius, len);
			ode_place(r->capsule[g], hs_scale(hs_add(a, b), 0.5), z_to(hs_scale(d, 1.0 / len)));
		}
		for (int i = 0; i < 2; ++i) // the carried cubes; the eight resting ones never move
			ode_place(r->cube[i], f->pos[i], f->rot[i]);
		r->job.touch = 0;
		dSpaceCollide2((dGeomID)r->hand, (dGeomID)r->cubes, r, ode_near);
		tally(&r->job, f);
		r->job.k = r->job.k + 1 == BENCH_PATH_FRAMES ? 0 : r->job.k + 1;
	}
}

static void *ode_create(race_job proto) {
	dInitODE2(0);
	ode_race *r = calloc(1, sizeof *r);
	if (!r)
		return NULL;
	r->job = proto;
	r->hand = dSimpleSpaceCreate(0);
	r->cubes = dHashSpaceCreate(0);
	for (int g = 0; g < RACE_SEGMENTS; ++g) {
		r->capsule[g] = dCreateCapsule(r->hand, proto.radius, 0.01);
		dGeomSetData(r->capsule[g], (void *)(intptr_t)(100 + g));
	}
	for (int i = 0; i < 10; ++i) {
		r->cube[i] = dCreateBox(r->cubes, BENCH_CUBE, BENCH_CUBE, BENCH_CUBE);
		dGeomSetData(r->cube[i], (void *)(intptr_t)i);
		ode_place(r->cube[i], proto.frames[0].pos[i], proto.frames[0].rot[i]);
	}
	return r;
}

static void ode_set_radius(void *state, double radius) { ((ode_race *)state)->job.radius = radius; } // set each frame

static void ode_destroy(void *state) {
	ode_race *r = state;
	dSpaceDestroy(r->hand);
	dSpaceDestroy(r->cubes);
	free(r);
	dCloseODE();
}
#endif

#ifdef HS_BENCH_MUJOCO
typedef struct mj_race {
	race_job job;
	mjModel *m;
	mjData *d;
	int cube_geom0, capsule_geom0;
} mj_race;

static void mj_place(mjData *d, int body, hs_vec3 p, hs_quat q) { // free joint `body`: 7 qpos each
	double *x = d->qpos + 7 * body;
	x[0] = p.x;
	x[1] = p.y;
	x[2] = p.z;
	x[3] = q.w;
	x[4] = q.x;
	x[5] = q.y;
	x[6] = q.z;
}

static void mj_frame(void *state, long frames) {
	mj_race *r = state;
	for (long n = 0; n < frames; ++n) {
		const bench_race_frame *f = &r->job.frames[r->job.k];
		for (int g = 0; g < RACE_SEGMENTS; ++g) { // bodies 10 .. 24: the capsules
			hs_vec3 a, b;
			segment(f, g, &a, &b);
			hs_vec3 d = hs_sub(b, a);
			mj_place(r->d, 10 + g, hs_scale(hs_add(a, b), 0.5), z_to(hs_normalize(d)));
		}
		for (int i = 0; i < 2; ++i)
			mj_place(r->d, i, f->pos[i], f->rot[i]);
		mj_kinematics(r->m, r->d);
		mj_collision(r->m, r->d);
		r->job.touch = 0;
		r->job.contacts += r->d->ncon;
		for (int c = 0; c < r->d->ncon; ++c) {
			int g1 = r->d->contact[c].geom1, g2 = r->d->contact[c].geom2;
			int cap = g1 >= r->capsule_geom0 ? g1 : g2, cube = g1 >= r->capsule_geom0 ? g2 : g1;
			r->job.touch |= 1ull << (((cap - r->capsule_geom0) / 3) * 10 + (cube - r->cube_geom0));
		}
		tally(&r->job, f);
		r->job.k = r->job.k + 1 == BENCH_PATH_FRAMES ? 0 : r->job.k + 1;
	}
}

static void *mj_create(race_job proto) {
	size_t size = 16384, len = 0;
	char *xml = malloc(size);
	if (!xml)
		return NULL;
	double h = 0.5 * BENCH_CUBE;
	len += (size_t)snprintf(xml + len, size - len, "<mujoco model=\"race\"><option timestep=\"%.17g\"/><worldbody>\n",
	                        BENCH_DT);
	for (int i = 0; i < 10; ++i) // cubes: conaffinity only; capsules: contype only: capsule-cube pairs
		len += (size_t)snprintf(xml + len, size - len,
		                        "<body name=\"cube%d\"><freejoint/><geom type=\"box\" size=\"%g %g %g\" contype=\"0\" "
		                        "conaffinity=\"1\"/></body>\n",
		                        i, h, h, h);
	for (int g = 0; g < RACE_SEGMENTS; ++g) {
		hs_vec3 a, b;
		segment(&proto.frames[0], g, &a, &b);
		len += (size_t)snprintf(xml + len, size - len,
		                        "<body name=\"seg%d\"><freejoint/><geom type=\"capsule\" size=\"%.17g %.17g\" contype=\"1\" "
		                        "conaffinity=\"0\"/></body>\n",
		                        g, proto.radius, 0.5 * hs_distance(a, b));
	}
	snprintf(xml + len, size - len, "</worldbody></mujoco>\n");
	mjVFS *vfs = malloc(sizeof *vfs);
	mj_race *r = calloc(1, sizeof *r);
	if (!vfs || !r) {
		free(xml);
		free(vfs);
		free(r);
		return NULL;
	}
	mj_defaultVFS(vfs);
	int n = (int)strlen(xml);
	mj_makeEmptyFileVFS(vfs, "race.xml", n);
	memcpy(vfs->filedata[mj_findFileVFS(vfs, "race.xml")], xml, (size_t)n);
	char error[1000] = "";
	r->m = mj_loadXML("race.xml", vfs, error, (int)sizeof error);
	mj_deleteVFS(vfs);
	free(vfs);
	free(xml);
	if (!r->m) {
		fprintf(stderr, "bench: race: MuJoCo: %s\n", error);
		free(r);
		return NULL;
	}
	r->d = mj_makeData(r->m);
	r->job = proto;
	r->cube_geom0 = mj_name2id(r->m, mjOBJ_BODY, "cube0") >= 0 ? r->m->body_geomadr[mj_name2id(r->m, mjOBJ_BODY, "cube0")] : 0;
	r->capsule_geom0 = r->m->body_geomadr[mj_name2id(r->m, mjOBJ_BODY, "seg0")];
	for (int i = 0; i < 10; ++i)
		mj_place(r->d, i, proto.frames[0].pos[i], proto.frames[0].rot[i]);
	return r;
}

// The capsules' radius: their size and bounding radius (half-length + radius) in the model.
static void mj_set_radius(void *state, double radius) {
	mj_race *r = state;
	for (int g = r->capsule_geom0; g < r->capsule_geom0 + RACE_SEGMENTS; ++g) {
		r->m->geom_rbound[g] = r->m->geom_size[3 * g + 1] + radius;
		r->m->geom_size[3 * g] = radius;
	}
	r->job.radius = radius;
}

static void mj_destroy(void *state) {
	mj_race *r = state;
	mj_deleteData(r->d);
	mj_deleteModel(r->m);
	free(r);
}
#endif

// A peer: made from the recorded frames, its capsules' radius set, stepped one frame at a time.
// Each one's state starts with its race_job.
typedef struct race_engine {
	const char *name, *key;
	void *(*create)(race_job proto);
	void (*set_radius)(void *state, double radius);
	bench_step_fn step;
	void (*destroy)(void *state);
} race_engine;

static const race_engine engines[] = {
#ifdef HS_BENCH_ODE
    {"ODE", "ode", ode_create, ode_set_radius, ode_frame, ode_destroy},
#endif
#ifdef HS_BENCH_MUJOCO
    {"MuJoCo", "mujoco", mj_create, mj_set_radius, mj_frame, mj_destroy},
#endif
    {NULL, NULL, NULL, NULL, NULL, NULL},
};

// One loop at `radius` from frame 0, its counts kept in the job; returns the (finger, cube) pairs.
static long loop_at(const race_engine *e, void *state, double radius) {
	race_job *job = state, keep = *job;
	e->set_radius(state, radius);
	memset(job, 0, sizeof *job);
	job->frames = keep.frames;
	job->radius = radius;
	e->step(state, BENCH_PATH_FRAMES);
	return job->touches;
}

// The capsules' radius whose pairs over the loop match handspring's `target`: the largest radius
// in [0, 2 finger_radius] with at most `target` pairs (pairs only grow with the radius), by
// bisection, 48 halvings; the least radius above it when that one's count is nearer.
static double match_radius(const race_engine *e, void *state, double finger_radius, long target) {
	double lo = 0.0, hi = 2.0 * finger_radius;
	if (loop_at(e, state, hi) <= target)
		lo = hi;
	for (int it = 0; it < 48 && hi > lo; ++it) {
		double mid = 0.5 * (lo + hi);
		if (loop_at(e, state, mid) <= target)
			lo = mid;
		else
			hi = mid;
	}
	long at_lo = loop_at(e, state, lo), at_hi = loop_at(e, state, hi);
	double r = labs(at_lo - target) <= labs(at_hi - target) ? lo : hi;
	loop_at(e, state, r); // its counts kept
	return r;
}

static void *race_make(const race_engine *e, const race_job *proto, long hs_touches, double *radius) {
	void *state = e->create(*proto);
	if (!state)
		return NULL;
	*radius = match_radius(e, state, proto->radius, hs_touches);
	return state;
}

// `hs_bench --profile-race ENGINE,N`: N frames of one peer at its matched radius, for callgrind.
__attribute__((noinline)) void race_profiled_frames(const race_engine *e, void *state, long frames);
void race_profiled_frames(const race_engine *e, void *state, long frames) { e->step(state, frames); }

static race_job race_proto(long *hs_touches) {
	race_job proto;
	memset(&proto, 0, sizeof proto);
	proto.frames = malloc(BENCH_PATH_FRAMES * sizeof *proto.frames);
	if (!proto.frames) {
		fprintf(stderr, "bench: race: out of memory\n");
		exit(2);
	}
	bench_race_record(proto.frames, &proto.radius);
	*hs_touches = 0;
	for (int f = 0; f < BENCH_PATH_FRAMES; ++f)
		*hs_touches += __builtin_popcountll(proto.frames[f].touch);
	return proto;
}

void bench_profile_race(const char *spec) {
	char name[32];
	const char *frames, *unused;
	bench_split_spec(spec, name, sizeof name, &frames, &unused);
	long hs_touches;
	race_job proto = race_proto(&hs_touches);
	for (const race_engine *e = engines; e->name; ++e) {
		if (strcmp(e->key, name) != 0)
			continue;
		double radius;
		void *state = race_make(e, &proto, hs_touches, &radius);
		if (state) {
			long n = frames ? atol(frames) : 600;
			race_profiled_frames(e, state, n);
			printf("race %s: %ld frames at radius %.6f m, %ld pairs a loop (handspring %ld)\n", e->name, n, radius,
			       ((race_job *)state)->touches, hs_touches);
			e->destroy(state);
		}
	}
	free(proto.frames);
}

static void instr_text(char *out, size_t size, double instr) {
	if (instr < 0.0)
		snprintf(out, size, "-");
	else
		snprintf(out, size, "%.0f", instr);
}

// One peer: its radius matched, then timed in interleaved pairs with handspring's honest frame.
static bool race_one(const race_engine *e, const race_job *proto, long hs_touches, const bench_opts *opts, FILE *csv,
                     double hs_instr, double *ratio, double *instr_ratio) {
	double radius;
	void *state = race_make(e, proto, hs_touches, &radius);
	if (!state)
		return false;
	race_job job = *(race_job *)state;
	bench_scene *hs = bench_honest_scene(BENCH_SHAPE_CUBE, 10, 0);
	bench_pair p = bench_measure_pair_cpu(e->step, state, bench_scene_step, hs, opts);
	bench_scene_destroy(hs);
	e->destroy(state);
	char args[64], peer_i[32], ratio_i[32] = "-";
	snprintf(args, sizeof args, "--profile-race %s,600", e->key);
	double instr = bench_callgrind(opts, args, "race_profiled_frames") / 600.0;
	instr_text(peer_i, sizeof peer_i, instr);
	if (instr > 0.0 && hs_instr > 0.0)
		snprintf(ratio_i, sizeof ratio_i, "%.2fx", instr / hs_instr);
	printf("%-7s %9.6f %6ld %5ld %5ld %7.1f%% %8.3f (%.3f-%.3f) %8.3f %6.2fx (%.2f-%.2f) %9s %7s\n", e->name, radius,
	       job.touches, job.extra, job.missing, 100.0 * (double)job.agree / (double)job.frames_run, 1e6 * p.a.median,
	       1e6 * p.a.min, 1e6 * p.a.max, 1e6 * p.b.median, p.ratio, p.ratio_min, p.ratio_max, peer_i, ratio_i);
	fprintf(csv, "%s,%.6f,%ld,%ld,%ld,%ld,%ld,%.1f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%.3f,%s,%s\n", e->name, radius,
	        job.touches, hs_touches, job.extra, job.missing, job.contacts,
	        100.0 * (double)job.agree / (double)job.frames_run, 1e6 * p.a.median, 1e6 * p.a.min, 1e6 * p.a.max,
	        1e6 * p.b.median, p.ratio, p.ratio_min, p.ratio_max, instr < 0.0 ? "" : peer_i,
	        instr < 0.0 ? "" : ratio_i);
	char value[192];
	snprintf(value, sizeof value, "%.2fx handspring's CPU time (%.2f-%.2f), %s instructions; pairs %ld vs %ld at r = %.4f m",
	         p.ratio, p.ratio_min, p.ratio_max, ratio_i, job.touches, hs_touches, radius);
	bench_summary_add("race", e->name, value, BENCH_INFO);
	*ratio = p.ratio;
	*instr_ratio = instr > 0.0 && hs_instr > 0.0 ? instr / hs_instr : -1.0;
	return true;
}

static void race_header(double finger_radius, double hs_instr, long hs_touches) {
	char hs_i[32];
	instr_text(hs_i, sizeof hs_i, hs_instr);
	printf("\n== Race: contact generation only, on the honest seed scene's frames (CPU time, interleaved pairs) ==\n");
	printf("what differs between the sides:\n"
	       " - handspring runs its whole honest frame (glove kinematics from the noisy reading, the check of 20 check\n"
	       "   points and 60 check lines with its rules, the grasp, carrying the 2 cubes, the state hash): %s\n"
	       "   instructions a frame (callgrind, fr_profiled_frames);\n"
	       " - each peer only generates capsule-box contacts on one recorded loop of %d frames: the hand as 15\n"
	       "   capsules (one per finger segment, check point to check point) moved to the recorded points, the 2\n"
	       "   carried cubes to their recorded poses, the 8 resting cubes never moved nor tested against each other;\n"
	       " - handspring's fingers are points and prism edges %.4f m from the axis; each peer's capsule radius is\n"
	       "   searched (bisection: the largest radius whose (finger, cube) pairs over the loop do not exceed\n"
	       "   handspring's %ld) so that the pair counts match.\n",
	       hs_i, BENCH_PATH_FRAMES, finger_radius, hs_touches);
	printf("(pairs: (finger, cube) pairs in contact summed over the loop; extra / missing: pairs only the peer / only\n"
	       " handspring finds; agree: frames with exactly handspring's pairs; times: CPU us a frame, median (min-max) of\n"
	       " the peer's batches, handspring's in the same pairs, and the peer's time over handspring's per pair)\n");
	printf("%-7s %9s %6s %5s %5s %8s %22s %8s %21s %9s %7s\n", "engine", "radius m", "pairs", "extra", "miss", "agree",
	       "peer us (min-max)", "hs us", "peer/hs (min-max)", "instr", "/hs");
}

void bench_race(const bench_opts *opts, bench_shared *shared) {
	long hs_touches;
	race_job proto = race_proto(&hs_touches);
	double hs_instr = bench_callgrind(opts, "--profile-seed-honest 600", "fr_profiled_frames") / 600.0;
	race_header(proto.radius, hs_instr, hs_touches);
	FILE *csv = bench_csv(opts, "race.csv", "contact generation only on the honest seed scene's frames, CPU time in "
	                                        "interleaved pairs with handspring's honest frame");
	fprintf(csv, "engine,radius_m,pairs,handspring_pairs,extra_pairs,missing_pairs,contacts,frames_agreeing_pct,"
	             "us_per_frame,us_min,us_max,handspring_us,peer_over_handspring,ratio_min,ratio_max,instr_per_frame,"
	             "instr_over_handspring\n");
	double worst = INFINITY, ode_instr = -1.0; // ODE's instructions over handspring's whole frame: the aim's figure
	int peers = 0;
	for (const race_engine *e = engines; e->name; ++e) {
		double ratio, instr_ratio;
		if (!race_one(e, &proto, hs_touches, opts, csv, hs_instr, &ratio, &instr_ratio))
			continue;
		peers++;
		worst = ratio < worst ? ratio : worst;
		if (strcmp(e->key, "ode") == 0)
			ode_instr = instr_ratio;
		shared->checksum ^= (uint64_t)(ratio > 0.0) * 0x9E3779B97F4A7C15ull;
	}
	fclose(csv);
	free(proto.frames);
#ifndef HS_BENCH_ODE
	printf("ODE: not built (libode-dev not installed: sh scripts/deps.sh bench): skipped\n");
#endif
#ifndef HS_BENCH_MUJOCO
	printf("MuJoCo: not built (libmujoco-dev not installed: sh scripts/deps.sh bench): skipped\n");
#endif
	const char *aim = "race: ODE's contacts alone >= 4x the instructions of handspring's whole honest frame";
	if (peers == 0 || ode_instr < 0.0) {
		bench_summary_add("target", aim, peers == 0 ? "peers not built" : "ODE not built or valgrind missing", BENCH_UNKNOWN);
		return;
	}
	char value[160];
	snprintf(value, sizeof value, "ODE %.2fx handspring's instructions; fastest peer %.2fx its CPU time (interleaved)", ode_instr,
	         worst);
	bench_summary_add("target", aim, value, ode_instr >= 4.0 ? BENCH_MET : BENCH_NOT_MET);
}
