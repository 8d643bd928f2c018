// test_util.h — shared helpers for the cmocka tests (included after cmocka.h).
#ifndef HS_TEST_UTIL_H
#define HS_TEST_UTIL_H

#include <math.h>
#include <stdio.h>

#include "hs_harness.h"

// |a - b| <= tol, with both values printed on failure
#define assert_near(a, b, tol)                                                                          \
	do {                                                                                                \
		double hs_a_ = (a), hs_b_ = (b), hs_t_ = (tol);                                                  \
		if (!(fabs(hs_a_ - hs_b_) <= hs_t_)) {                                                          \
			print_error("%s = %.17g, %s = %.17g, |diff| = %.3g > %.3g\n", #a, hs_a_, #b, hs_b_,          \
			            fabs(hs_a_ - hs_b_), hs_t_);                                                     \
			fail();                                                                                     \
		}                                                                                               \
	} while (0)

#define assert_vec3_near(a, b, tol)                                                                     \
	do {                                                                                                \
		hs_vec3 hs_va_ = (a), hs_vb_ = (b);                                                              \
		assert_near(hs_va_.x, hs_vb_.x, tol);                                                            \
		assert_near(hs_va_.y, hs_vb_.y, tol);                                                            \
		assert_near(hs_va_.z, hs_vb_.z, tol);                                                            \
	} while (0)

// Adds an object of `shape` (taken and destroyed) whose mass = density × volume is `mass` (kg).
static inline hs_object_id hs_test_add_mass(hs_world *w, hs_shape *shape, double mass, hs_vec3 pos, hs_vec3 vel) {
	assert_non_null(shape);
	hs_status st;
	hs_shape_id sid = hs_world_add_shape(w, shape, &st);
	assert_int_equal(st, HS_OK);
	hs_object_def od = hs_default_object_def();
	od.shape = sid;
	od.position = pos;
	od.velocity = vel;
	od.density = mass / shape->volume;
	hs_shape_destroy(shape);
	hs_object_id id = hs_world_add_object(w, &od, &st);
	assert_int_equal(st, HS_OK);
	return id;
}

#endif
