// test_util.h — shared helpers for the cmocka tests (included after cmocka.h).
#ifndef HS_TEST_UTIL_H
#define HS_TEST_UTIL_H

#include <math.h>
#include <stdio.h>

#include "handspring.h"

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

#endif
