// bench_main.c — `make bench`: the 1999 paper's frame-rate measurement reproduced, cost scaling,
// speed against error, throw fidelity across frame rates, and the peers side by side.
//
//   hs_bench [--quick] [--out DIR] [--only SECTION]
//   hs_bench --profile-seed N[,OBJECTS] | --profile-seed-honest N[,OBJECTS] | --profile-seed-noskip N[,OBJECTS]
//            | --profile-seed-paper N[,OBJECTS]
//                                 (N frames of the seed scene alone, 2 grasped, for perf; -honest: the
//                                 honest frame's input, noisy glove, turning wrist, hash every frame;
//                                 -paper: the paper's contact rule; callgrind
//                                 --toggle-collect=fr_profiled_frames; after --deadband N, the measured
//                                 world's glove deadband is N sensor units: 0, the moving-glove frame)
//   hs_bench --floor-check           (the floor finds handspring's contacts frame by frame: bench/floor.c)
//   hs_bench --fig13-check           (every cube row of the frame-rate sweep grasps what it claims: bench/fig13.c)
//   hs_bench --profile-fig13 T,N[,draw|alone] (N frames of the 10-cube row with T grasped; `draw`: drawn,
//                                 `alone`: the T cubes alone; callgrind --toggle-collect=fr_profiled_frames)
//   hs_bench --profile-floor N       (N frames of the floor alone; callgrind --toggle-collect=floor_profiled_frames)
//   hs_bench --profile-race ENGINE,N (N frames of the race's ENGINE, ode or mujoco, at its matched radius;
//                                 callgrind --toggle-collect=race_profiled_frames)
//   hs_bench --noisy-joints IN OUT  (a joint recording with a tracker's jitter added: make bench-instr)
//   hs_bench --profile-collide KIND,FRAMES[,N]   (box, hand, hand+box, spring, spring+box)
//   hs_bench --profile-scaling ROW,VALUE[,FRAMES] (one point of the honest frame's scaling rows: faces
//                                 6|32|128|512, grasped 0|1|2|5|10, hands 1|2|4, untouched[-nohash]
//                                 10|100|1000|10000; callgrind --toggle-collect=hsc_profiled_frames)
//
// Progress goes to stderr, the tables and the closing summary to stdout, CSV files to DIR
// (default build/bench), from which bench/*.gp draw the plots. Benchmarks report: the exit status
// is 0 whatever the times are (2 only on bad usage or an unwritable folder).
#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench.h"

// The registry: what runs, in order.
typedef struct bench_section {
	const char *name;
	const char *what;
	void (*run)(const bench_opts *opts, bench_shared *shared);
} bench_section;

static const bench_section sections[] = {
    {"frame_rate", "items 1-2: Fig. 13 frame rate, skipping", bench_frame_rate},
    {"fig13", "Fig. 13 at 10 cubes: 0/1/2/4 grasped, the check alone and with drawing", bench_fig13},
    {"accuracy", "item 3: speed against error", bench_accuracy},
    {"throw", "item 4: throw fidelity across frame rates", bench_throw},
    {"peers", "item 5: ODE and MuJoCo on the seed scene", bench_peers},
    {"collide", "item 6: collisions that scale", bench_collide},
    {"floor", "the honest frame against the least code that finds its contacts", bench_floor},
    {"race", "contact generation only, handspring against ODE and MuJoCo", bench_race},
    {"scaling", "the honest frame against faces, grasped objects, hands, untouched objects",
     bench_hand_scaling},
};
#define N_SECTIONS ((int)(sizeof sections / sizeof sections[0]))

static int usage(void) {
	fprintf(stderr, "usage: hs_bench [--quick] [--out DIR] [--only SECTION]\nsections:");
	for (int i = 0; i < N_SECTIONS; ++i)
		fprintf(stderr, " %s", sections[i].name);
	fprintf(stderr, "\n");
	return 2;
}

int main(int argc, char **argv) {
	bench_opts opts;
	memset(&opts, 0, sizeof opts);
	opts.out_dir = "build/bench";
	const char *only = NULL;
	int deadband = -1; // the world's default
	for (int i = 1; i < argc; ++i) {
		if (strcmp(argv[i], "--deadband") == 0 && i + 1 < argc) {
			char *end;
			long v = strtol(argv[++i], &end, 10);
			if (*end != '\0' || end == argv[i] || v < 0 || v > HS_MAX_GLOVE_DEADBAND) {
				fprintf(stderr, "hs_bench: --deadband takes 0 to %d sensor units, got '%s'\n", HS_MAX_GLOVE_DEADBAND,
				        argv[i]);
				return 2;
			}
			deadband = (int)v;
		} else if (strcmp(argv[i], "--noisy-joints") == 0 && i + 2 < argc)
			return bench_noisy_joints(argv[i + 1], argv[i + 2]);
		else if (strcmp(argv[i], "--quick") == 0)
			opts.quick = true;
		else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc)
			opts.out_dir = argv[++i];
		else if (strcmp(argv[i], "--only") == 0 && i + 1 < argc)
			only = argv[++i];
		else if (strcmp(argv[i], "--profile-seed") == 0 && i + 1 < argc) {
			const char *comma = strchr(argv[i + 1], ',');
			bench_profile_seed(atol(argv[i + 1]), comma ? atoi(comma + 1) : 10, true, false, false, deadband);
			return 0;
		} else if (strcmp(argv[i], "--profile-seed-honest") == 0 && i + 1 < argc) {
			const char *comma = strchr(argv[i + 1], ',');
			bench_profile_seed(atol(argv[i + 1]), comma ? atoi(comma + 1) : 10, true, false, true, deadband);
			return 0;
		} else if (strcmp(argv[i], "--profile-seed-paper") == 0 && i + 1 < argc) {
			const char *comma = strchr(argv[i + 1], ',');
			bench_profile_seed(atol(argv[i + 1]), comma ? atoi(comma + 1) : 10, true, true, false, deadband);
			return 0;
		} else if (strcmp(argv[i], "--profile-seed-noskip") == 0 && i + 1 < argc) {
			const char *comma = strchr(argv[i + 1], ',');
			bench_profile_seed(atol(argv[i + 1]), comma ? atoi(comma + 1) : 10, false, false, false, deadband);
			return 0;
		} else if (strcmp(argv[i], "--floor-check") == 0) {
			return bench_floor_check();
		} else if (strcmp(argv[i], "--fig13-check") == 0) {
			return bench_fig13_check();
		} else if (strcmp(argv[i], "--profile-fig13") == 0 && i + 1 < argc) {
			bench_profile_fig13(argv[i + 1]);
			return 0;
		} else if (strcmp(argv[i], "--profile-race") == 0 && i + 1 < argc) {
			bench_profile_race(argv[i + 1]);
			return 0;
		} else if (strcmp(argv[i], "--profile-floor") == 0 && i + 1 < argc) {
			bench_profile_floor(atol(argv[i + 1]));
			return 0;
		} else if (strcmp(argv[i], "--profile-scaling") == 0 && i + 1 < argc) {
			bench_profile_scaling(argv[i + 1]);
			return 0;
		} else if (strcmp(argv[i], "--profile-collide") == 0 && i + 1 < argc) {
			bench_profile_collide(argv[i + 1]);
			return 0;
		} else
			return usage();
	}
	if (mkdir(opts.out_dir, 0777) != 0 && errno != EEXIST) {
		fprintf(stderr, "bench: cannot create %s: %s\n", opts.out_dir, strerror(errno));
		return 2;
	}
	opts.batch_s = opts.quick ? 0.002 : 0.02;
	opts.reps = opts.quick ? 5 : 7;

	bench_shared shared;
	memset(&shared, 0, sizeof shared);
	bench_note_start();
	bench_meta_start(&opts);
	double t0 = bench_now();
	int ran = 0;
	for (int i = 0; i < N_SECTIONS; ++i) {
		if (only && strcmp(only, sections[i].name) != 0)
			continue;
		double ts = bench_now();
		bench_progress("[bench] %s (%s)\n", sections[i].name, sections[i].what);
		sections[i].run(&opts, &shared);
		fflush(stdout);
		bench_progress("[bench] %s done in %.1f s\n", sections[i].name, bench_now() - ts);
		ran++;
	}
	if (ran == 0)
		return usage();
	bench_summary_print(stdout, &opts);
	printf("checksum : %016" PRIx64 " (all stepped states; keeps the work observable); %.1f s in all\n",
	       shared.checksum, bench_now() - t0);
	printf("files    : %s/*.csv, plots %s/*.png and *.svg\n", opts.out_dir, opts.out_dir);
	return 0;
}
