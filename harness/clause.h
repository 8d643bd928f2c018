// clause.h — the expect clauses and their checks as data: what a clause says (hs_clause), what a
// check records while the run passes (hs_capture, hs_check), a scenario's whole set
// (hs_expectations). Read by the clause reader and the report (expect.c), the predicate rows
// (expect_predicates.c), the captures (capture.c) and the scenario that owns them.
#ifndef HS_HARNESS_CLAUSE_H
#define HS_HARNESS_CLAUSE_H

#include <stdbool.h>

#include "handspring.h"
#include "hs_harness.h"

enum {
	HS_SEQ_CAPACITY = 64, // collapsed contact states recorded per check
	HS_MAX_CHECKS = 1000000, // expect clauses × the objects they name ("*")
	HS_MAX_CLAUSES = 100000,
};

typedef enum hs_conserved_quantity { HS_CONSERVE_MOMENTUM, HS_CONSERVE_ENERGY } hs_conserved_quantity;

// One `expect` clause as written.
typedef struct hs_clause {
	unsigned long line;
	int object; // index, or -1 for "*"
	int pred;   // row of hs_predicates
	bool at_end;
	long frame;       // at-based: the frame whose state is checked; still and windows: the first frame watched
	long last_frame;  // still and windows: the last frame watched
	hs_vec3 target;   // near: m; velocity: m/s
	double tolerance; // near, rest_length: m; lands_at: s; velocity: m/s; stiffness: N/m; extension_ratio, conserved: 1
	unsigned axes;    // near: bit 0 x, bit 1 y, bit 2 z
	bool flag;        // resting, on_face, still, attached, candidate, grasped
	bool robust;      // `robust: true`: an outcome that must hold in every cell of a sweep
	long count;       // floor_contacts; never_contact, grasped: a contact state; attached: an hs_attach_kind (NONE: any); released: an hs_release_kind;
	                  // conserved: an hs_conserved_quantity
	double value;     // below/above/moved/swing_below: m; turned_deg: deg; lands_at: s; speed_below: m/s; ...
	int seq_len;      // contact_sequence
	long min_frames;  // contact_sequence: a state held for fewer frames is left out (`min_s`)
	unsigned char seq[HS_SEQ_CAPACITY];
	int first_member, member_count; // conserved: the group's objects in hs_expectations.members
	bool all_objects;                // conserved: the group is every object ("*")
} hs_clause;

// What a check records while the run passes: one member per kind of predicate.
typedef union hs_capture {
	struct { // at-based: the state at the clause's frame, its velocity (spring worlds: the
	         // integrated one) and the spring (spring worlds only)
		hs_object_state state;
		hs_vec3 velocity;       // m/s
		int holder;             // object on the spring, -1 when none
		int candidate;          // the 'I want this one' candidate, -1 when none
		hs_attach_kind kind;    // how the holder got there
		double ratio;           // the holder's spring extension / x0
		double extension, rest_length; // m
		double overlap;         // overlap_at_most: m, its deepest penetration into another object
		int overlap_with;       // that object, -1 when none
	} at;
	struct { // still: the reference pose and the first change
		hs_object_state state;
		bool moved;
		long moved_frame;
	} still;
	struct { // conserved and swing_below: a window of frames [from, to]
		bool began;                 // the first frame of the window has been seen
		double before[3], after[3]; // conserved: momentum (kg m/s) or energy (J, in before[0]) at from and to
		double peak;                // swing_below: the largest horizontal stylus–G distance so far, m
		long peak_frame;
	} window;
	struct { // lands_at: the first floor contact after a frame without any
		bool had_no_floor, landed;
		long frame;
	} lands;
	struct { // contact_sequence: the object's contact states, repeats collapsed
		unsigned char states[HS_SEQ_CAPACITY];
		int len;
		long overflow;        // changes that did not fit
		unsigned char last;   // the last state seen, recorded or not
		long held;            // frames `last` has been held so far
	} seq;
	hs_release release; // released: the object's last release (kind NONE: never released)
} hs_capture;

// One clause applied to one object (or to its group): the unit that passes or fails.
typedef struct hs_check {
	int clause, object; // object -1: the clause's group (conserved)
	bool captured;      // at-based: the clause's frame was captured; still: the reference pose;
	                    // windows: the last frame of the window has been seen
	hs_capture u;
} hs_check;

// Everything the expectations of one scenario hold. Allocated at load: stepping never allocates.
typedef struct hs_expectations {
	int clause_count;
	hs_clause *clauses;
	int check_count;
	hs_check *checks;
	int capture_count, capture_next;
	int *capture_order; // at-based checks in frame order, captured as the run passes their frame
	int live_count;
	int *live;          // the other checks, which capture every frame
	int member_total;
	int *members;       // conserved: the objects of every group, clause by clause
} hs_expectations;

#endif
