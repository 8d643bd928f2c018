// fig13.c — section `fig13` of `make bench`: the 1999 paper's Experiment 3 (Fig. 13) at its own
// point, 10 cubes, with 0, 1, 2 and 4 of them grasped, timed two ways:
//  - the check alone: the frame-rate sweep's scene (bench/frame_rate.c), the hand's full check and
//    the world step, the grasp counted every frame;
//  - the check plus drawing the scene every frame with the software rasteriser of bench/raster.h
//    (640 x 480, flat-shaded, z-buffered), closer to the paper's frames, which were drawn on screen.
// Four grasped are held by two hands (one per pair; one hand grasps no 2 x 2 block), so that row
// also has a second hand's check. Each row's two scenes are timed in interleaved batches on the
// process's CPU clock (bench_measure_pair_cpu). With valgrind, callgrind counts each row's
// instructions per frame and splits the check into stages, to say what grows with grasped objects.
// `hs_bench --fig13-check` verifies that every cube row of the sweep holds what it claims.
#include <stdlib.h>
#include <string.h>

#include "bench.h"

static const int fig13_touched[] = {0, 1, 2, 4};
#define F13_ROWS 4
#define F13_OBJECTS 10
#define F13_CG_FRAMES 600      // frames callgrind counts of the check alone
#define F13_CG_DRAW_FRAMES 30  // and of the check plus drawing (each drawn frame is ~100x the check)
#define F13_PAPER_FPS 17.0     // Experiment 3: 10 objects, 2 grasped, drawn on screen

// The stages of the check (callgrind's inclusive counts of these functions, the measured frames only).
enum { ST_SET_HAND, ST_DETECT, ST_MANIPULATE, ST_STEP, ST_LOOP, ST_COUNT };
static const char *const stage_names[ST_COUNT] = {
    "hand set from its reading (hs_world_set_hand)", "contact detection (hs_contact_detect)",
    "rest of hands on objects: grasp rule, carrying (hs_manipulate)",
    "rest of the world step: broad phase, free objects, hands' history",
    "the bench's loop: state queries, grasp count"};

typedef struct f13_row {
	bool valid;
	int touched, grasped_check, grasped_draw, stray;
	long lost;
	bench_pair pair;       // a: check alone, b: check + draw (s per frame, CPU time)
	double instr, instr_draw; // per frame (−1: not counted)
	double stage[ST_COUNT];   // instructions per frame
	double tests, contacts;   // per frame over a loop: objects tested against a hand, contacts found
	double instr_alone;       // per frame: the check with the touched cubes alone (−1: not counted)
} f13_row;

static void held(bench_scene *sc, int *grasped, f13_row *row) {
	long lost, frames;
	int stray;
	bench_fig13_held(sc, grasped, &lost, &frames, &stray);
	row->lost += lost;
	row->stray += stray;
}

static void time_row(f13_row *row, const bench_opts *opts, bench_shared *shared) {
	bench_scene *check = bench_fig13_scene(F13_OBJECTS, row->touched, false);
	bench_scene *draw = bench_fig13_scene(F13_OBJECTS, row->touched, true);
	if (!check || !draw) {
		bench_scene_destroy(check);
		bench_scene_destroy(draw);
		return;
	}
	row->valid = true;
	row->pair = bench_measure_pair_cpu(bench_scene_step, check, bench_scene_step, draw, opts);
	held(check, &row->grasped_check, row);
	held(draw, &row->grasped_draw, row);
	char path[600];
	snprintf(path, sizeof path, "%s/fig13_frame_%d.ppm", opts->out_dir, row->touched);
	if (!bench_fig13_picture(draw, path))
		bench_progress("[fig13] cannot write %s\n", path);
	bench_fig13_work(check, BENCH_PATH_FRAMES, &row->tests, &row->contacts); // after the timing: not timed
	held(check, &row->grasped_check, row);
	long lost;
	int stray;
	uint64_t sum_a, sum_b;
	bench_scene_report(check, &lost, &stray, &sum_a);
	bench_scene_report(draw, &lost, &stray, &sum_b);
	shared->checksum ^= sum_a ^ sum_b;
	bench_scene_destroy(check);
	bench_scene_destroy(draw);
	bench_progress("[fig13] %d grasped: %.0f frames/s check alone, %.0f check + draw; fewest grasped %d / %d of %d\n",
	               row->touched, 1.0 / row->pair.a.median, 1.0 / row->pair.b.median, row->grasped_check,
	               row->grasped_draw, row->touched);
}

static void count_row(f13_row *row, const bench_opts *opts) {
	char args[64];
	snprintf(args, sizeof args, "--profile-fig13 %d,%d", row->touched, F13_CG_FRAMES);
	double total = bench_callgrind(opts, args, "fr_profiled_frames");
	row->instr = total > 0.0 ? total / F13_CG_FRAMES : -1.0;
	if (total > 0.0) {
		double set = bench_callgrind_fn(opts, args, "hs_world_set_hand");
		double step = bench_callgrind_fn(opts, args, "hs_world_step");
		double manip = bench_callgrind_fn(opts, args, "hs_manipulate");
		double detect = bench_callgrind_fn(opts, args, "hs_contact_detect");
		set = set > 0.0 ? set : 0.0;
		step = step > 0.0 ? step : 0.0;
		manip = manip > 0.0 ? manip : 0.0;
		detect = detect > 0.0 && detect <= manip ? detect : 0.0;
		row->stage[ST_SET_HAND] = set / F13_CG_FRAMES;
		row->stage[ST_DETECT] = detect / F13_CG_FRAMES;
		row->stage[ST_MANIPULATE] = (manip - detect) / F13_CG_FRAMES;
		row->stage[ST_STEP] = (step - manip) / F13_CG_FRAMES;
		row->stage[ST_LOOP] = (total - set - step) / F13_CG_FRAMES;
	}
	snprintf(args, sizeof args, "--profile-fig13 %d,%d,draw", row->touched, F13_CG_DRAW_FRAMES);
	total = bench_callgrind(opts, args, "fr_profiled_frames");
	row->instr_draw = total > 0.0 ? total / F13_CG_DRAW_FRAMES : -1.0;
	if (row->touched > 0) {
		snprintf(args, sizeof args, "--profile-fig13 %d,%d,alone", row->touched, F13_CG_FRAMES);
		total = bench_callgrind(opts, args, "fr_profiled_frames");
		row->instr_alone = total > 0.0 ? total / F13_CG_FRAMES : -1.0;
	}
}

static void fmt_grasped(char *out, size_t size, const f13_row *r) {
	int least = r->grasped_check < r->grasped_draw ? r->grasped_check : r->grasped_draw;
	if (least == r->touched && r->lost == 0)
		snprintf(out, size, "%d of %d", least, r->touched);
	else
		snprintf(out, size, "LOST %d of %d", least, r->touched);
}

static void print_rows(const f13_row *rows, bool counted) {
	printf("\n== fig13. The paper's point, 10 cubes: the check alone and the check + drawing, against grasped ==\n");
	printf("frames/s on the process's CPU clock, median (min-max), the two timed in interleaved batches; drawing:\n"
	       "bench/raster.h's software z-buffer, 640x480, flat-shaded (the floor, every cube's faces, the hands'\n"
	       "finger segments and palms); 4 grasped: TWO hands, one per pair\n");
	printf("%8s %6s %12s | %26s | %26s | %6s | %12s %14s\n", "grasped", "hands", "held every", "check alone",
	       "check + draw", "draw %", "instr check", "instr +draw");
	for (int i = 0; i < F13_ROWS; ++i) {
		const f13_row *r = &rows[i];
		if (!r->valid) {
			printf("%8d %6s %12s | no grasp pose found: not measured\n", r->touched, "-", "-");
			continue;
		}
		char g[32], a[64], b[64];
		fmt_grasped(g, sizeof g, r);
		snprintf(a, sizeof a, "%.0f (%.0f-%.0f)", 1.0 / r->pair.a.median, 1.0 / r->pair.a.max, 1.0 / r->pair.a.min);
		snprintf(b, sizeof b, "%.0f (%.0f-%.0f)", 1.0 / r->pair.b.median, 1.0 / r->pair.b.max, 1.0 / r->pair.b.min);
		printf("%8d %6d %12s | %26s | %26s | %5.1f%% | %12.0f %14.0f\n", r->touched, r->touched > 2 ? 2 : 1, g, a, b,
		       100.0 * (1.0 - r->pair.a.median / r->pair.b.median), r->instr, r->instr_draw);
	}
	if (!counted) {
		printf("instructions: not counted (valgrind is not on PATH)\n");
		return;
	}
	printf("\nthe check's instructions per frame by stage (callgrind, %d frames of each row):\n", F13_CG_FRAMES);
	printf("%-66s", "stage");
	for (int i = 0; i < F13_ROWS; ++i)
		printf(" %9d gr", rows[i].touched);
	printf("\n");
	for (int s = 0; s < ST_COUNT; ++s) {
		printf("%-66s", stage_names[s]);
		for (int i = 0; i < F13_ROWS; ++i)
			printf(" %12.0f", rows[i].valid ? rows[i].stage[s] : 0.0);
		printf("\n");
	}
	printf("%-66s", "instructions per frame, the touched cubes alone (no other cube)");
	for (int i = 0; i < F13_ROWS; ++i)
		if (rows[i].instr_alone < 0.0)
			printf(" %12s", "-");
		else
			printf(" %12.0f", rows[i].instr_alone);
	printf("\n%-66s", "objects tested against a hand per frame (past the bounding volumes)");
	for (int i = 0; i < F13_ROWS; ++i)
		printf(" %12.1f", rows[i].tests);
	printf("\n%-66s", "contacts found per frame (check points in faces, lines on edges)");
	for (int i = 0; i < F13_ROWS; ++i)
		printf(" %12.1f", rows[i].contacts);
	printf("\n");
}

static void write_csv(const bench_opts *opts, const f13_row *rows) {
	FILE *csv = bench_csv(opts, "fig13_trend.csv",
	                      "Fig. 13 at 10 cubes: frames/s of the check alone and of the check + software drawing, "
	                      "CPU time, against grasped objects; callgrind instructions per frame and stages");
	fprintf(csv, "grasped,hands,grasped_min,fps_check,fps_check_min,fps_check_max,fps_draw,fps_draw_min,fps_draw_max,"
	             "instr_check,instr_draw,instr_set_hand,instr_detect,instr_manipulate_rest,instr_step_rest,instr_loop,"
	             "tests_per_frame,contacts_per_frame,instr_alone\n");
	for (int i = 0; i < F13_ROWS; ++i) {
		const f13_row *r = &rows[i];
		if (!r->valid)
			continue;
		fprintf(csv, "%d,%d,%d,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.0f,%.0f", r->touched, r->touched > 2 ? 2 : 1,
		        r->grasped_check < r->grasped_draw ? r->grasped_check : r->grasped_draw, 1.0 / r->pair.a.median,
		        1.0 / r->pair.a.max, 1.0 / r->pair.a.min, 1.0 / r->pair.b.median, 1.0 / r->pair.b.max,
		        1.0 / r->pair.b.min, r->instr, r->instr_draw);
		for (int s = 0; s < ST_COUNT; ++s)
			fprintf(csv, ",%.0f", r->instr > 0.0 ? r->stage[s] : -1.0);
		fprintf(csv, ",%.2f,%.2f,%.0f\n", r->tests, r->contacts, r->instr_alone);
	}
	fclose(csv);
}

static void summarise(const f13_row *rows, bool counted) {
	char check[128] = "", draw[128] = "", instr[128] = "", value[160];
	for (int i = 0; i < F13_ROWS; ++i) {
		const f13_row *r = &rows[i];
		const char *sep = i ? " / " : "";
		size_t n = strlen(check), m = strlen(draw), k = strlen(instr);
		snprintf(check + n, sizeof check - n, "%s%.0f", sep, r->valid ? 1.0 / r->pair.a.median : 0.0);
		snprintf(draw + m, sizeof draw - m, "%s%.0f", sep, r->valid ? 1.0 / r->pair.b.median : 0.0);
		snprintf(instr + k, sizeof instr - k, "%s%.0f", sep, r->valid ? r->instr : 0.0);
	}
	bench_summary_add("fig13", "10 cubes, 0/1/2/4 grasped (4: 2 hands): check alone, frames/s", check, BENCH_INFO);
	bench_summary_add("fig13", "the same, check + software drawing 640x480, frames/s", draw, BENCH_INFO);
	if (counted)
		bench_summary_add("fig13", "the same, the check's instructions per frame", instr, BENCH_INFO);
	const f13_row *two = &rows[2];
	if (two->valid) { // the one ratio to the paper, the caveat beside it
		snprintf(value, sizeof value, "%.0fx (%.0f frames/s); NOT like for like: newer CPU, flat software raster, "
		         "no glove I/O", 1.0 / two->pair.b.median / F13_PAPER_FPS, 1.0 / two->pair.b.median);
		bench_summary_add("fig13", "check + draw, 10 cubes, 2 grasped / paper's 17 frames/s", value, BENCH_INFO);
	}
	for (int i = 0; i < F13_ROWS; ++i)
		if (rows[i].valid && (rows[i].lost || rows[i].grasped_check < rows[i].touched)) {
			snprintf(value, sizeof value, "%d grasped: grasp LOST in %ld frames", rows[i].touched, rows[i].lost);
			bench_summary_add("fig13", "a row's pose did not hold what it claims", value, BENCH_INFO);
		}
}

void bench_fig13(const bench_opts *opts, bench_shared *shared) {
	f13_row rows[F13_ROWS];
	memset(rows, 0, sizeof rows);
	for (int i = 0; i < F13_ROWS; ++i) {
		rows[i].touched = fig13_touched[i];
		time_row(&rows[i], opts, shared);
	}
	bool counted = bench_have_valgrind();
	for (int i = 0; i < F13_ROWS; ++i) {
		rows[i].instr = rows[i].instr_draw = rows[i].instr_alone = -1.0;
		if (counted && rows[i].valid)
			count_row(&rows[i], opts);
	}
	write_csv(opts, rows);
	print_rows(rows, counted);
	summarise(rows, counted);
}

// ---------------------------------------------------------------------------------------------
// `hs_bench --fig13-check` (make check-bench-fig13)

// Two loops of a scene: true when every touched cube was GRASP on every frame and no other cube
// was touched or woken.
static bool holds(bench_scene *sc, int touched, int *grasped, long *lost, int *stray) {
	long frames;
	bench_scene_step(sc, 2 * BENCH_PATH_FRAMES);
	bench_fig13_held(sc, grasped, lost, &frames, stray);
	return *grasped == touched && *lost == 0 && *stray == 0;
}

int bench_fig13_check(void) {
	static const int objects[] = {1, 2, 5, 10, 20, 50, 100, 1000};
	int failed = 0;
	for (int t = 1; t < F13_ROWS; ++t)
		for (int c = 0; c < (int)(sizeof objects / sizeof objects[0]); ++c) {
			int touched = fig13_touched[t], grasped;
			long lost;
			int stray;
			if (touched > objects[c])
				continue;
			bench_scene *sc = bench_fig13_scene(objects[c], touched, false);
			bool ok = sc && holds(sc, touched, &grasped, &lost, &stray);
			if (!sc)
				printf("fig13-check: FAIL: %d cubes, %d touched: no grasp pose found\n", objects[c], touched);
			else
				printf("fig13-check: %s: %4d cubes, %d touched%s: %d grasped on every frame, %ld frames lost, "
				       "%d others disturbed\n",
				       ok ? "ok" : "FAIL", objects[c], touched, touched > 2 ? " (2 hands)" : "", grasped, lost, stray);
			failed += !ok;
			bench_scene_destroy(sc);
		}
	// the check itself: hands hovering 0.3 m above the pair they claim must be caught
	bench_scene *hover = bench_fig13_false_scene(2);
	int grasped, stray;
	long lost;
	bool caught = hover && !holds(hover, 2, &grasped, &lost, &stray);
	printf("fig13-check: %s: a hand hovering over the pair it claims is %s\n", caught ? "ok" : "FAIL",
	       caught ? "caught" : "NOT caught");
	failed += !caught;
	bench_scene_destroy(hover);
	printf("fig13-check: %s\n", failed ? "FAILED" : "every row holds what it claims");
	return failed ? 1 : 0;
}
