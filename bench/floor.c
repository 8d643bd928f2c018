// floor.c — section `floor` of `make bench`, `make bench-floor` and `make check-bench-floor`: the
// honest frame against a floor measured in the same run.
//
// The floor (floor_detect.c) is the least code that finds the honest frame's contacts: the 20
// check points and 60 check lines against the ten cubes, point-in-box and segment-against-box in
// structures of arrays, with the per-part memory the contact set needs. It is fed exactly what
// handspring's detection saw, recorded from the honest scene after each step through the public
// API (bench_floor_record: the world's check points, the check lines of the reading the hand used,
// the cubes where handspring tested them), and it is honest only because it finds the same
// contacts: per frame the same check points and lines on the same cubes (`--floor-check`, which
// also shows that a floor without the memory of parts that started inside is caught).
// handspring's figure is its whole honest frame (glove kinematics, detection, grasp, carrying,
// hash); the floor's is detection alone, on input already made.
#include <stdlib.h>
#include <string.h>

#include "floor.h"

#define FLOOR_FRAMES 600 // five loops of the hand's path, after the set-up

typedef struct floor_run {
	floor_input *in; // BENCH_FLOOR_SETUP + FLOOR_FRAMES frames
	bench_floor_frame *rec;
	int frames;
	floor_state st;
	int k; // the next frame, cycling over the honest ones
	uint64_t checksum;
} floor_run;

static void to_soa(const bench_floor_frame *r, floor_input *in) {
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		in->hand.px[i] = r->points[i].x, in->hand.py[i] = r->points[i].y, in->hand.pz[i] = r->points[i].z;
	for (int j = 0; j < HS_HAND_LINES; ++j)
		for (int e = 0; e < 2; ++e) {
			in->hand.lx[60 * e + j] = r->lines[j][e].x;
			in->hand.ly[60 * e + j] = r->lines[j][e].y;
			in->hand.lz[60 * e + j] = r->lines[j][e].z;
		}
	for (int c = 0; c < BENCH_FLOOR_CUBES; ++c) {
		floor_poses *n = &in->now, *b = &in->before;
		n->x[c] = r->pos[c].x, n->y[c] = r->pos[c].y, n->z[c] = r->pos[c].z;
		n->qw[c] = r->rot[c].w, n->qx[c] = r->rot[c].x, n->qy[c] = r->rot[c].y, n->qz[c] = r->rot[c].z;
		b->x[c] = r->pos_before[c].x, b->y[c] = r->pos_before[c].y, b->z[c] = r->pos_before[c].z;
		b->qw[c] = r->rot_before[c].w, b->qx[c] = r->rot_before[c].x;
		b->qy[c] = r->rot_before[c].y, b->qz[c] = r->rot_before[c].z;
	}
	in->held = r->held;
}

static void reset_state(floor_run *run, bool forget) {
	hs_world_def wd = hs_default_world_def();
	memset(&run->st, 0, sizeof run->st);
	run->st.margin = wd.grasp_release_mm * 1e-3;
	run->st.finger_radius = hs_default_hand_def().finger_radius;
	run->st.forget = forget;
}

static floor_run *floor_run_create(void) {
	floor_run *run = calloc(1, sizeof *run);
	int n = BENCH_FLOOR_SETUP + FLOOR_FRAMES;
	if (!run || !(run->in = calloc((size_t)n, sizeof *run->in)) || !(run->rec = calloc((size_t)n, sizeof *run->rec))) {
		fprintf(stderr, "bench: floor: out of memory\n");
		exit(2);
	}
	long differ = bench_floor_record(run->rec, FLOOR_FRAMES);
	if (differ)
		bench_progress("[floor] WARNING: %ld frames' check points differ from the recorded reading's kinematics\n", differ);
	run->frames = n;
	for (int f = 0; f < n; ++f)
		to_soa(&run->rec[f], &run->in[f]);
	run->checksum = 14695981039346656037ull;
	return run;
}

static void floor_run_destroy(floor_run *run) {
	free(run->in);
	free(run->rec);
	free(run);
}

// Frame f through the floor (its hand a frame ago: frame f − 1's; the first frame's own).
static void floor_frame(floor_run *run, int f, floor_found *out) {
	floor_detect(&run->st, &run->in[f], &run->in[f > 0 ? f - 1 : 0], out);
}

// The timed steps: the honest frames over and over, the memory carried on (frame 0 of each loop
// follows the last, as the honest frame's loop does).
static void floor_step(void *state, long frames) {
	floor_run *run = state;
	for (long n = 0; n < frames; ++n) {
		floor_found out;
		int f = BENCH_FLOOR_SETUP + run->k;
		floor_detect(&run->st, &run->in[f], &run->in[run->k ? f - 1 : run->frames - 1], &out);
		run->checksum ^= out.points[0] + (out.points[1] << 1) + out.lines[1];
		run->k = run->k + 1 == FLOOR_FRAMES ? 0 : run->k + 1;
	}
}

// handspring's contacts of a recorded frame as the floor writes them.
static void handspring_found(const bench_floor_frame *r, floor_found *out) {
	memset(out, 0, sizeof *out);
	for (int c = 0; c < r->contacts; ++c) {
		if (r->part[c] < HS_HAND_POINTS)
			out->points[r->cube[c]] |= 1u << r->part[c];
		else
			out->lines[r->cube[c]] |= (uint64_t)1 << (r->part[c] - HS_HAND_POINTS);
	}
}

static int count_found(const floor_found *f) {
	int n = 0;
	for (int c = 0; c < BENCH_FLOOR_CUBES; ++c)
		n += __builtin_popcount(f->points[c]) + __builtin_popcountll(f->lines[c]);
	return n;
}

typedef struct floor_agreement {
	int frames, agree, first_bad;
	long contacts_hs, contacts_floor;
	char first[200]; // the first frame that differs
} floor_agreement;

// The set-up's frames, where the hand closes on the cubes, need the trailing-part rule the floor
// leaves out (docs/model.md §3: the index and middle fingers' DIPs reach the faces behind their
// tips, and are set aside): there the floor's memory of which parts touch is handspring's contacts.
static void follow_setup(floor_run *run, const floor_found *mine, const floor_found *theirs) {
	uint32_t p_mine = 0, p_theirs = 0;
	uint64_t l_mine = 0, l_theirs = 0;
	for (int c = 0; c < BENCH_FLOOR_CUBES; ++c) {
		p_mine |= mine->points[c], p_theirs |= theirs->points[c];
		l_mine |= mine->lines[c], l_theirs |= theirs->lines[c];
	}
	run->st.touch_points = (run->st.touch_points & ~p_mine) | p_theirs;
	run->st.touch_lines = (run->st.touch_lines & ~l_mine) | l_theirs;
}

// Every recorded frame through the floor from a fresh memory, the honest ones against handspring's contacts.
static floor_agreement compare(floor_run *run, bool forget) {
	floor_agreement a;
	memset(&a, 0, sizeof a);
	a.first_bad = -1;
	reset_state(run, forget);
	for (int f = 0; f < run->frames; ++f) {
		floor_found mine, theirs;
		floor_frame(run, f, &mine);
		handspring_found(&run->rec[f], &theirs);
		if (f < BENCH_FLOOR_SETUP) {
			follow_setup(run, &mine, &theirs);
			continue;
		}
		a.frames++;
		a.contacts_hs += count_found(&theirs);
		a.contacts_floor += count_found(&mine);
		if (memcmp(&mine, &theirs, sizeof mine) == 0) {
			a.agree++;
			continue;
		}
		if (a.first_bad >= 0)
			continue;
		a.first_bad = f;
		for (int c = 0; c < BENCH_FLOOR_CUBES; ++c)
			if (mine.points[c] != theirs.points[c] || mine.lines[c] != theirs.lines[c]) {
				snprintf(a.first, sizeof a.first, "frame %d, cube %d: points %05x lines %015llx, handspring's %05x %015llx", f,
				         c, mine.points[c], (unsigned long long)mine.lines[c], theirs.points[c],
				         (unsigned long long)theirs.lines[c]);
				break;
			}
	}
	return a; // the memory as after the last honest frame: the timed loop goes on from there
}

// `hs_bench --floor-check` (make check-bench-floor): the floor finds handspring's contacts on every
// frame, and a floor without the memory of parts that started inside does not (the comparison can fail).
int bench_floor_check(void) {
	floor_run *run = floor_run_create();
	floor_agreement a = compare(run, false), forgetful = compare(run, true);
	floor_run_destroy(run);
	printf("floor-check: %d of %d honest frames the same contacts (after %d set-up frames): %ld by the floor, %ld by "
	       "handspring\n",
	       a.agree, a.frames, BENCH_FLOOR_SETUP, a.contacts_floor, a.contacts_hs);
	if (a.first_bad >= 0)
		printf("floor-check: FAIL: first difference at %s\n", a.first);
	printf("floor-check: without the memory of parts that started inside: %d of %d frames agree (%ld contacts)%s\n",
	       forgetful.agree, forgetful.frames, forgetful.contacts_floor,
	       forgetful.agree < forgetful.frames ? ", caught" : "");
	bool ok = a.first_bad < 0 && a.contacts_hs > 0 && forgetful.agree < forgetful.frames;
	if (forgetful.agree == forgetful.frames)
		printf("floor-check: FAIL: the comparison did not see the forgetful floor\n");
	printf("floor-check: %s\n", ok ? "ok" : "FAIL");
	return ok ? 0 : 1;
}

// `hs_bench --profile-floor N`: N frames of the floor alone, for callgrind.
__attribute__((noinline)) void floor_profiled_frames(floor_run *run, long frames);
void floor_profiled_frames(floor_run *run, long frames) { floor_step(run, frames); }

void bench_profile_floor(long frames) {
	floor_run *run = floor_run_create();
	(void)compare(run, false); // its memory as the timed loop's
	floor_profiled_frames(run, frames);
	printf("floor: %ld frames, checksum %016llx\n", frames, (unsigned long long)run->checksum);
	floor_run_destroy(run);
}

static void print_instr(char *out, size_t size, double instr) {
	if (instr < 0.0)
		snprintf(out, size, "-");
	else
		snprintf(out, size, "%.0f", instr);
}

void bench_floor(const bench_opts *opts, bench_shared *shared) {
	floor_run *run = floor_run_create();
	floor_agreement a = compare(run, false);
	bench_scene *hs = bench_honest_scene(BENCH_SHAPE_CUBE, BENCH_FLOOR_CUBES, 0);
	if (!hs) {
		printf("\n== Floor: not measured (no grasp pose for the honest frame) ==\n");
		floor_run_destroy(run);
		return;
	}
	bench_pair p = bench_measure_pair_cpu(bench_scene_step, hs, floor_step, run, opts);
	long lost;
	int stray;
	uint64_t hs_sum;
	bench_scene_report(hs, &lost, &stray, &hs_sum);
	bench_scene_destroy(hs);
	shared->checksum ^= hs_sum ^ run->checksum;
	char hs_args[64], fl_args[64], hs_i[32], fl_i[32];
	snprintf(hs_args, sizeof hs_args, "--profile-seed-honest %d", FLOOR_FRAMES);
	snprintf(fl_args, sizeof fl_args, "--profile-floor %d", FLOOR_FRAMES);
	double hs_instr = bench_callgrind(opts, hs_args, "fr_profiled_frames") / FLOOR_FRAMES;
	double fl_instr = bench_callgrind(opts, fl_args, "floor_profiled_frames") / FLOOR_FRAMES;
	print_instr(hs_i, sizeof hs_i, hs_instr);
	print_instr(fl_i, sizeof fl_i, fl_instr);

	printf("\n== Floor: the honest frame against the least code that finds its contacts (same run) ==\n");
	printf("floor: bench/floor_detect.c, 20 check points and 60 check lines against the 10 cubes (point in box,\n"
	       "segment against box, structures of arrays, %s), fed handspring's check points and lines after each\n"
	       "step and the cubes where handspring tested them; no kinematics, grasp, carrying or hash\n",
#if defined(__AVX__)
	       "AVX"
#elif defined(__SSE2__)
	       "SSE2"
#else
	       "scalar"
#endif
	);
	printf("same contacts: %d of %d honest frames, which check point or line on which cube (%ld contacts; its memory\n"
	       "of touching parts taken from handspring's contacts in the %d set-up frames, where the hand closes)\n",
	       a.agree, a.frames, a.contacts_hs, BENCH_FLOOR_SETUP);
	if (a.first_bad >= 0)
		printf("  DIFFERENT: first at %s\n", a.first);
	printf("%-11s %30s %14s\n", "", "CPU us/frame median (min-max)", "instr/frame");
	printf("%-11s %12.3f (%.3f-%.3f) %14s   (whole honest frame; grasp lost in %ld frames)\n", "handspring", 1e6 * p.a.median,
	       1e6 * p.a.min, 1e6 * p.a.max, hs_i, lost);
	printf("%-11s %12.3f (%.3f-%.3f) %14s   (detection alone)\n", "floor", 1e6 * p.b.median, 1e6 * p.b.min,
	       1e6 * p.b.max, fl_i);
	char ratio_i[32] = "-";
	if (hs_instr > 0.0 && fl_instr > 0.0)
		snprintf(ratio_i, sizeof ratio_i, "%.1fx", hs_instr / fl_instr);
	printf("handspring / floor: %.1fx CPU time (median of %d interleaved pairs, %.1f-%.1fx), %s instructions%s\n", p.ratio,
	       p.pairs, p.ratio_min, p.ratio_max, ratio_i,
	       hs_instr < 0.0 ? " (valgrind not found: no instruction counts)" : "");
	FILE *csv = bench_csv(opts, "floor.csv", "the honest frame against the floor: CPU time per frame in interleaved pairs");
	fprintf(csv, "who,us_per_frame,us_min,us_max,instr_per_frame,frames_agreeing,frames\n");
	fprintf(csv, "handspring,%.4f,%.4f,%.4f,%s,%d,%d\n", 1e6 * p.a.median, 1e6 * p.a.min, 1e6 * p.a.max,
	        hs_instr < 0.0 ? "" : hs_i, a.agree, a.frames);
	fprintf(csv, "floor,%.4f,%.4f,%.4f,%s,%d,%d\n", 1e6 * p.b.median, 1e6 * p.b.min, 1e6 * p.b.max,
	        fl_instr < 0.0 ? "" : fl_i, a.agree, a.frames);
	fclose(csv);
	char value[128];
	snprintf(value, sizeof value, "%.1fx CPU time (%.1f-%.1fx), %s instructions; %d of %d frames same contacts", p.ratio,
	         p.ratio_min, p.ratio_max, ratio_i, a.agree, a.frames);
	bench_summary_add("floor", "honest frame / floor (same contacts, interleaved)", value, BENCH_INFO);
	floor_run_destroy(run);
}
