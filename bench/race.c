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
// floor or each other (handspring's resting cubes are asleep). handspring's figure is its whole
// honest frame — glove kinematics, the full check, the grasp, the carrying, the state hash — which
// is more than contact generation. The jobs are shown to match by their contacts: per frame, the
// (finger, cube) pairs in contact in each engine, against handspring's.
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

static bool ode_run(race_job proto, const bench_opts *opts, race_job *out, bench_stats *st) {
	dInitODE2(0);
	ode_race *r = calloc(1, sizeof *r);
	if (!r)
		return false;
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
	ode_frame(r, BENCH_PATH_FRAMES); // one loop counted: the contacts compared
	*out = r->job;
	r->job.k = 0;
	*st = bench_measure(ode_frame, r, opts);
	dSpaceDestroy(r->hand);
	dSpaceDestroy(r->cubes);
	free(r);
	dCloseODE();
	return true;
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

static bool mj_run(race_job proto, const bench_opts *opts, race_job *out, bench_stats *st) {
	size_t size = 16384, len = 0;
	char *xml = malloc(size);
	if (!xml)
		return false;
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
		return false;
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
		return false;
	}
	r->d = mj_makeData(r->m);
	r->job = proto;
	r->cube_geom0 = mj_name2id(r->m, mjOBJ_BODY, "cube0") >= 0 ? r->m->body_geomadr[mj_name2id(r->m, mjOBJ_BODY, "cube0")] : 0;
	r->capsule_geom0 = r->m->body_geomadr[mj_name2id(r->m, mjOBJ_BODY, "seg0")];
	for (int i = 0; i < 10; ++i)
		mj_place(r->d, i, proto.frames[0].pos[i], proto.frames[0].rot[i]);
	mj_frame(r, BENCH_PATH_FRAMES);
	*out = r->job;
	r->job.k = 0;
	*st = bench_measure(mj_frame, r, opts);
	mj_deleteData(r->d);
	mj_deleteModel(r->m);
	free(r);
	return true;
}
#endif

static void row(const char *name, const bench_stats *st, double hs_us, const race_job *job, long hs_touches) {
	double us = 1e6 * st->median;
	if (!job) {
		printf("%-11s %9.3f (%.3f-%.3f) %10.2fx   %8ld %8s %7s %7s %7s\n", name, us, 1e6 * st->min, 1e6 * st->max, 1.0,
		       hs_touches, "-", "-", "-", "-");
		return;
	}
	printf("%-11s %9.3f (%.3f-%.3f) %10.2fx   %8ld %8ld %6.1f%% %7ld %7ld\n", name, us, 1e6 * st->min, 1e6 * st->max,
	       us / hs_us, job->touches, job->contacts, 100.0 * (double)job->agree / (double)job->frames_run, job->extra,
	       job->missing);
}

void bench_race(const bench_opts *opts, bench_shared *shared) {
	race_job proto;
	memset(&proto, 0, sizeof proto);
	proto.frames = malloc(BENCH_PATH_FRAMES * sizeof *proto.frames);
	if (!proto.frames) {
		fprintf(stderr, "bench: race: out of memory\n");
		exit(2);
	}
	bench_race_record(proto.frames, &proto.radius);
	long hs_touches = 0;
	for (int f = 0; f < BENCH_PATH_FRAMES; ++f)
		hs_touches += __builtin_popcountll(proto.frames[f].touch);
	bench_stats hs = bench_honest_measure(opts);
	double hs_us = 1e6 * hs.median;
	bench_progress("[race] handspring honest frame: %.3f us\n", hs_us);

	printf("\n== Race: contact generation only, on the honest seed scene's frames ==\n");
	printf("one loop of %d frames: the hand as 15 capsules (r = %.4g m) through the 10 cubes, 2 carried; the 8 resting\n"
	       "cubes asleep on every side; handspring's figure is its whole honest frame\n",
	       BENCH_PATH_FRAMES, proto.radius);
	printf("%-11s %27s %11s   %8s %8s %7s %7s %7s\n", "engine", "us/frame median (min-max)", "/handspring",
	       "touches", "contacts", "agree", "extra", "missing");
	printf("(touches: (finger, cube) pairs in contact, summed over the loop; agree: frames with exactly handspring's "
	       "pairs;\n extra / missing: pairs only the engine finds / only handspring finds)\n");
	row("handspring", &hs, hs_us, NULL, hs_touches);
	FILE *csv = bench_csv(opts, "race.csv", "contact generation only on the honest seed scene's frames");
	fprintf(csv, "engine,us_per_frame,us_min,us_max,peer_over_handspring,finger_cube_touches,contacts,frames_agreeing_pct,"
	             "extra_pairs,missing_pairs\n");
	fprintf(csv, "handspring,%.4f,%.4f,%.4f,1,%ld,,100,0,0\n", hs_us, 1e6 * hs.min, 1e6 * hs.max, hs_touches);
	double worst = INFINITY;
	int peers = 0;
	char value[160];
	struct {
		const char *name;
		bool (*run)(race_job, const bench_opts *, race_job *, bench_stats *);
	} engines[] = {
#ifdef HS_BENCH_ODE
	    {"ODE", ode_run},
#endif
#ifdef HS_BENCH_MUJOCO
	    {"MuJoCo", mj_run},
#endif
	    {NULL, NULL},
	};
	for (int e = 0; engines[e].name; ++e) {
		race_job job;
		bench_stats st;
		if (!engines[e].run(proto, opts, &job, &st))
			continue;
		peers++;
		row(engines[e].name, &st, hs_us, &job, hs_touches);
		double ratio = 1e6 * st.median / hs_us, agree = 100.0 * (double)job.agree / (double)job.frames_run;
		fprintf(csv, "%s,%.4f,%.4f,%.4f,%.3f,%ld,%ld,%.1f,%ld,%ld\n", engines[e].name, 1e6 * st.median, 1e6 * st.min,
		        1e6 * st.max, ratio, job.touches, job.contacts, agree, job.extra, job.missing);
		shared->checksum ^= (uint64_t)job.touches * 0x9E3779B97F4A7C15ull + (uint64_t)job.contacts;
		snprintf(value, sizeof value, "%.2f us/frame = %.2fx handspring's; pairs %ld vs %ld (%ld extra, %ld missing)",
		         1e6 * st.median, ratio, job.touches, hs_touches, job.extra, job.missing);
		bench_summary_add("race", engines[e].name, value, BENCH_INFO);
		worst = ratio < worst ? ratio : worst;
	}
	fclose(csv);
	free(proto.frames);
	if (peers == 0) {
		bench_summary_add("target", "race: >= 10x faster than ODE and MuJoCo (contacts only)", "peers not built",
		                  BENCH_UNKNOWN);
		return;
	}
	snprintf(value, sizeof value, "fastest peer %.2fx handspring's honest frame (%.2f us)", worst, hs_us);
	bench_summary_add("target", "race: >= 10x faster than ODE and MuJoCo (contacts only)", value,
	                  peers == 2 && worst >= 10.0 ? BENCH_MET : BENCH_NOT_MET);
}
