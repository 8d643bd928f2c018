// scenario_internal.h — the scenario as the harness's files share it: what the file built, the
// input scripts, the expectations and the run so far; the queries below are scenario_access.c's.
#ifndef HS_HARNESS_SCENARIO_INTERNAL_H
#define HS_HARNESS_SCENARIO_INTERNAL_H

#include <stdint.h>

#include "error.h"
#include "clause.h"
#include "file_list.h"
#include "hands.h"
#include "hs_harness.h"
#include "noise.h"
#include "stylus_script.h"
#include "yaml_read.h"

enum { HS_MAX_NAME = 64 }; // characters of an object name
enum { HS_ROBUST_MAX_DTS = 16, HS_ROBUST_MAX_SEEDS = 100 };

// The `robust` block: the sweep's matrix and the noise levels of its cells.
typedef struct hs_robust {
	bool given;
	int dt_count;
	double dts[HS_ROBUST_MAX_DTS]; // s
	char dt_text[HS_ROBUST_MAX_DTS][16]; // as written, for the table
	int seeds;                     // cells use seeds 1..seeds
	bool phases;                   // seed k also runs the scripts (k - 1) / seeds of a frame late
	bool has_levels;               // any of the three below was given (the others are then 0)
	hs_noise_options levels;
} hs_robust;

struct hs_scenario {
	char *name, *description;
	double dt, duration; // s
	double phase;        // the input scripts run phase × dt late (hs_scenario_options.phase)
	long frames;         // to run: llround(duration / dt)
	long frame;          // run so far
	hs_world *world;
	int object_count;
	char **object_names;
	hs_object_id *ids;
	hs_object_state *initial; // every object at frame 0 (moved, turned_deg)
	hs_vec3 gravity;          // m/s²: the potential energy of `conserved: energy`
	bool springs;             // the scenario has a stylus: its world is a spring world (HS_WORLD_SPRING)
	hs_hands hands;           // hand worlds: glove + tracker scripts (1999 paper §5.1)
	hs_stylus_script stylus;  // spring worlds: the stylus (workbench paper §3–§5)
	hs_noise *noise;          // the input noise's generator (NULL: no noise)
	hs_noise_options noise_options;
	hs_expectations expect;
	hs_robust robust;
	bool overridden;          // loaded with a dt or noise option: a state file could not name the run
	hs_status step_status;    // the first failed step (HS_OK: none)
	long failed_frame;
	uint64_t source_hash;     // FNV-1a of the scenario file's bytes: a state file names the file it continues
	long fault_offset;        // numeric faults before a resume that the world's counters do not hold
	char *warnings;           // what the load warns of, one line each with its newline (NULL: nothing)
	hs_file_list inputs;      // the scenario's file, then every file it names (hs_scenario_input_path)
};

// A scenario file read and parsed once, to be loaded many times (a campaign's trials): each load
// builds its own scenario from the same document, as hs_scenario_load_with does from the file.
typedef struct hs_scenario_source {
	hs_yaml y; // the parsed document; y.path is the file's path (not owned)
	uint64_t hash; // FNV-1a of its bytes
} hs_scenario_source;
bool hs_scenario_source_open(hs_scenario_source *src, const char *path, hs_error *err);
void hs_scenario_source_close(hs_scenario_source *src);
hs_scenario *hs_scenario_load_source(const hs_scenario_source *src, const hs_scenario_options *options, hs_error *err);

// Appends a warning line (hs_scenario_warnings); false when out of memory.
HS_PRINTF(2, 3) bool hs_scenario_warn(hs_scenario *s, const char *fmt, ...);

// Numeric faults the world caught in this run (a resumed run counts those before the save too).
long hs_scenario_faults(const hs_scenario *s);

// The state of the i-th object (zero when the world refuses).
hs_object_state hs_scenario_state_of(const hs_scenario *s, int object);
// The index of an object handle, -1 for the null handle or another world's: objects were added
// in the file's order, so the handle's index1 is index + 1.
int hs_scenario_index_of(const hs_scenario *s, hs_object_id id);

#endif
