// hs_harness.h — the public API of handspring's harness: scenario files (YAML) that build a
// world, drive it with hand and stylus scripts or recorded input, and check `expect` clauses;
// the scenario catalog; trajectories and their comparison with goldens.
//
// Use: #include <handspring/hs_harness.h> (it includes handspring.h), link with
// `pkg-config --cflags --libs handspring-harness` (libhandspring-harness, libhandspring, and for
// --static also libyaml and GSL). The physics alone (handspring.h) needs neither.
// The scenario file format: scenarios/README.md in the repository; the models the scenarios
// drive: docs/model.md (index docs/README.md).
#ifndef HS_HARNESS_H
#define HS_HARNESS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "handspring.h"

#ifdef __cplusplus
extern "C" {
#endif

// ---------------------------------------------------------------------------------------------
// Scenarios: a YAML file that builds a world, drives it and states what must happen.

/// The frame times a scenario may choose (s): 1/2000 to 1/12 (the hand paper ran at 12–17
/// frames/s), a sub-range of the model's [HS_MIN_DT, HS_MAX_DT] that keeps catalog runs short.
#define HS_SCENARIO_MIN_DT (1.0 / 2000.0)
#define HS_SCENARIO_MAX_DT (1.0 / 12.0)

typedef struct hs_scenario hs_scenario;

/// An error message `file:line: what is wrong` (no trailing newline).
typedef struct hs_error {
	char message[512];
} hs_error;

/// Loads and validates a scenario file. NULL and `err` filled on any problem.
hs_scenario *hs_scenario_load(const char *path, hs_error *err);

/// What a load may change in the file (zero-initialised: nothing).
typedef struct hs_scenario_options {
	double dt;                // s: replaces the file's dt (0: the file's); the frames are round(duration / dt)
	bool noise;               // draw realistic input noise from `noise_seed`: hand worlds the robust block's
	unsigned long noise_seed; // levels, else model.input_noise's, else glove ±4 units, wrist ±0.762 mm and
	                          // ±0.15° (the tracker's static accuracy, paper §5.1); spring worlds the stylus's
	double noise_scale;       // with `noise`: every level times this, glove units rounded (0: times 1)
	/// Model options read after the file's `model:` (later ones win), each a YAML mapping's text such
	/// as "{grasp_threshold_deg: 120}" (not `spring` or `input_noise`); messages name `model_path`
	/// and the text's own lines (a campaign pads a text with newlines to its line in its file).
	int model_count;
	const char *const *model_texts;
	const char *model_path;
	/// A thrower's error on this run (NULL: none): see hs_throw_error.
	const struct hs_throw_error *throw_error;
	/// Fraction of a frame, within [0, 1): the input scripts (hands, stylus) run this much of a frame
	/// late, so their events fall elsewhere between two frames (scenarios/README.md, Robustness).
	double phase;
} hs_scenario_options;

/// A human thrower's error on one throw (docs/campaigns.md): one hand's script is changed from
/// `from` on. The wrist's path after `from` is scaled about where it is then by 1 + speed and
/// turned by `azimuth` about the vertical and by `elevation` about the horizontal line across the
/// swing (the direction from the wrist at `from` to it at `release`; up is positive; a vertical
/// swing turns about x); the wrist's orientation keeps its script. The glove's readings after
/// `from` come `timing` s later (negative: earlier) than the script has them, so the hand opens
/// that much later against the arm. `delay` runs the hand's whole script that much later (the
/// frame clock's phase against the person: a real throw does not start on a frame). Zero
/// everywhere: the script as written.
typedef struct hs_throw_error {
	int hand;         ///< the hand's index, in the file's order
	double delay;     ///< s: within [0, 1]
	double from;      ///< s: the swing starts (the fingers should be still around this time)
	double release;   ///< s: when the script's hand opens, for the swing's direction (> from)
	double timing;    ///< s
	double speed;     ///< relative: > -1
	double azimuth;   ///< rad
	double elevation; ///< rad
} hs_throw_error;

/// hs_scenario_load with overrides (`options` NULL: none). A run loaded with a dt or a noise seed
/// cannot be saved or resumed (HS_ERR_INVALID_ARGUMENT): a state file names the file's bytes only.
hs_scenario *hs_scenario_load_with(const char *path, const hs_scenario_options *options, hs_error *err);
/// A frame time as the YAML `dt:` takes it ("1/60" or "0.0125") within [HS_SCENARIO_MIN_DT,
/// HS_SCENARIO_MAX_DT]; false when it is not one.
bool hs_scenario_parse_dt(const char *text, double *dt);
/// Runs the scenario's `robust` matrix in-process: the nominal run (every clause), then every dt
/// of the block × seeds 1..seeds with the noise on (the clauses marked `robust: true`). Prints a
/// table to `out`: one row per dt, one column per seed, a cell `ok`, `L<line>` (the first failing
/// robust clause) or `fault` (the world failed to step or caught a numeric fault), then
/// `sweep: N of M cells pass`. Returns 0 when every cell and the nominal run pass, 1 when any
/// fails, 2 with `err` set on bad input (the file or any cell fails to load, no `robust` block).
int hs_scenario_sweep(const char *path, FILE *out, hs_error *err);

// ---------------------------------------------------------------------------------------------
// Campaigns: many trials of one scenario over axes of options and a thrower's errors
// (docs/campaigns.md). Trial i's row depends only on the campaign file and i.

typedef struct hs_campaign hs_campaign;

/// Loads a campaign file and checks it whole: every cell's scenario is loaded once, so a bad
/// option fails here, at its line. NULL and `err` filled on any problem.
hs_campaign *hs_campaign_load(const char *path, hs_error *err);
void hs_campaign_destroy(hs_campaign *campaign);
/// The files the campaign read: its own file (0), then its scenarios' files and the files they name.
int hs_campaign_input_count(const hs_campaign *campaign);
const char *hs_campaign_input_path(const hs_campaign *campaign, int i);
/// Trials in the campaign: cells × trials per cell.
long hs_campaign_trials(const hs_campaign *campaign);
/// What trial `trial` costs to run, in frames (its scenario's duration / its dt): for progress.
double hs_campaign_trial_frames(const hs_campaign *campaign, long trial);
/// The trial CSV's header line (with its newline).
void hs_campaign_write_header(const hs_campaign *campaign, FILE *out);
/// Runs trial `trial` (0 ≤ trial < hs_campaign_trials) and writes its CSV row. False with `err`
/// filled when the trial cannot be loaded (out of memory, a range).
bool hs_campaign_run_trial(hs_campaign *campaign, long trial, FILE *out, hs_error *err);
/// Reads a trial CSV (from `in`, named `in_path` in messages): this campaign's header, then every
/// trial's row in trial order, each once (as the tool and scripts/campaign.sh merge them), and
/// writes the per-cell summary CSV to `summary` (hits, rate, Wilson 95 % interval, mean distance)
/// and a table to `table` (either may be NULL). Returns 0; 1 when a trial's run faulted (a step
/// failed or a value went non-finite: `clauses` is `fault`; the summary counts them and is written);
/// 2 with `err` filled when the rows are refused.
int hs_campaign_summarize(const hs_campaign *campaign, FILE *in, const char *in_path, FILE *summary, FILE *table,
                          hs_error *err);
/// The Wilson score interval of `hits` of `n` at z = 1.959963984540054 (95 %); [0, 1] for n = 0.
void hs_wilson_interval(long hits, long n, double *lo, double *hi);
void hs_scenario_destroy(hs_scenario *scenario);

const char *hs_scenario_name(const hs_scenario *scenario);
const char *hs_scenario_description(const hs_scenario *scenario);
/// The world the scenario built (owned by the scenario).
hs_world *hs_scenario_world(hs_scenario *scenario);
/// Name of the i-th object, in the order of the file.
const char *hs_scenario_object_name(const hs_scenario *scenario, int i);
/// Frames the scenario runs: round(duration / dt).
long hs_scenario_frame_count(const hs_scenario *scenario);

/// Steps one frame (inputs, then the world) and records what expectations need.
/// Returns false once every frame has run.
bool hs_scenario_step(hs_scenario *scenario);

/// Evaluates every `expect` clause; writes one line per clause (PASS/FAIL and the measured
/// value) to `report` when not NULL, and a FAIL line when the world failed to step or caught a
/// numeric fault. Returns the number of failed lines.
int hs_scenario_check(const hs_scenario *scenario, FILE *report);
/// Lines hs_scenario_check writes: one per clause and object it names ("*" names every object),
/// plus one when the world failed to step, plus one when it caught a numeric fault (a non-finite
/// value: the run fails, whatever its clauses say).
int hs_scenario_expectation_count(const hs_scenario *scenario);
/// Writes the run's state at the current frame: a header (magic, version, the scenario's name, a
/// checksum of the scenario file's bytes, the frame), the harness's own state (the input noise
/// generator, what the expectations captured so far), then the world's state block
/// (hs_world_save_state). HS_OK, or a status and `err` ("state file: what is wrong").
hs_status hs_scenario_save(const hs_scenario *scenario, FILE *out, hs_error *err);
/// Restores a state written by hs_scenario_save into a scenario just loaded from the same file
/// (the same bytes: checked). Stepping then continues the saved run bit for bit, and
/// hs_scenario_check reports what the full run reports. On failure the scenario is unchanged
/// (HS_ERR_STATE_MISMATCH for a state from another scenario, file version or build).
hs_status hs_scenario_resume(hs_scenario *scenario, FILE *in, hs_error *err);
/// s: the scenario's frame time.
double hs_scenario_dt(const hs_scenario *scenario);
/// The files the scenario read, as it opened them: its own file (0), then every file it names (a
/// hand's or the stylus's `record:`). A program that writes outputs refuses to overwrite these.
int hs_scenario_input_count(const hs_scenario *scenario);
const char *hs_scenario_input_path(const hs_scenario *scenario, int i);
int hs_scenario_object_count(const hs_scenario *scenario);
/// What the load warns of, one line each ending with a newline ("" when nothing): a joint
/// recording that says no frame (read as z_up; scenarios/README.md, "Recorded joint positions").
/// The tool prints them on stderr.
const char *hs_scenario_warnings(const hs_scenario *scenario);
/// The hands, in the order of the file, and the i-th's name (NULL out of range).
int hs_scenario_hand_count(const hs_scenario *scenario);
const char *hs_scenario_hand_name(const hs_scenario *scenario, int hand);
/// How hand `hand` (0: the first) was fitted to its joint recording (scenarios/README.md,
/// "Recorded joint positions"): the RMS distance in mm between the recorded check points of every
/// tracked sample and the fitted hand's (the hand as built, its sensors and wrist pose for that
/// sample), the tracked samples, and the recording as the scenario names it (owned by the
/// scenario). Any output may be NULL. False, outputs untouched, for a hand driven by keys or a
/// glove file, or an index out of range.
bool hs_scenario_hand_fit(const hs_scenario *scenario, int hand, double *rms_mm, long *samples, const char **record);

/// The scenario files below a folder: every *.yaml, recursively (hidden entries skipped), sorted
/// by name (strcmp). A name is the path relative to the folder without ".yaml", e.g. "hand/flick";
/// a path is the folder joined with that relative path.
typedef struct hs_catalog {
	int count;
	char **names;
	char **paths;
} hs_catalog;

/// Fills `out` (free it with hs_catalog_free). False and `err` = "DIR: what is wrong" when the
/// folder cannot be read; an empty folder is a valid, empty catalog.
bool hs_catalog_load(const char *dir, hs_catalog *out, hs_error *err);
void hs_catalog_free(hs_catalog *catalog);

// ---------------------------------------------------------------------------------------------
// Trajectories: CSV, one row per object per frame.

/// Writes the header line `frame,t,object,x,y,z,qw,qx,qy,qz,contact,floor,resting,hash`.
void hs_trajectory_write_header(FILE *out);
/// Writes the rows of the current frame of a scenario's world (numbers with 17 significant digits).
void hs_trajectory_write_frame(FILE *out, hs_scenario *scenario);
/// The same for the objects i with selected[i] != 0 only (selected: one flag per object, in the
/// order of the file; NULL: every object).
void hs_trajectory_write_selected(FILE *out, hs_scenario *scenario, const uint8_t *selected);

/// What the hands and the stylus do, one row per thing per frame, the header line
/// `frame,t,kind,hand,index,x,y,z,u,v,w,flag,object,value`: kind `point` (each hand's check
/// points as measured, x y z, and as rectified, u v w; flag 1 when touching), `contact` (each
/// contact of the last step: C, its normal, flag 1 for an edge, the object's name and contact
/// state), and in spring worlds `stylus` (position, pointing ray, button, attached object, attach
/// kind), `spring` (anchor, the attached object's G, extension) and `candidate` (its G, its name).
/// scenarios/README.md gives every column. Nothing is written for a NULL `out`.
void hs_hand_trace_write_header(FILE *out);
/// Writes the rows of the current frame (hand h = index in the order added, point 0-19 as
/// hs_world_hand_points; numbers with 17 significant digits).
void hs_hand_trace_write_frame(FILE *out, hs_scenario *scenario);

/// Absolute tolerance of a golden comparison (`make check`, `handspring check`): room for libm
/// differences between machines, nothing more.
#define HS_GOLDEN_TOLERANCE 1e-12

/// Writes hand `hand` (0: the first) of a scenario as a recording of joint positions, `format`
/// "mediapipe" (21 landmarks: t,x0,y0,z0,...,z20) or "openxr" (26 joints with orientations:
/// t,px0,py0,pz0,qw0,qx0,qy0,qz0,...,qz25), one sample per frame (t = frame × dt, frame 0
/// included) of the scenario's input (its keys or recording, no noise), through the glove model's
/// kinematics, `rate` samples per second (t = k / rate). The file says its frame, units and hand
/// (@frame z_up, @units m, @hand) and has a `tracked` column when the hand has untracked samples.
/// A hand's `record:` reads such files back (scenarios/README.md). False with `err`.
bool hs_scenario_export_joints(hs_scenario *scenario, int hand, const char *format, double rate, FILE *out,
                               hs_error *err);

/// Compares a trajectory with its golden (both as written above; lines starting with '#' are
/// comments). Numbers must agree within `tolerance` (absolute), contact states and row keys exactly.
/// Returns true when they match; otherwise writes the first mismatch into `why`, as
/// "LABEL: frame F, object O, field X: golden G, now N (difference D)".
bool hs_trajectory_compare(FILE *golden, FILE *actual, double tolerance, const char *label, char *why,
                           size_t why_size);

#ifdef __cplusplus
}
#endif

#endif
