// bench.h — shared pieces of `make bench`: timing, statistics, progress, the result registry.
//
// Benchmarks report; they never fail on a time. Every timing is CLOCK_MONOTONIC around a batch
// of steps, after a warm-up, repeated (≥ 5 times) and summarised as median with min–max beside
// it. Nothing is pinned to a core. Every stepped state
// feeds a checksum that is printed, so no work can be optimised away.
#ifndef HS_BENCH_H
#define HS_BENCH_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "hs_bench.h"
#include "handspring.h"

/// Run options from the command line.
typedef struct bench_opts {
	bool quick;          ///< `make bench QUICK=1`: shorter batches, fewer points, under a minute
	const char *out_dir; ///< CSV files go here (the plots are drawn from them by bench.mk)
	double batch_s;      ///< s: wall time of one timed batch
	int reps;            ///< timed batches per figure (≥ 5)
} bench_opts;

/// s on CLOCK_MONOTONIC.
double bench_now(void);

/// Median and range of a set of per-frame times (s).
typedef struct bench_stats {
	double median, min, max; ///< s per step
	long steps;              ///< steps per batch
	int reps;
} bench_stats;

/// Runs `frames` steps of a case; accumulates into its own checksum.
typedef void (*bench_step_fn)(void *state, long frames);

/// Warm-up (calibrates the batch to opts->batch_s), then opts->reps timed batches of the same
/// number of steps. Returns seconds per step.
bench_stats bench_measure(bench_step_fn step, void *state, const bench_opts *opts);

/// The same as bench_measure for two cases at once, their timed batches interleaved (a, b, a, b, ...)
/// so that whatever else the machine runs slows both alike. Returns the median over the repeats of
/// a's time over b's in the same repeat: the stable figure on a busy machine.
double bench_measure_pair(bench_step_fn step_a, void *a, bench_step_fn step_b, void *b, const bench_opts *opts,
                          bench_stats *out_a, bench_stats *out_b);

/// s of CPU time of this process (CLOCK_PROCESS_CPUTIME_ID): time the process was not given is not counted.
double bench_cpu_now(void);

/// Two cases in interleaved batches (a, b, a, b, ...) timed on the process's CPU clock, ≥ 7 pairs.
typedef struct bench_pair {
	bench_stats a, b;                   ///< s per step of each
	double ratio, ratio_min, ratio_max; ///< a's time over b's in the same pair: median and range
	int pairs;
} bench_pair;
bench_pair bench_measure_pair_cpu(bench_step_fn step_a, void *a, bench_step_fn step_b, void *b, const bench_opts *opts);

/// True when valgrind is on PATH.
bool bench_have_valgrind(void);
/// The instructions callgrind counts in the function `toggle` (--toggle-collect) when this program
/// runs again under valgrind with the flags `args` (its files: opts->out_dir/cg*); −1 without
/// valgrind or when the run failed. Each `args` is run once per process.
double bench_callgrind(const bench_opts *opts, const char *args, const char *toggle);

/// The inclusive instructions of function `fn` in the callgrind run bench_callgrind made for
/// `args` (read with callgrind_annotate); −1 when that run or the function is missing.
double bench_callgrind_fn(const bench_opts *opts, const char *args, const char *fn);

/// Median of n values (sorts a copy; n ≤ 64).
double bench_median(const double *values, int n);

/// A profiling flag's "NAME,FIRST[,SECOND]": NAME into name (size bytes, cut short), *first and
/// *second at the text after each comma (NULL when absent).
void bench_split_spec(const char *spec, char *name, size_t size, const char **first, const char **second);

/// Progress and notes go to stderr, tables to stdout.
void bench_progress(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/// Opens out_dir/name for writing (exits with a message when it cannot).
FILE *bench_csv(const bench_opts *opts, const char *name, const char *about);
/// Starts DIR/meta.txt: the machine, date, compiler, flags and QUICK; bench_csv adds a line per CSV.
void bench_meta_start(const bench_opts *opts);

/// The closing summary: one line per figure, and the targets (docs/benchmarks.md, "A run").
typedef enum bench_verdict { BENCH_INFO = 0, BENCH_MET, BENCH_NOT_MET, BENCH_UNKNOWN } bench_verdict;
void bench_summary_add(const char *section, const char *what, const char *value, bench_verdict verdict);
void bench_summary_print(FILE *out, const bench_opts *opts);
/// Records the machine's load average before the first timing (other processes skew medians).
void bench_note_start(void);

/// The grasp-start rule of every hand scene of the bench: the 1999 paper's (two contact normals
/// 90° apart, no pressing toward each other nor closing asked). The seed scene's hand holds two
/// adjacent cubes together, thumb on one and fingers on the other, as the paper's Experiment 3
/// does; neither cube has opposed contacts, so handspring's default start rule never grasps them
/// (scenarios/hand/seed_scene_hand.yaml runs the same rule for the same reason; docs/model.md §3).
void bench_grasp_start(hs_world_def *wd);

/// Folds 8 bytes into a running FNV-1a checksum.
uint64_t bench_mix(uint64_t h, double x);

// ---------------------------------------------------------------------------------------------
// Sections (the registry of what `make bench` runs, in order)

/// Hand-model figures shared between sections (the peers compare against the seed scene).
typedef struct bench_shared {
	double seed_us_per_frame;      ///< µs per frame of the seed scene, skip_work on (0: not measured)
	double seed_dt;                ///< s: the frame time the seed scene is stepped with
	double projectile_error_60;    ///< m: the 1999 Verlet landing error at the peers' dt
	uint64_t checksum;
} bench_shared;

void bench_frame_rate(const bench_opts *opts, bench_shared *shared); // items 1 and 2
void bench_accuracy(const bench_opts *opts, bench_shared *shared);   // item 3
void bench_throw(const bench_opts *opts, bench_shared *shared);      // item 4
void bench_peers(const bench_opts *opts, bench_shared *shared);      // item 5
void bench_collide(const bench_opts *opts, bench_shared *shared);    // item 6
/// `--profile-collide KIND,FRAMES[,N]` (collide_scaling.c): one collision scene alone, for callgrind.
void bench_profile_collide(const char *spec);
/// The seed scene of item 1 timed alone (the peers' comparison when item 1 did not run).
bench_stats bench_seed_measure(const bench_opts *opts, bool skip);
/// N frames of the seed scene alone (for a profiler): 10 objects (or `objects`), 2 grasped; `honest`:
/// the honest frame's input (noisy glove reading and turning wrist every frame, the hash every frame).
/// `deadband`: the measured scene's glove deadband in sensor units (−1: the world's default, 3).
void bench_profile_seed(long frames, int objects, bool skip, bool paper, bool honest, int deadband);
/// `--noisy-joints IN OUT`: a joint recording (handspring joints) with seeded uniform noise of
/// ±BENCH_JOINT_NOISE_MM on every coordinate, as a hand tracker's jitter (bench/joint_noise.c).
#define BENCH_JOINT_NOISE_MM 1.0
int bench_noisy_joints(const char *in, const char *out);

// ---------------------------------------------------------------------------------------------
// The seed scene and the projectile, as every engine builds them (the peers use these numbers)

#define BENCH_CUBE 0.05        ///< m: the seed cubes' edge
#define BENCH_SPACING 0.06     ///< m: centre spacing of the floor grid (1 cm gaps)
#define BENCH_ROW_Y 0.3        ///< m: y of the seed row (scenarios/seed_scene.yaml)
#define BENCH_PER_ROW 10       ///< cubes per grid row
#define BENCH_PATH_FRAMES 120  ///< frames of one loop of the scripted hand path
#define BENCH_DT (1.0 / 60.0)  ///< s: frame time of the frame-rate scenes and the peers

/// Centre of grid cell (i, j): x = (i − 4.5) · spacing, y = 0.3 − j · spacing, on the floor.
hs_vec3 bench_cell(int i, int j);
/// Offset of the scripted loop at frame k (0 ≤ k < BENCH_PATH_FRAMES): lift straight up, swing
/// sideways only once clear of the neighbours, come straight down; zero at k = 0.
hs_vec3 bench_path(int k);

/// The projectile: G starts at (0, 0, 1) m with v = (2, 0, 1) m/s under g = 9.81 m/s²; its range
/// is where G crosses the plane z = 0.5 m (above the floor, so no contact is involved).
#define BENCH_PROJ_Z0 1.0
#define BENCH_PROJ_VX 2.0
#define BENCH_PROJ_VZ 1.0
#define BENCH_PROJ_PLANE 0.5
#define BENCH_G 9.81
/// Closed-form range: x at the plane crossing.
double bench_projectile_range(void);
/// The crossing of the plane from per-frame samples: the quadratic through the last three samples
/// (exact for a sampled parabola), solved for z = plane; returns x there. `z` and `x` hold n ≥ 3
/// samples at spacing dt, the last one below the plane and the one before above it.
double bench_crossing_x(const double *x, const double *z, int n, double plane);


// ---------------------------------------------------------------------------------------------
// Peers (bench/peer_ode.c, bench/peer_mujoco.c, built only when their headers exist)

/// The seed scene in a peer engine: 8 resting dynamic cubes, the 2 grasped ones as kinematic
/// (ODE) or mocap (MuJoCo) bodies on the path of the hand, stepped at BENCH_DT.
typedef struct bench_peer_result {
	bool ran;
	char name[32], version[64], setup[192];
	bench_stats step;        ///< s per step of the seed scene
	double projectile_error; ///< m: range error of the projectile at BENCH_DT (bench_crossing_x)
	double resting_drift;    ///< m: largest displacement of a resting cube after the timed steps
	uint64_t checksum;
} bench_peer_result;

#ifdef HS_BENCH_ODE
/// Fills out[0] (auto-disable off, ODE's default) and out[1] (on); returns 2.
int bench_peer_ode(const bench_opts *opts, bench_peer_result out[2]);
#endif
#ifdef HS_BENCH_MUJOCO
bench_peer_result bench_peer_mujoco(const bench_opts *opts);
#endif

// ---------------------------------------------------------------------------------------------
/// The race (bench/race.c): one frame of the honest seed scene as handspring ran
/// it: the hand's 20 check points, the 10 cubes' poses (the 2 grasped first) and which fingers
/// touch which cubes (bit finger · 10 + cube).
typedef struct bench_race_frame {
	hs_vec3 points[HS_HAND_POINTS];
	hs_vec3 pos[10];
	hs_quat rot[10];
	uint64_t touch;
} bench_race_frame;
/// Records one loop (BENCH_PATH_FRAMES frames) of the honest seed scene; *finger_radius (m).
void bench_race_record(bench_race_frame frames[BENCH_PATH_FRAMES], double *finger_radius);
/// The honest frame (the seed scene on noisy glove input, wrist turning, hash every frame) timed.
bench_stats bench_honest_measure(const bench_opts *opts);
void bench_race(const bench_opts *opts, bench_shared *shared); // section `race`
/// `--profile-race ENGINE,N` (ode or mujoco): N frames of one peer at its matched radius, for
/// callgrind --toggle-collect=race_profiled_frames.
void bench_profile_race(const char *spec);

// ---------------------------------------------------------------------------------------------
/// The floor (bench/floor.c): one frame of the honest frame as its contact detection saw it.
#define BENCH_FLOOR_CUBES 10
#define BENCH_FLOOR_MAX_CONTACTS 64
#define BENCH_FLOOR_SETUP 6 ///< frames of the honest scene's set-up (the hand comes down and closes)
typedef struct bench_floor_frame {
	hs_vec3 points[HS_HAND_POINTS];       ///< m: the check points after the step (the world's)
	hs_vec3 lines[HS_HAND_LINES][2];      ///< m: the check lines, from the reading the hand used
	hs_vec3 pos[BENCH_FLOOR_CUBES];       ///< m: each cube where handspring tested it (a held cube
	hs_quat rot[BENCH_FLOOR_CUBES];       ///<    carried to the hand's new pose first)
	hs_vec3 pos_before[BENCH_FLOOR_CUBES];///< m: each cube at the start of the frame
	hs_quat rot_before[BENCH_FLOOR_CUBES];
	uint16_t held;                        ///< bit i: cube i was grasped when the frame began
	int contacts;                         ///< handspring's contacts this frame (hs_world_contacts)
	uint8_t part[BENCH_FLOOR_MAX_CONTACTS], cube[BENCH_FLOOR_MAX_CONTACTS]; ///< check point i or 20 + line j; cube
} bench_floor_frame;
/// Builds the honest frame's scene with its BENCH_FLOOR_SETUP set-up frames recorded, then steps it
/// n frames more as the honest frame does; frames gets BENCH_FLOOR_SETUP + n. Returns how many
/// frames' check points differ from the kinematics of the reading the hand used (0: the recorded
/// lines are the world's own).
long bench_floor_record(bench_floor_frame *frames, int n);
void bench_floor(const bench_opts *opts, bench_shared *shared); // section `floor`
/// `--floor-check`: 0 when the floor finds handspring's contacts on every recorded frame (and a
/// floor without its memory of parts that started inside does not), else 1.
int bench_floor_check(void);
/// `--profile-floor N`: N frames of the floor alone (callgrind --toggle-collect=floor_profiled_frames).
void bench_profile_floor(long frames);

// ---------------------------------------------------------------------------------------------
/// Scaling rows of the honest frame (bench/hand_scaling.c): cost per frame against
/// faces, grasped objects, hands and untouched objects, each against the honest frame in the same run.
void bench_hand_scaling(const bench_opts *opts, bench_shared *shared);
/// `--profile-scaling ROW,VALUE[,FRAMES]` (ROW faces, grasped, hands, untouched or untouched-nohash;
/// FRAMES 600 by default): one point's scene alone, for callgrind --toggle-collect=hsc_profiled_frames.
void bench_profile_scaling(const char *spec);

/// The shapes of the frame-rate scenes: 5 cm across; the balls are UV polyhedra (bench_uv_ball).
typedef enum bench_shape {
	BENCH_SHAPE_CUBE = 0,     ///< 6 faces, 12 edges
	BENCH_SHAPE_ELLIPSOID,    ///< the paper's 32 faces, 56 edges (8 slices, 4 stacks)
	BENCH_SHAPE_POLY128,      ///< 128 faces (16 slices, 8 stacks)
	BENCH_SHAPE_POLY512,      ///< 512 faces (32 slices, 16 stacks)
	BENCH_SHAPES
} bench_shape;
/// A ball of radius r (m) as a convex UV polyhedron of slices × stacks faces (triangle fans at the
/// poles, planar trapezoids between), built through hs_shape_polyhedron.
hs_shape *bench_uv_ball(int slices, int stacks, double r, hs_status *status);

/// The honest frame's scene (bench/frame_rate.c) with `objects` objects of `shape`, the first two
/// grasped; objects beyond the first row start `far_rows` rows further back (out of the hand's
/// reach). NULL when no grasp pose was found for the shape.
typedef struct fr_scene bench_scene;
bench_scene *bench_honest_scene(bench_shape shape, int objects, int far_rows);
void bench_scene_step(void *scene, long frames);
/// Hash the state every frame (the default) or not (to see what the hash costs).
void bench_scene_hash(bench_scene *scene, bool on);
/// Frames with a grasp lost, untouched objects touched or awake now, and the scene's checksum.
void bench_scene_report(const bench_scene *scene, long *lost, int *stray, uint64_t *checksum);
void bench_scene_destroy(bench_scene *scene);
/// The seed of the honest frame's glove noise (other hands take their own).
#define BENCH_HONEST_SEED 0x9E3779B97F4A7C15ull
/// The honest frame's input for one loop: the reading `held` with seeded uniform noise of ±4 units
/// on every sensor, and the wrist turning by up to 2.5° about x and y.
void bench_honest_readings(const uint8_t held[HS_GLOVE_SENSORS], uint64_t seed,
                           uint8_t noisy[BENCH_PATH_FRAMES][HS_GLOVE_SENSORS], hs_quat turns[BENCH_PATH_FRAMES]);
/// The honest frame's hand for 1 or 2 cubes (a pair along x) resting with centroid `centroid`: the
/// wrist at the start of the loop and the squeezed posture the noise is drawn around. False when
/// the pose search found no grasp.
bool bench_honest_hand(int touched, hs_vec3 centroid, hs_vec3 *wrist, uint8_t held[HS_GLOVE_SENSORS]);

// ---------------------------------------------------------------------------------------------
/// Fig. 13 at 10 objects (bench/fig13.c): 0, 1, 2, 4 grasped, the check alone and the check plus
/// drawing the scene (bench/raster.h), instructions and stages by callgrind.
void bench_fig13(const bench_opts *opts, bench_shared *shared); // section `fig13`
/// The frame-rate sweep's cube scene (bench/frame_rate.c) with `objects` cubes, `touched` 0, 1, 2 or 4
/// of them grasped (4: two hands, one per pair), skip_work on, the pose the sweep found; drawn every
/// frame when `draw`. NULL when no grasp pose was found.
bench_scene *bench_fig13_scene(int objects, int touched, bool draw);
/// A scene whose hands hover 0.3 m above the `touched` cubes they claim (the grasp check must catch it).
bench_scene *bench_fig13_false_scene(int touched);
/// The fewest touched objects GRASP on any frame stepped, frames with one lost, frames stepped, and
/// untouched objects now touched or awake.
void bench_fig13_held(const bench_scene *scene, int *grasped_min, long *lost, long *frames, int *stray);
/// Steps `frames` more frames and gives, per frame, the objects tested against a hand after the
/// bounding-volume check (hs_world_counters.hand_tests) and the contacts found (hs_world_contacts).
void bench_fig13_work(bench_scene *scene, long frames, double *tests, double *contacts);
/// The scene's last drawn frame as a PPM image; false when it is not drawn or cannot be written.
bool bench_fig13_picture(const bench_scene *scene, const char *path);
/// `--profile-fig13 TOUCHED,FRAMES[,draw|alone]`: one row alone, drawn, or its touched cubes without
/// the other eight (callgrind --toggle-collect=fr_profiled_frames).
void bench_profile_fig13(const char *spec);
/// `--fig13-check`: 0 when every cube row of the sweep grasps, on every frame of two loops, all it
/// claims (and a hovering hand is caught), else 1.
int bench_fig13_check(void);


#endif
