// expect_table.h — the predicate table's row type, shared by the clause reader (expect.c), the
// rows (expect_predicates.c) and the captures (capture.c).
#ifndef HS_HARNESS_EXPECT_TABLE_H
#define HS_HARNESS_EXPECT_TABLE_H

#include "clause.h"
#include "scenario_parser.h"
#include "state_io.h"

// Rows of hs_predicates; the keys of a clause are the predicates' names, then the modifiers.
#define HS_PREDICATE_COUNT 28
enum { HS_E_OBJECT = HS_PREDICATE_COUNT, HS_E_AT, HS_E_TOLERANCE, HS_E_AXES, HS_E_FROM, HS_E_TO, HS_E_MIN_S, HS_E_ROBUST, HS_E_COUNT };

// What a predicate accepts and how it is watched.
enum {
	HS_PRED_AT = 1u << 0,      // takes `at` (end or a time): captured once, at that frame
	HS_PRED_SPRINGS = 1u << 1, // only a spring world (a scenario with a stylus) can answer it
	HS_PRED_FROM_TO = 1u << 2, // takes `from` and `to`: watched over frames [from, to]
	HS_PRED_WINDOW = 1u << 3,  // from/to is a window: `to` must come at least one frame after `from`
	HS_PRED_AXES = 1u << 4,    // takes `axes`
	HS_PRED_GROUP = 1u << 5,   // `object` may name a group (a list or "*"): one check for the group
	HS_PRED_MIN_S = 1u << 6,   // takes `min_s`: states held for less than that are left out
};

// The member of hs_capture a predicate records into: what a state file keeps of its checks.
typedef enum hs_store {
	HS_STORE_NONE, // judged from the world at the end
	HS_STORE_AT,
	HS_STORE_STILL,
	HS_STORE_WINDOW,
	HS_STORE_LANDS,
	HS_STORE_SEQ,
	HS_STORE_RELEASE,
} hs_store;

// What was expected and what was measured, for the report line.
typedef struct hs_verdict {
	char when[64]; // at-based rows: "at end (t = 3 s)" or "at t = 1.5 s"
	char what[640], measured[640];
} hs_verdict;

typedef struct hs_predicate {
	const char *name;
	unsigned flags;
	const char *tolerance_unit; // NULL: the predicate takes no tolerance
	// reads the predicate's value (f->value[row]) into c; false with the message set
	bool (*parse)(hs_scenario_parser *p, const hs_fields *f, hs_clause *c);
	// records from the current frame: at-based rows once at the clause's frame, the others every frame
	void (*capture)(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
	hs_store store; // where it records
	// judges a check at the end; writes what was expected and what was measured
	bool (*evaluate)(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v);
} hs_predicate;

extern const hs_predicate hs_predicates[HS_PREDICATE_COUNT];

// capture.c: the rows' capture functions
void hs_capture_at(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
void hs_capture_overlap(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
void hs_capture_still(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
void hs_capture_conserved(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
void hs_capture_swing(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
void hs_capture_energy(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
void hs_capture_lands(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
void hs_capture_sequence(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
// never_contact and grasped: the first frame of [from, to] that breaks the clause (in the still store)
void hs_capture_never_contact(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
void hs_capture_grasped(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
void hs_capture_release(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame);
// A check's captures in a state file, word by word (state_io.h), as its row's `store` says.
void hs_capture_put(hs_state_io *io, hs_store store, const hs_check *k);
void hs_capture_get(hs_state_io *io, hs_store store, hs_check *k);

#endif
