// test_math.c — vec3/quat algebra against hand-computed values.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "test_util.h"

static void test_vector_algebra(void **state) {
	(void)state;
	hs_vec3 a = hs_v3(1, 2, 3), b = hs_v3(-4, 5, 0.5);
	assert_near(hs_dot(a, b), -4 + 10 + 1.5, 0);
	assert_vec3_near(hs_cross(a, b), hs_v3(2 * 0.5 - 3 * 5, 3 * -4 - 1 * 0.5, 1 * 5 - 2 * -4), 0);
	assert_vec3_near(hs_cross(hs_v3(1, 0, 0), hs_v3(0, 1, 0)), hs_v3(0, 0, 1), 0); // right-handed
	assert_near(hs_length(hs_v3(3, 4, 12)), 13, 0);
	assert_vec3_near(hs_normalize(hs_v3(0, 0, -7)), hs_v3(0, 0, -1), 0);
	assert_vec3_near(hs_normalize(hs_v3(0, 0, 0)), hs_v3(0, 0, 0), 0);
	assert_vec3_near(hs_lerp(a, b, 0.25), hs_v3(1 - 1.25, 2 + 0.75, 3 - 0.625), 1e-15);
	assert_vec3_near(hs_mul_add(a, 2, b), hs_v3(-7, 12, 4), 0);
}

static void test_quaternion_rotation(void **state) {
	(void)state;
	// 90 degrees about z takes x to y and y to -x
	hs_quat qz = hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 2);
	assert_vec3_near(hs_quat_rotate(qz, hs_v3(1, 0, 0)), hs_v3(0, 1, 0), 1e-15);
	assert_vec3_near(hs_quat_rotate(qz, hs_v3(0, 1, 0)), hs_v3(-1, 0, 0), 1e-15);
	assert_vec3_near(hs_quat_inv_rotate(qz, hs_v3(0, 1, 0)), hs_v3(1, 0, 0), 1e-15);
	// a * b applies b first: 90 about x then 90 about z sends y → z → z
	hs_quat qx = hs_quat_from_axis_angle(hs_v3(1, 0, 0), HS_PI / 2);
	assert_vec3_near(hs_quat_rotate(hs_quat_mul(qz, qx), hs_v3(0, 1, 0)), hs_v3(0, 0, 1), 1e-15);
	assert_vec3_near(hs_quat_rotate(hs_quat_mul(qx, qz), hs_v3(1, 0, 0)), hs_v3(0, 0, 1), 1e-15);
	assert_near(hs_quat_angle(hs_quat_mul(qz, qz)), HS_PI, 1e-15);
	assert_near(hs_quat_angle(hs_quat_identity()), 0, 0);
	// rpy: pitch 90 sends x to -z (right-handed about y)
	assert_vec3_near(hs_quat_rotate(hs_quat_from_rpy(0, HS_PI / 2, 0), hs_v3(1, 0, 0)), hs_v3(0, 0, -1), 1e-15);
	assert_vec3_near(hs_quat_rotate(hs_quat_from_rpy(0, 0, HS_PI / 2), hs_v3(1, 0, 0)), hs_v3(0, 1, 0), 1e-15);
}

static void test_slerp(void **state) {
	(void)state;
	hs_quat a = hs_quat_identity(), b = hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 2);
	hs_quat m = hs_quat_slerp(a, b, 0.5);
	assert_near(hs_quat_angle(m), HS_PI / 4, 1e-15);
	assert_vec3_near(hs_quat_rotate(m, hs_v3(1, 0, 0)), hs_v3(sqrt(0.5), sqrt(0.5), 0), 1e-15);
	// the shorter arc: -b is the same rotation
	hs_quat nb = hs_q(-b.w, -b.x, -b.y, -b.z);
	assert_near(hs_quat_angle(hs_quat_slerp(a, nb, 0.5)), HS_PI / 4, 1e-15);
	assert_near(hs_quat_dot(hs_quat_slerp(a, b, 0), a), 1, 1e-15);
	assert_near(fabs(hs_quat_dot(hs_quat_slerp(a, b, 1), b)), 1, 1e-15);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_vector_algebra),
	    cmocka_unit_test(test_quaternion_rotation),
	    cmocka_unit_test(test_slerp),
	};
	return cmocka_run_group_tests_name("math", tests, NULL, NULL);
}
