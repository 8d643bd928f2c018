// test_letter.c — the papers' letter as a whole (hs_world_def_letter, docs/model.md §11): which
// options each letter sets, that it leaves every other field alone, that the defaults come back,
// and that a letter world is a world of its own (its definition checksum refuses a default state).
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "handspring.h"

static void test_hand1999_sets_every_departure(void **state) {
	(void)state;
	hs_world_def d = hs_default_world_def();
	d.grasp_threshold_deg = 120.0; // not a departure: left as it is
	d.dt = 1.0 / 30.0;
	assert_int_equal(hs_world_def_letter(&d, HS_LETTER_HAND1999), HS_OK);
	assert_true(d.paper_contacts && d.grasp_any_contacts && !d.grasp_opposed && d.grasp_close_mm == 0.0);
	assert_true(d.paper_grasp_end && d.glove_deadband == 0 && d.release_fit == HS_RELEASE_FIT_OBJECT);
	assert_true(d.paper_landing && d.paper_floor_push && d.paper_push_end && d.paper_tipping && d.paper_carry);
	assert_int_equal(d.stacking, HS_STACKING_PAPER);
	assert_true(d.grasp_threshold_deg == 120.0 && d.dt == 1.0 / 30.0);
	assert_false(d.spring.pen_tip_spring || d.spring.paper_collisions); // the other paper's letter is not set
}

static void test_workbench_sets_the_spring_letter(void **state) {
	(void)state;
	hs_world_def d = hs_default_world_def(), base = hs_default_world_def();
	assert_int_equal(hs_world_def_letter(&d, HS_LETTER_WORKBENCH), HS_OK);
	assert_true(d.spring.pen_tip_spring && d.spring.paper_collisions);
	d.spring.pen_tip_spring = d.spring.paper_collisions = false;
	assert_memory_equal(&d.spring, &base.spring, sizeof d.spring); // nothing else of the spring model moved
	assert_false(d.paper_contacts || d.paper_grasp_end || d.paper_floor_push); // nor the hand model
	assert_int_equal(d.release_fit, HS_RELEASE_FIT_MEAN);
}

static void test_none_restores_the_defaults(void **state) {
	(void)state;
	hs_world_def d = hs_default_world_def(), base = hs_default_world_def();
	assert_int_equal(hs_world_def_letter(&d, HS_LETTER_HAND1999), HS_OK);
	assert_int_equal(hs_world_def_letter(&d, HS_LETTER_WORKBENCH), HS_OK); // the hand letter goes, the spring's comes
	assert_false(d.paper_contacts);
	assert_int_equal(hs_world_def_letter(&d, HS_LETTER_NONE), HS_OK);
	assert_memory_equal(&d, &base, sizeof d);
}

static void test_bad_calls_refused(void **state) {
	(void)state;
	hs_world_def d = hs_default_world_def(), base = d;
	assert_int_equal(hs_world_def_letter(NULL, HS_LETTER_HAND1999), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_def_letter(&d, (hs_letter)7), HS_ERR_INVALID_ARGUMENT);
	assert_memory_equal(&d, &base, sizeof d);
}

// A world built to a letter is its own definition: a state saved by a default world is refused.
static void test_letter_world_refuses_a_default_state(void **state) {
	(void)state;
	hs_world_def def = hs_default_world_def(), letter = def;
	assert_int_equal(hs_world_def_letter(&letter, HS_LETTER_HAND1999), HS_OK);
	hs_status st;
	hs_world *a = hs_world_create(&def, &st), *b = hs_world_create(&letter, &st);
	assert_non_null(a);
	assert_non_null(b);
	size_t n = hs_world_state_size(a);
	void *buf = malloc(n);
	assert_non_null(buf);
	assert_int_equal(hs_world_save_state(a, buf, n), HS_OK);
	assert_int_not_equal(hs_world_load_state(b, buf, n), HS_OK);
	assert_int_equal(hs_world_load_state(a, buf, n), HS_OK);
	free(buf);
	hs_world_destroy(a);
	hs_world_destroy(b);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_hand1999_sets_every_departure),
	    cmocka_unit_test(test_workbench_sets_the_spring_letter),
	    cmocka_unit_test(test_none_restores_the_defaults),
	    cmocka_unit_test(test_bad_calls_refused),
	    cmocka_unit_test(test_letter_world_refuses_a_default_state),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
