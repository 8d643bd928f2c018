// hand_scaling.c — section `scaling` of `make bench`: what the honest frame costs as one thing grows.
//
// The honest frame (bench/frame_rate.c): the seed scene — ten 5 cm cubes in a row, two grasped —
// with a new glove reading every frame (±4 units of seeded noise on all 18 sensors), the wrist
// moving along the loop and turning, the state hash every frame. Each row changes one thing:
//  - faces: the ten objects are the cube (6 faces), the paper's ellipsoid (32), or the same 5 cm
//    ball with 128 or 512 faces (UV polyhedra, bench_uv_ball); each shape's grasp pose is searched;
//  - grasped objects 0, 1, 2, 5, 10: five hands over the row, one per pair of cubes, each on its own
//    copy of the loop with its own noise; a hand holds its pair, one cube of it, or hovers 0.3 m
//    above it, so the hands' count stays 5 while the grasped count changes;
//  - hands 1, 2, 4: that many hands, each holding its own pair of the row (2 grasped per hand);
//  - untouched objects 10 → 10,000: resting cubes added on a grid behind the seed row, starting
//    HSC_FAR_ROWS rows back, out of the hand's reach (objects near the fingers are tested, and are
//    the faces and grasped rows' business).
// Each point is timed with its batches interleaved with the honest frame's own (bench_measure_pair),
// so a busy machine slows both alike; the ratio to the honest frame is the stable figure. The
// instruction counts (callgrind) come from `hs_bench --profile-scaling ROW,VALUE,FRAMES`.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

// Rows left empty behind the seed row before the untouched objects: 0.6 m, beyond the hand's loop
// (with rows 1 and 2 filled, the hand's bounding volume reaches them and they are tested: callgrind
// counts 74,000 instructions a frame without the hash at 10 objects, 138,000 from 110 on, flat after).
#define HSC_FAR_ROWS 9
#define HSC_MAX_HANDS 5
#define HSC_HOVER 0.3 // m: a hand that holds nothing runs its loop this far above its pair

static void die(const char *what, hs_status st) {
	fprintf(stderr, "bench: %s: %s\n", what, hs_status_string(st));
	exit(2);
}

// ---------------------------------------------------------------------------------------------
// Several hands over the seed row

typedef enum hsc_job { HSC_JOB_HOVER = 0, HSC_JOB_ONE = 1, HSC_JOB_PAIR = 2 } hsc_job;

typedef struct hsc_hand {
	hs_hand_id id;
	int held;                   // cubes it holds (its job)
	hs_object_id targets[2];
	hs_vec3 wrist[BENCH_PATH_FRAMES];
	uint8_t noisy[BENCH_PATH_FRAMES][HS_GLOVE_SENSORS];
	hs_quat turns[BENCH_PATH_FRAMES];
} hsc_hand;

typedef struct hsc_scene {
	hs_world *world;
	int hands;
	hsc_hand hand[HSC_MAX_HANDS];
	int k;
	long frames, lost;
	uint64_t checksum;
} hsc_scene;

// Hand h works over the pair of cells (2s, 2s + 1) of the row, s = slot[h]: hand 0 over the seed
// scene's pair (cells 4 and 5), the others outward from it.
static const int slot[HSC_MAX_HANDS] = {2, 0, 4, 1, 3};

// Sets up hand h's loop for its job; the single cube is the pair's second (cell 2s + 1), as the
// frame-rate sweep's one touched cube is cell 5.
static void plan_hand(hsc_scene *sc, int h, hsc_job job, const hs_object_id cubes[BENCH_PER_ROW]) {
	hsc_hand *hd = &sc->hand[h];
	int s = slot[h], touched = job == HSC_JOB_ONE ? 1 : 2;
	hs_vec3 a = bench_cell(2 * s, 0), b = bench_cell(2 * s + 1, 0);
	hs_vec3 centroid = touched == 1 ? b : hs_scale(hs_add(a, b), 0.5);
	hs_vec3 base;
	uint8_t held[HS_GLOVE_SENSORS];
	if (!bench_honest_hand(touched, centroid, &base, held))
		die("no grasp pose for the cubes", HS_ERR_INVALID_ARGUMENT);
	if (job == HSC_JOB_HOVER)
		base = hs_add(base, hs_v3(0.0, 0.0, HSC_HOVER));
	hd->held = job == HSC_JOB_HOVER ? 0 : touched;
	hd->targets[0] = cubes[touched == 1 ? 2 * s + 1 : 2 * s];
	hd->targets[1] = cubes[2 * s + 1];
	for (int k = 0; k < BENCH_PATH_FRAMES; ++k)
		hd->wrist[k] = hs_add(base, bench_path(k));
	// its own glove noise (hand 0 draws the honest frame's); every wrist turns alike
	uint64_t seed = BENCH_HONEST_SEED;
	for (int i = 0; i < h; ++i)
		seed += 0x632BE59BD9B4E019ull;
	bench_honest_readings(held, seed, hd->noisy, hd->turns);
}

// Ten cubes on the seed row, `hands` hands with jobs[h]; the holding hands come down open and close
// on their cubes as the honest frame's hand does (fingers that start inside touch nothing).
static hsc_scene *multi_create(int hands, const hsc_job *jobs) {
	hsc_scene *sc = calloc(1, sizeof *sc);
	if (!sc)
		die("scene", HS_ERR_NO_MEMORY);
	hs_world_def wd = hs_default_world_def();
	bench_grasp_start(&wd);
	wd.dt = BENCH_DT;
	wd.max_objects = BENCH_PER_ROW;
	wd.max_hands = hands;
	hs_status st;
	if (!(sc->world = hs_world_create(&wd, &st)))
		die("world", st);
	hs_shape *cube = hs_shape_box(hs_v3(BENCH_CUBE, BENCH_CUBE, BENCH_CUBE), &st);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(sc->world, cube, &st);
	hs_shape_destroy(cube);
	if (st != HS_OK)
		die("shape", st);
	hs_object_id cubes[BENCH_PER_ROW];
	for (int i = 0; i < BENCH_PER_ROW; ++i) {
		od.position = bench_cell(i, 0);
		cubes[i] = hs_world_add_object(sc->world, &od, &st);
		if (st != HS_OK)
			die("object", st);
	}
	hs_hand_def hdef = hs_default_hand_def();
	uint8_t wide[HS_GLOVE_SENSORS];
	if (hs_hand_posture(&hdef, HS_POSTURE_GRASP, 0.12, wide) != HS_OK)
		die("posture", HS_ERR_INVALID_ARGUMENT);
	sc->hands = hands;
	for (int h = 0; h < hands; ++h) {
		if (!(sc->hand[h].id = hs_world_add_hand(sc->world, &hdef, &st)).index1)
			die("hand", st);
		plan_hand(sc, h, jobs[h], cubes);
	}
	for (int k = 4; k >= -1; --k) { // down 5 cm in 5 frames, open; then the first reading
		for (int h = 0; h < hands; ++h) {
			const hsc_hand *hd = &sc->hand[h];
			hs_vec3 at = k >= 0 ? hs_add(hd->wrist[0], hs_v3(0, 0, 0.01 * k)) : hd->wrist[0];
			hs_world_set_hand(sc->world, hd->id, at, k >= 0 ? hs_quat_identity() : hd->turns[0],
			                  k >= 0 ? wide : hd->noisy[0]);
		}
		hs_world_step(sc->world);
	}
	(void)hs_world_hash(sc->world); // a user who hashes every frame has hashed the set-up too: every object digested once
	sc->checksum = 14695981039346656037ull;
	return sc;
}

// One honest frame of every hand: new noisy readings and turned wrists, the step, the hash, the
// grasps verified.
static void multi_step(void *state, long frames) {
	hsc_scene *sc = state;
	for (long f = 0; f < frames; ++f) {
		for (int h = 0; h < sc->hands; ++h) {
			const hsc_hand *hd = &sc->hand[h];
			hs_world_set_hand(sc->world, hd->id, hd->wrist[sc->k], hd->turns[sc->k], hd->noisy[sc->k]);
		}
		hs_world_step(sc->world);
		sc->checksum ^= hs_world_hash(sc->world);
		sc->k = sc->k + 1 == BENCH_PATH_FRAMES ? 0 : sc->k + 1;
		bool held = true;
		for (int h = 0; h < sc->hands; ++h)
			for (int t = 0; t < sc->hand[h].held; ++t) {
				hs_object_state os;
				hs_world_object_state(sc->world, sc->hand[h].targets[t], &os);
				held = held && os.contact == HS_CONTACT_GRASP;
				sc->checksum = bench_mix(sc->checksum, os.position.z);
			}
		sc->lost += !held;
		sc->frames++;
	}
}

// Cubes no hand holds that are touched or awake now.
static int multi_stray(const hsc_scene *sc) {
	int stray = 0;
	for (int i = 0; i < BENCH_PER_ROW; ++i) {
		hs_object_id id = hs_world_object_at(sc->world, i);
		bool target = false;
		for (int h = 0; h < sc->hands; ++h)
			for (int t = 0; t < sc->hand[h].held; ++t)
				target = target || sc->hand[h].targets[t].index1 == id.index1;
		hs_object_state os;
		hs_world_object_state(sc->world, id, &os);
		stray += !target && (os.contact != HS_CONTACT_NONE || !os.resting);
	}
	return stray;
}

static void multi_destroy(hsc_scene *sc) {
	if (sc)
		hs_world_destroy(sc->world);
	free(sc);
}

// The jobs of `hands` hands holding `grasped` cubes: pairs first, then one single, the rest hover.
static void jobs_for(int hands, int grasped, hsc_job jobs[HSC_MAX_HANDS]) {
	for (int h = 0; h < hands; ++h) {
		int left = grasped - 2 * h;
		jobs[h] = left >= 2 ? HSC_JOB_PAIR : left == 1 ? HSC_JOB_ONE : HSC_JOB_HOVER;
	}
}

// ---------------------------------------------------------------------------------------------
// The rows

typedef enum hsc_row { HSC_FACES = 0, HSC_GRASPED, HSC_HANDS, HSC_UNTOUCHED, HSC_BARE, HSC_ROWS } hsc_row;
static const char *const row_names[HSC_ROWS] = {"faces", "grasped", "hands", "untouched", "untouched-nohash"};
#define HSC_MAX_POINTS 5
static const int row_values[HSC_ROWS][HSC_MAX_POINTS] = {
    {6, 32, 128, 512, 0}, {0, 1, 2, 5, 10}, {1, 2, 4, 0, 0}, {10, 100, 1000, 10000, 0}, {10, 10000, 0, 0, 0}};
static const int row_points[HSC_ROWS] = {4, 5, 3, 4, 2};

// One point of a row: either the honest frame's own scene (frame_rate.c) or the several-hand one.
typedef struct hsc_case {
	bench_scene *scene;
	hsc_scene *multi;
} hsc_case;

static bench_shape shape_of_faces(int faces) {
	return faces == 6 ? BENCH_SHAPE_CUBE
	       : faces == 32 ? BENCH_SHAPE_ELLIPSOID
	       : faces == 128 ? BENCH_SHAPE_POLY128
	                      : BENCH_SHAPE_POLY512;
}

// NULL scene and multi: no grasp pose for that shape (reported, not measured).
static hsc_case case_create(hsc_row row, int value) {
	hsc_case c = {NULL, NULL};
	hsc_job jobs[HSC_MAX_HANDS];
	switch (row) {
	case HSC_FACES:
		c.scene = bench_honest_scene(shape_of_faces(value), BENCH_PER_ROW, 0);
		break;
	case HSC_GRASPED:
		jobs_for(HSC_MAX_HANDS, value, jobs);
		c.multi = multi_create(HSC_MAX_HANDS, jobs);
		break;
	case HSC_HANDS:
		jobs_for(value, 2 * value, jobs);
		c.multi = multi_create(value, jobs);
		break;
	case HSC_UNTOUCHED:
	case HSC_BARE:
		c.scene = bench_honest_scene(BENCH_SHAPE_CUBE, value, HSC_FAR_ROWS);
		if (row == HSC_BARE && c.scene)
			bench_scene_hash(c.scene, false);
		break;
	default:
		break;
	}
	return c;
}

static bench_step_fn case_step(const hsc_case *c) { return c->scene ? bench_scene_step : multi_step; }
static void *case_state(const hsc_case *c) { return c->scene ? (void *)c->scene : (void *)c->multi; }

static void case_report(const hsc_case *c, long *lost, int *stray, uint64_t *checksum) {
	if (c->scene) {
		bench_scene_report(c->scene, lost, stray, checksum);
		return;
	}
	*lost = c->multi->lost;
	*stray = multi_stray(c->multi);
	*checksum = c->multi->checksum ^ hs_world_hash(c->multi->world);
}

static void case_destroy(hsc_case *c) {
	bench_scene_destroy(c->scene);
	multi_destroy(c->multi);
}

typedef struct hsc_point {
	bool valid;
	bench_stats st, ref; // s per frame: this point, the honest frame interleaved with it
	double ratio;        // median over the repeats of this point's time over the honest frame's
	long lost;
	int stray;
} hsc_point;

static hsc_point measure_point(hsc_row row, int value, const bench_opts *opts, bench_shared *shared) {
	hsc_point p;
	memset(&p, 0, sizeof p);
	hsc_case c = case_create(row, value), ref = case_create(HSC_FACES, 6);
	if (!c.scene && !c.multi) {
		bench_progress("[scaling] %s %d: no grasp pose found, not measured\n", row_names[row], value);
		case_destroy(&ref);
		return p;
	}
	p.ratio = bench_measure_pair(case_step(&c), case_state(&c), case_step(&ref), case_state(&ref), opts, &p.st, &p.ref);
	uint64_t sum;
	case_report(&c, &p.lost, &p.stray, &sum);
	shared->checksum ^= sum;
	long ref_lost;
	int ref_stray;
	case_report(&ref, &ref_lost, &ref_stray, &sum);
	shared->checksum ^= sum;
	if (p.lost || p.stray)
		bench_progress("[scaling] WARNING: %s %d: grasp lost in %ld frames, %d untouched objects touched or awake\n",
		               row_names[row], value, p.lost, p.stray);
	bench_progress("[scaling] %-16s %6d: %8.2f us/frame, honest frame %6.2f us beside it\n", row_names[row], value,
	               1e6 * p.st.median, 1e6 * p.ref.median);
	case_destroy(&c);
	case_destroy(&ref);
	p.valid = true;
	return p;
}

static const char *const row_titles[HSC_ROWS] = {
    "faces: the ten objects' shape (cube; the paper's ellipsoid; the same 5 cm ball with 128 and 512 faces)",
    "grasped objects: five hands over the row, each holding its pair, one cube of it, or hovering 0.3 m above it",
    "hands: that many hands, each holding its own pair of the row (2 grasped per hand)",
    "untouched objects: resting cubes added on a grid from 0.6 m behind the seed row (objects in all)",
    "the same without the per-frame state hash (the step alone)"};

static void print_row(hsc_row row, const hsc_point *pts) {
	printf("\n%s\n", row_titles[row]);
	printf("%8s %24s %12s %10s %8s %6s\n", "value", "us/frame (min-max)", "honest us", "ratio", "lost", "stray");
	for (int i = 0; i < row_points[row]; ++i) {
		const hsc_point *p = &pts[i];
		if (!p->valid) {
			printf("%8d %24s\n", row_values[row][i], "no grasp pose found");
			continue;
		}
		char us[64];
		snprintf(us, sizeof us, "%.2f (%.2f-%.2f)", 1e6 * p->st.median, 1e6 * p->st.min, 1e6 * p->st.max);
		printf("%8d %24s %12.2f %9.2fx %8ld %6d\n", row_values[row][i], us, 1e6 * p->ref.median, p->ratio, p->lost,
		       p->stray);
	}
}

// "a / b / c us" of a row's points (µs per frame, "-" where not measured).
static void row_value(hsc_row row, const hsc_point *pts, char *out, size_t size) {
	size_t n = 0;
	out[0] = '\0';
	for (int i = 0; i < row_points[row] && n < size; ++i) {
		if (pts[i].valid)
			n += (size_t)snprintf(out + n, size - n, "%s%.1f", i ? " / " : "", 1e6 * pts[i].st.median);
		else
			n += (size_t)snprintf(out + n, size - n, "%s-", i ? " / " : "");
	}
	if (n < size)
		snprintf(out + n, size - n, " us");
}

// Frame time at the row's last point over its first, each against the honest frame timed beside it
// (the load of the machine cancels).
static double row_ratio(const hsc_point *pts, int last) {
	const hsc_point *a = &pts[0], *b = &pts[last];
	if (!a->valid || !b->valid)
		return 0.0;
	return b->ratio / a->ratio;
}

static void summarise(hsc_point pts[HSC_ROWS][HSC_MAX_POINTS]) {
	char value[96];
	static const char *const what[HSC_UNTOUCHED + 1] = {
	    "honest frame against faces 6 / 32 / 128 / 512",
	    "against grasped 0 / 1 / 2 / 5 / 10 (5 hands)",
	    "against hands 1 / 2 / 4 (2 grasped each)",
	    "against untouched 10 / 100 / 1000 / 10000 objects"};
	for (int r = HSC_FACES; r <= HSC_UNTOUCHED; ++r) {
		row_value((hsc_row)r, pts[r], value, sizeof value);
		bench_summary_add("scaling", what[r], value, BENCH_INFO);
	}
	const hsc_point *u = pts[HSC_UNTOUCHED], *bare = pts[HSC_BARE];
	double step_ratio = row_ratio(bare, 1), ratio = row_ratio(u, 3);
	if (step_ratio > 0.0) {
		snprintf(value, sizeof value, "%.2fx (%.2f -> %.2f us)", step_ratio, 1e6 * bare[0].st.median,
		         1e6 * bare[1].st.median);
		bench_summary_add("scaling", "untouched 10 -> 10000, the step alone (no state hash)", value, BENCH_INFO);
	}
	if (ratio > 0.0) {
		snprintf(value, sizeof value, "%.2fx (%.2f -> %.2f us)", ratio,
		         1e6 * u[0].st.median, 1e6 * u[3].st.median);
		bench_summary_add("target", "honest frame: untouched 10 -> 10,000 within 1.1x", value,
		                  ratio <= 1.1 ? BENCH_MET : BENCH_NOT_MET);
	} else
		bench_summary_add("target", "honest frame: untouched 10 -> 10,000 within 1.1x", "not measured", BENCH_UNKNOWN);
}

void bench_hand_scaling(const bench_opts *opts, bench_shared *shared) {
	static hsc_point pts[HSC_ROWS][HSC_MAX_POINTS];
	memset(pts, 0, sizeof pts);
	for (int r = 0; r < HSC_ROWS; ++r)
		for (int i = 0; i < row_points[r]; ++i)
			pts[r][i] = measure_point((hsc_row)r, row_values[r][i], opts, shared);

	printf("\n== Scaling of the honest frame: us per frame, median (min-max) of %d batches, ==\n",
	       opts->reps < 5 ? 5 : opts->reps);
	printf("each interleaved with the honest frame's own batches (its us beside it; ratio: the median of this / it\n"
	       "batch by batch). Lost: frames with a grasp lost; stray: untouched objects touched or awake after the\n"
	       "timing. Instructions per frame:\n"
	       "valgrind --tool=callgrind --toggle-collect=hsc_profiled_frames hs_bench --profile-scaling ROW,VALUE,600\n");
	for (int r = 0; r < HSC_ROWS; ++r)
		print_row((hsc_row)r, pts[r]);

	FILE *csv = bench_csv(opts, "hand_scaling.csv",
	                      "us per frame of the honest frame against one varied thing, and of the "
	                      "honest frame interleaved with it");
	fprintf(csv, "row,value,us,us_min,us_max,honest_us,ratio,lost,stray\n");
	for (int r = 0; r < HSC_ROWS; ++r)
		for (int i = 0; i < row_points[r]; ++i) {
			const hsc_point *p = &pts[r][i];
			if (p->valid)
				fprintf(csv, "%s,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%ld,%d\n", row_names[r], row_values[r][i],
				        1e6 * p->st.median, 1e6 * p->st.min, 1e6 * p->st.max, 1e6 * p->ref.median, p->ratio,
				        p->lost, p->stray);
		}
	fclose(csv);
	summarise(pts);
}

// not inlined: `valgrind --tool=callgrind --toggle-collect=hsc_profiled_frames` counts these frames only
__attribute__((noinline)) void hsc_profiled_frames(const hsc_case *c, long frames);
void hsc_profiled_frames(const hsc_case *c, long frames) { case_step(c)(case_state(c), frames); }

void bench_profile_scaling(const char *spec) {
	char name[32];
	const char *first, *second;
	bench_split_spec(spec, name, sizeof name, &first, &second);
	int value = first ? atoi(first) : 0;
	long frames = second ? atol(second) : 600;
	int row = 0;
	while (row < HSC_ROWS && strcmp(name, row_names[row]) != 0)
		++row;
	if (row == HSC_ROWS) {
		fprintf(stderr, "bench: --profile-scaling ROW,VALUE,FRAMES with ROW one of faces, grasped, hands, untouched, "
		                "untouched-nohash\n");
		exit(2);
	}
	bool known = false;
	for (int i = 0; i < row_points[row]; ++i)
		known = known || row_values[row][i] == value;
	if (!known || (row == HSC_HANDS && value > HSC_MAX_HANDS)) {
		fprintf(stderr, "bench: --profile-scaling %s: value %d is not one of the row's\n", name, value);
		exit(2);
	}
	hsc_case c = case_create((hsc_row)row, value);
	if (!c.scene && !c.multi)
		die("no grasp pose for that shape", HS_ERR_INVALID_ARGUMENT);
	double t0 = bench_now();
	hsc_profiled_frames(&c, frames);
	double el = bench_now() - t0;
	long lost;
	int stray;
	uint64_t sum;
	case_report(&c, &lost, &stray, &sum);
	printf("%s %d: %ld frames in %.3f s = %.3f us/frame, grasp lost in %ld, %d stray, checksum %016llx\n", name, value,
	       frames, el, 1e6 * el / (double)frames, lost, stray, (unsigned long long)sum);
	case_destroy(&c);
}
