// collide_scaling.c — item 6 of `make bench`: what object–object collisions
// cost as a world grows, and what one huge object among small ones costs, in both models.
//
//  - Spring walled box: N spheres (r = 5 cm, 1 kg-ish) on the floor of a frictionless walled box,
//    one per (15 cm)² of its floor, each sliding at up to 1 m/s in a fixed pseudo-random direction: an elastic gas
//    of spheres (restitution 1). µs per frame and per object; a broad phase makes µs per object flat.
//  - Mixed sizes: 4000 cubes of 5 cm falling from 0.5 m on a 10 cm grid, alone and with one
//    400 m × 400 m × 1 m box beside them, in the hand model (skip_work on) and the spring model.
//    Timed over their first frames in the air, every object awake; a fresh world per batch.
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define CS_RADIUS 0.05
#define CS_GAP 0.15
#define CS_CUBES 4000
#define CS_CUBE_GAP 0.10
#define CS_FALL_FRAMES 6 // frames timed per fresh mixed-size world (all still in the air)

static void die(const char *what, hs_status st) {
	fprintf(stderr, "bench: %s: %s\n", what, hs_status_string(st));
	exit(2);
}

static hs_shape_id add_shape(hs_world *w, hs_shape *s, hs_status st) {
	if (!s)
		die("shape", st);
	hs_shape_id id = hs_world_add_shape(w, s, &st);
	hs_shape_destroy(s);
	if (st != HS_OK)
		die("shape", st);
	return id;
}

static void add_object(hs_world *w, hs_shape_id shape, hs_vec3 pos, hs_vec3 vel) {
	hs_object_def od = hs_default_object_def();
	od.shape = shape;
	od.position = pos;
	od.velocity = vel;
	hs_status st;
	hs_world_add_object(w, &od, &st);
	if (st != HS_OK)
		die("object", st);
}

// A fixed pseudo-random number in [-1, 1] (an LCG: the same scene on every machine).
static double next_unit(uint64_t *s) {
	*s = *s * 6364136223846793005ull + 1442695040888963407ull;
	return (double)(*s >> 11) / (double)(1ull << 52) - 1.0;
}

typedef struct cs_scene {
	hs_world *world;
	int objects;
	uint64_t checksum;
} cs_scene;

static int side_of(int n) {
	int side = 1;
	while (side * side < n)
		++side;
	return side;
}

// The walled box of n spheres, one per CS_GAP² of floor at every n (the box's side is √n · CS_GAP,
// the spheres on a lattice of side_of(n) columns across it): the same gas, as dense, whatever n.
// (A box of side_of(n) cells held 10 spheres in 16 cells and 1000 in 1024: the small box's gas was
// thinner and its spheres met a tenth as often.)
static hs_world *spring_box(int n) {
	hs_world_def wd = hs_default_world_def();
	wd.dt = BENCH_DT;
	wd.max_objects = n;
	int side = side_of(n);
	hs_spring_def sd = hs_default_spring_def();
	sd.friction_static = sd.friction_sliding = 0.0;
	sd.walls.enabled = true;
	sd.walls.x_min = sd.walls.y_min = 0.0;
	double room = sqrt((double)n) * CS_GAP, step = room / side;
	sd.walls.x_max = sd.walls.y_max = room;
	wd.kind = HS_WORLD_SPRING;
	wd.spring = sd;
	hs_status st;
	hs_world *w = hs_world_create(&wd, &st);
	if (!w)
		die("world", st);
	hs_shape_id ball = add_shape(w, hs_shape_sphere(CS_RADIUS, &st), st);
	uint64_t seed = 12345;
	for (int k = 0; k < n; ++k) {
		double vx = next_unit(&seed), vy = next_unit(&seed);
		hs_vec3 p = hs_v3((k % side + 0.5) * step, (k / side + 0.5) * step, CS_RADIUS);
		add_object(w, ball, p, hs_v3(vx, vy, 0.0));
	}
	return w;
}

// 4000 falling cubes, with or without the 400 m box, in the hand or the spring model; `pile`:
// all of them in one place (the same centre) instead of on the grid.
static hs_world *mixed_sizes(bool spring, bool big_box, bool pile) {
	hs_world_def wd = hs_default_world_def();
	wd.dt = BENCH_DT;
	wd.max_objects = CS_CUBES + 1;
	wd.kind = spring ? HS_WORLD_SPRING : HS_WORLD_HAND; // the default spring definition
	hs_status st;
	hs_world *w = hs_world_create(&wd, &st);
	if (!w)
		die("world", st);
	hs_shape_id cube = add_shape(w, hs_shape_box(hs_v3(BENCH_CUBE, BENCH_CUBE, BENCH_CUBE), &st), st);
	int side = side_of(CS_CUBES);
	for (int k = 0; k < CS_CUBES; ++k)
		add_object(w, cube, pile ? hs_v3(0, 0, 0.5) : hs_v3((k % side) * CS_CUBE_GAP, (k / side) * CS_CUBE_GAP, 0.5),
		           hs_v3(0, 0, 0));
	if (big_box) { // beside the cubes, resting on the floor
		hs_shape_id slab = add_shape(w, hs_shape_box(hs_v3(400.0, 400.0, 1.0), &st), st);
		add_object(w, slab, hs_v3(-210.0, 0.0, 0.5), hs_v3(0, 0, 0));
	}
	return w;
}

// not inlined: `valgrind --tool=callgrind --toggle-collect=cs_profiled_frames` counts these frames only
__attribute__((noinline)) uint64_t cs_profiled_frames(hs_world *w, long frames, uint64_t h);

static uint64_t step_world(hs_world *w, long frames, uint64_t h) {
	for (long f = 0; f < frames; ++f) {
		hs_world_step(w);
		h ^= hs_world_hash(w);
		h *= 1099511628211ull;
	}
	return h;
}

// s per frame of the walled box over the same stretch of its life at every N: frames 30 to 89 of a
// fresh world. (The gas cools and clusters as it runs — slow impacts do not bounce — so timing a
// small box over more frames, as a fixed batch time did, timed a different, calmer scene.) The
// median over as many fresh worlds as fill batch_s, at least reps and at most CS_BOX_WORLDS.
#define CS_BOX_WARM 30
#define CS_BOX_FRAMES 60
#define CS_BOX_WORLDS 64
static double time_box(int n, const bench_opts *opts, bench_shared *shared) {
	double times[CS_BOX_WORLDS], spent = 0.0;
	int reps = opts->reps < 5 ? 5 : opts->reps, worlds = 0;
	while (worlds < CS_BOX_WORLDS && (worlds < reps || spent < opts->batch_s)) {
		hs_world *w = spring_box(n);
		uint64_t h = step_world(w, CS_BOX_WARM, 14695981039346656037ull);
		double t0 = bench_now();
		h = step_world(w, CS_BOX_FRAMES, h);
		double el = bench_now() - t0;
		hs_world_destroy(w);
		times[worlds++] = el / CS_BOX_FRAMES;
		spent += el;
		shared->checksum ^= h;
	}
	return bench_median(times, worlds);
}

// s per frame over the first CS_FALL_FRAMES frames of a fresh mixed-size world (median of reps).
static double time_mixed(bool spring, bool big_box, int reps, bench_shared *shared) {
	double times[64];
	reps = reps < 1 ? 1 : (reps > 64 ? 64 : reps);
	for (int r = 0; r < reps; ++r) {
		hs_world *w = mixed_sizes(spring, big_box, false);
		double t0 = bench_now();
		shared->checksum ^= step_world(w, CS_FALL_FRAMES, 14695981039346656037ull);
		times[r] = (bench_now() - t0) / CS_FALL_FRAMES;
		hs_world_destroy(w);
	}
	return bench_median(times, reps);
}

static const int box_counts[] = {10, 100, 1000, 10000};
#define N_BOX ((int)(sizeof box_counts / sizeof box_counts[0]))

void bench_collide(const bench_opts *opts, bench_shared *shared) {
	double us[N_BOX];
	printf("\n== 6. Collisions that scale ==\n");
	printf("spring walled box: N spheres r = %.2f m, %.2f m apart, frictionless, elastic, up to 1 m/s; frames %d-%d "
	       "of a fresh world, median of >= %d worlds\n",
	       CS_RADIUS, CS_GAP, CS_BOX_WARM, CS_BOX_WARM + CS_BOX_FRAMES - 1, opts->reps < 5 ? 5 : opts->reps);
	printf("%8s %14s %14s\n", "objects", "us/frame", "us/object");
	for (int c = 0; c < N_BOX; ++c) {
		bench_progress("[collide] walled box, %d spheres\n", box_counts[c]);
		us[c] = 1e6 * time_box(box_counts[c], opts, shared);
		printf("%8d %14.2f %14.4f\n", box_counts[c], us[c], us[c] / box_counts[c]);
	}
	char value[128];
	double ratio = (us[2] / box_counts[2]) / (us[0] / box_counts[0]);
	snprintf(value, sizeof value, "%.2fx (%.3f -> %.3f us/object)", ratio, us[0] / box_counts[0], us[2] / box_counts[2]);
	bench_summary_add("target", "spring box: us/object at 1000 within 2x of at 10", value,
	                  ratio <= 2.0 ? BENCH_MET : BENCH_NOT_MET);

	int reps = opts->quick ? 3 : 5;
	printf("\nmixed sizes: %d cubes of %.2f m falling on a %.2f m grid, alone and with one 400 m box beside them;\n"
	       "us per frame over the first %d frames of a fresh world, median of %d worlds\n",
	       CS_CUBES, BENCH_CUBE, CS_CUBE_GAP, CS_FALL_FRAMES, reps);
	printf("%-8s %16s %16s %10s\n", "model", "cubes alone", "+ 400 m box", "ratio");
	for (int m = 0; m < 2; ++m) {
		bool spring = m == 1;
		bench_progress("[collide] mixed sizes, %s model\n", spring ? "spring" : "hand");
		double alone = 1e6 * time_mixed(spring, false, reps, shared);
		double with = 1e6 * time_mixed(spring, true, reps, shared);
		printf("%-8s %16.1f %16.1f %9.2fx\n", spring ? "spring" : "hand", alone, with, with / alone);
		snprintf(value, sizeof value, "%.2fx (%.0f -> %.0f us/frame)", with / alone, alone, with);
		bench_summary_add("target", spring ? "spring: 400 m box among 4000 cubes within 2x"
		                                   : "hand: 400 m box among 4000 cubes within 2x",
		                  value, with / alone <= 2.0 ? BENCH_MET : BENCH_NOT_MET);
	}
}

// `hs_bench --profile-collide KIND,FRAMES[,N]`: for callgrind. KIND box (walled box of N spheres,
// after 30 frames of warm-up), hand, hand+box, spring, spring+box (the mixed-size worlds),
// hand-pile (the 4000 cubes of `hand` all in one place).
void bench_profile_collide(const char *spec) {
	char kind[16];
	const char *first, *second;
	bench_split_spec(spec, kind, sizeof kind, &first, &second);
	long frames = first ? atol(first) : 1;
	int n = second ? atoi(second) : 100;
	hs_world *w;
	if (strcmp(kind, "box") == 0) {
		w = spring_box(n);
		step_world(w, CS_BOX_WARM, 0);
	} else {
		bool spring = strncmp(kind, "spring", 6) == 0;
		w = mixed_sizes(spring, strchr(kind, '+') != NULL, strstr(kind, "pile") != NULL);
	}
	double t0 = bench_now();
	uint64_t h = cs_profiled_frames(w, frames, 14695981039346656037ull);
	double el = bench_now() - t0;
	printf("%s: %ld frames in %.3f s = %.1f us/frame, checksum %016llx\n", kind, frames, el, 1e6 * el / (double)frames,
	       (unsigned long long)h);
	hs_world_destroy(w);
}

uint64_t cs_profiled_frames(hs_world *w, long frames, uint64_t h) { return step_world(w, frames, h); }
