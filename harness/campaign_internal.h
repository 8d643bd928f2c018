// campaign_internal.h — a campaign as its three files share it: what the file says (campaign.c),
// running one trial (campaign_run.c) and the summary of the trials' rows (campaign_summary.c).
#ifndef HS_HARNESS_CAMPAIGN_INTERNAL_H
#define HS_HARNESS_CAMPAIGN_INTERNAL_H

#include <stdint.h>

#include "file_list.h"
#include "hs_harness.h"

enum { HS_CAMPAIGN_MAX_AXES = 8, HS_CAMPAIGN_MAX_VALUES = 64, HS_CAMPAIGN_MAX_WORD = 48 };
enum { HS_CAMPAIGN_MAX_OPTIONS = 16 }; // model options in one value of the `model` axis
// a visitor's throws (`visitor_throws`): the default, docs/campaigns.md says why; the most
enum { HS_CAMPAIGN_VISITOR_THROWS = 5, HS_CAMPAIGN_MAX_VISITOR_THROWS = 1000 };
#define HS_CAMPAIGN_MAX_TRIALS 100000000L
#define HS_CAMPAIGN_TRUNCATE 4.0 // a thrower's draws are normal, cut at this many SD

typedef enum hs_axis_kind {
	HS_AXIS_DT,          // the frame time (`dt` as a scenario writes it)
	HS_AXIS_NOISE,       // input noise: the scenario's realistic levels times this (0: none)
	HS_AXIS_THROW_SCALE, // the thrower's three SDs times this
	HS_AXIS_MODEL,       // one `model:` option, or a named set of them
	HS_AXIS_SCENARIO,    // the base scenario (`scenario:` a list): always the first axis
} hs_axis_kind;

typedef struct hs_axis {
	hs_axis_kind kind;
	char name[HS_CAMPAIGN_MAX_WORD]; // its CSV column: dt, noise, throw_scale or the model key
	int count;
	double value[HS_CAMPAIGN_MAX_VALUES];                     // dt, noise, throw_scale
	char text[HS_CAMPAIGN_MAX_VALUES][HS_CAMPAIGN_MAX_WORD];  // a model value as written, a scenario's name
	char *model[HS_CAMPAIGN_MAX_VALUES];                      // its override text at its line; a scenario's path
} hs_axis;

// The thrower (hs_throw_error): its hand, swing and the SDs of its errors.
typedef struct hs_thrower_spec {
	bool given;
	int hand[HS_CAMPAIGN_MAX_VALUES]; // in each scenario
	double from, release;         // s
	double timing, speed, angle;  // SD: s, relative, rad (azimuth and elevation each)
	bool phase;                   // the script starts U[0, dt) late: the frame clock's phase
	// s, in each scenario: when the hand's script starts to open it (its glove's last key before
	// `release` with the reading at `from`); a grasp lost before that is no throw (campaign_run.c)
	double opens[HS_CAMPAIGN_MAX_VALUES];
} hs_thrower_spec;

typedef struct hs_target {
	bool given;
	int object[HS_CAMPAIGN_MAX_VALUES]; // in each scenario
	double x, y, radius; // m
} hs_target;

struct hs_campaign {
	char *path, *scenario; // the base scenario (NULL: a scenario axis)
	double dt[HS_CAMPAIGN_MAX_VALUES];       // s: each scenario's own frame time
	double duration[HS_CAMPAIGN_MAX_VALUES]; // s: each scenario's duration
	// each scenario read and parsed once (a trial's load then builds its world from the document:
	// the parse was three fifths of a 12 frames/s trial); `sources` of them are open
	int sources;
	struct hs_scenario_source *source; // [HS_CAMPAIGN_MAX_VALUES]
	uint64_t seed;
	long per_cell, cells, trials;
	bool judge_all; // every clause, not only the robust ones
	long visitor_throws; // with a thrower: trials k to k + visitor_throws - 1 of a cell are one visitor
	int axis_count;
	hs_axis axes[HS_CAMPAIGN_MAX_AXES];
	hs_thrower_spec thrower;
	hs_target target;
	hs_file_list inputs; // the campaign's file, its scenarios' and theirs (hs_campaign_input_path)
};

// One trial's inputs: the cell's axis values and the trial's draws.
typedef struct hs_trial {
	long index, cell, k;
	int value[HS_CAMPAIGN_MAX_AXES]; // an index into each axis
	uint64_t seed;
	int scenario_index;   // in the scenario axis (0 without one)
	hs_scenario_options options;
	const char *models[HS_CAMPAIGN_MAX_AXES];
	hs_throw_error error;
} hs_trial;

// campaign_run.c: the trial's options (pointers into `c` and `t`); the trial CSV's header line
// (no newline).
void hs_trial_prepare(const hs_campaign *c, long index, hs_trial *t);
enum { HS_CAMPAIGN_HEADER = 1024 };
void hs_campaign_header(const hs_campaign *c, char *text, size_t size);
// Whether the trial rows say if the grasp was lost in the swing: a thrower and a target given.
static inline bool hs_campaign_watches_grasp(const hs_campaign *c) { return c->thrower.given && c->target.given; }

#endif
