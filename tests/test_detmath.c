// test_detmath.c — the own elementary functions (detmath.c, detmath_exp.c): special values, known values, ulp
// errors against long double libm (a reference only: tests are not the state), identities, and
// golden bits so that any change in the last bit is seen.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "test_util.h"

static uint64_t bits(double x) {
	uint64_t u;
	memcpy(&u, &x, sizeof u);
	return u;
}
// same bits (so -0 differs from +0), or both NaN
static int same(double a, double b) { return (isnan(a) && isnan(b)) || bits(a) == bits(b); }
#define assert_same(a, b)                                                                               \
	do {                                                                                                \
		double sa_ = (a), sb_ = (b);                                                                     \
		if (!same(sa_, sb_)) {                                                                          \
			print_error("%s = %a, expected %a\n", #a, sa_, sb_);                                        \
			fail();                                                                                     \
		}                                                                                               \
	} while (0)

// error of v in ulps of the double nearest ref
static double ulp_err(double v, long double ref) {
	if (isnan(ref) || isnan(v) || isinf(v) || isinf((double)ref))
		return same(v, (double)ref) ? 0.0 : INFINITY;
	int e;
	frexpl(ref, &e);
	if (ref == 0)
		e = -1073;
	return (double)(fabsl((long double)v - ref) / ldexpl(1.0L, e - 53 < -1074 ? -1074 : e - 53));
}
#define assert_ulp(v, ref, bound)                                                                       \
	do {                                                                                                \
		double ue_ = ulp_err((v), (ref));                                                                \
		if (!(ue_ <= (bound))) {                                                                        \
			print_error("%s: %.3f ulp > %.3f\n", #v, ue_, (double)(bound));                               \
			fail();                                                                                     \
		}                                                                                               \
	} while (0)

static void test_special_values(void **state) {
	(void)state;
	double nan = NAN, inf = INFINITY;
	double (*f1[])(double) = {hs_sin, hs_cos, hs_tan, hs_asin, hs_acos, hs_atan, hs_exp, hs_log, hs_cbrt};
	for (size_t i = 0; i < sizeof f1 / sizeof f1[0]; i++)
		assert_true(isnan(f1[i](nan)));
	assert_true(isnan(hs_atan2(nan, 1)) && isnan(hs_atan2(1, nan)) && isnan(hs_pow(nan, 2)) && isnan(hs_pow(2, nan)));
	assert_true(isnan(hs_sin(inf)) && isnan(hs_cos(-inf)) && isnan(hs_tan(inf)));
	assert_same(hs_sin(-0.0), -0.0); assert_same(hs_tan(-0.0), -0.0); assert_same(hs_cos(-0.0), 1.0);
	assert_same(hs_asin(-0.0), -0.0); assert_same(hs_atan(-0.0), -0.0); assert_same(hs_cbrt(-0.0), -0.0);
	assert_true(isnan(hs_asin(1.0000000000000002)) && isnan(hs_acos(-1.0000000000000002)) && isnan(hs_asin(inf)));
	assert_same(hs_asin(1), 0x1.921fb54442d18p+0); assert_same(hs_acos(1), 0.0); assert_same(hs_acos(-1), 0x1.921fb54442d18p+1);
	assert_same(hs_atan(inf), 0x1.921fb54442d18p+0); assert_same(hs_atan(-inf), -0x1.921fb54442d18p+0);
	assert_same(hs_exp(0), 1.0); assert_same(hs_exp(-0.0), 1.0); assert_same(hs_exp(inf), inf); assert_same(hs_exp(-inf), 0.0);
	assert_same(hs_exp(710), inf); assert_same(hs_exp(-746), 0.0); assert_same(hs_exp(-745.1), 0x1p-1074);
	assert_same(hs_exp(-740), (double)expl(-740.0L)); // subnormal result
	assert_same(hs_log(1), 0.0); assert_same(hs_log(0.0), -inf); assert_same(hs_log(-0.0), -inf); assert_same(hs_log(inf), inf);
	assert_true(isnan(hs_log(-1)) && isnan(hs_log(-inf)));
	assert_same(hs_log(0x1p-1074), (double)logl(0x1p-1074L));
	assert_same(hs_cbrt(inf), inf); assert_same(hs_cbrt(-inf), -inf); assert_same(hs_cbrt(-27), -3.0);
	assert_same(hs_cbrt(0x1p-1074), (double)cbrtl(0x1p-1074L));
}

static void test_atan2_quadrants(void **state) {
	(void)state;
	double pi = 0x1.921fb54442d18p+1, pio2 = 0x1.921fb54442d18p+0, inf = INFINITY;
	assert_same(hs_atan2(0.0, 1), 0.0); assert_same(hs_atan2(-0.0, 1), -0.0);
	assert_same(hs_atan2(0.0, -1), pi); assert_same(hs_atan2(-0.0, -1), -pi);
	assert_same(hs_atan2(0.0, 0.0), 0.0); assert_same(hs_atan2(0.0, -0.0), pi); assert_same(hs_atan2(-0.0, -0.0), -pi);
	assert_same(hs_atan2(1, 0.0), pio2); assert_same(hs_atan2(-1, -0.0), -pio2);
	assert_same(hs_atan2(inf, inf), 0x1.921fb54442d18p-1); assert_same(hs_atan2(-inf, -inf), -0x1.2d97c7f3321d2p+1);
	assert_same(hs_atan2(inf, 5), pio2); assert_same(hs_atan2(5, inf), 0.0); assert_same(hs_atan2(-5, -inf), -pi);
	double q[4][2] = {{1, 2}, {1, -2}, {-1, -2}, {-1, 2}};
	for (int i = 0; i < 4; i++)
		assert_ulp(hs_atan2(q[i][0], q[i][1]), atan2l(q[i][0], q[i][1]), 0.5);
	assert_ulp(hs_atan2(1e-300, 1e300), atan2l(1e-300L, 1e300L), 0.5); // subnormal quotient
	assert_ulp(hs_atan2(3e300, -1e-300), atan2l(3e300L, -1e-300L), 0.5);
}

static void test_pow_special(void **state) {
	(void)state;
	double inf = INFINITY, nan = NAN;
	assert_same(hs_pow(nan, 0.0), 1.0); assert_same(hs_pow(1.0, nan), 1.0); assert_same(hs_pow(-1, inf), 1.0);
	assert_same(hs_pow(0.5, inf), 0.0); assert_same(hs_pow(0.5, -inf), inf); assert_same(hs_pow(2, inf), inf);
	assert_same(hs_pow(-0.0, -3), -inf); assert_same(hs_pow(0.0, -3), inf); assert_same(hs_pow(-0.0, -2), inf);
	assert_same(hs_pow(-0.0, 3), -0.0); assert_same(hs_pow(-0.0, 2.5), 0.0); assert_same(hs_pow(0.0, -inf), inf);
	assert_same(hs_pow(-inf, 3), -inf); assert_same(hs_pow(-inf, -3), -0.0); assert_same(hs_pow(-inf, 2), inf);
	assert_same(hs_pow(inf, -1), 0.0); assert_same(hs_pow(inf, 0.5), inf);
	assert_true(isnan(hs_pow(-2, 0.5)));
	assert_same(hs_pow(-2, 3), -8.0); assert_same(hs_pow(-2, 4), 16.0); assert_same(hs_pow(2, 10), 1024.0);
	assert_same(hs_pow(-2, 0x1p60), inf); assert_same(hs_pow(0.5, 0x1p70), 0.0); assert_same(hs_pow(2, -1074), 0x1p-1074);
	assert_same(hs_pow(10, 400), inf); assert_same(hs_pow(10, -400), 0.0); assert_same(hs_pow(9, 0.5), 3.0);
}

static void test_known_values(void **state) {
	(void)state;
	assert_ulp(hs_sin(HS_PI / 6), 0.5L, 1); assert_ulp(hs_cos(HS_PI / 3), 0.5L, 1);
	assert_ulp(hs_tan(HS_PI / 4), 1.0L, 1); assert_ulp(hs_atan(1), 0.785398163397448309615660845819875721L, 0.5);
	assert_ulp(hs_exp(1), 2.71828182845904523536028747135266250L, 0.5);
	assert_same(hs_log(2.71828182845904523536), 1.0); assert_same(hs_cbrt(27), 3.0); assert_same(hs_cbrt(-0.125), -0.5);
	assert_ulp(hs_sin(1e22), -0.852200849767188801772705893208L, 0.5); // Payne–Hanek
	assert_ulp(hs_sin(0x1.fffffffffffffp1023), 0.00496195478918406203L, 0.5);
	assert_ulp(hs_cos(0x1.fffffffffffffp1023), -0.99998768942655994L, 0.5);
	assert_ulp(hs_asin(0.5), 0.523598775598298873077107230546583814L, 0.5);
	assert_ulp(hs_acos(-0.5), 2.09439510239319549230842892218633526L, 0.5);
}

typedef struct ufunc {
	const char *name;
	double (*f)(double);
	long double (*ref)(long double);
	double lo, hi; // arguments: uniform in [lo, hi] half the time, else log-uniform magnitude below hi
} ufunc;

static uint64_t rng_state = 42;
static double uniform01(void) {
	rng_state ^= rng_state << 13, rng_state ^= rng_state >> 7, rng_state ^= rng_state << 17;
	return (double)(rng_state >> 11) * 0x1p-53;
}

// worst ulp error over n arguments: half uniform, half spread over many binades
static double worst_ulp(const ufunc *u, int n, double *at) {
	double worst = 0;
	for (int i = 0; i < n; i++) {
		double x = u->lo + (u->hi - u->lo) * uniform01();
		if (i & 1) {
			double m = fmax(fabs(u->lo), fabs(u->hi));
			x = (x < 0 ? -1 : 1) * m * exp2(-60 * uniform01());
			if (u->lo >= 0)
				x = fabs(x);
		}
		double e = ulp_err(u->f(x), u->ref(x));
		if (e > worst)
			worst = e, *at = x;
	}
	return worst;
}

#define N_ARGS 200000
static void test_ulp_one_argument(void **state) {
	(void)state;
	static const ufunc us[] = {
	    {"sin", hs_sin, sinl, -100, 100}, {"sin", hs_sin, sinl, -1e9, 1e9}, {"cos", hs_cos, cosl, -100, 100},
	    {"cos", hs_cos, cosl, -1e300, 1e300}, {"tan", hs_tan, tanl, -100, 100}, {"asin", hs_asin, asinl, -1, 1},
	    {"acos", hs_acos, acosl, -1, 1}, {"atan", hs_atan, atanl, -1e6, 1e6}, {"exp", hs_exp, expl, -745, 709.7},
	    {"log", hs_log, logl, 0, 1e300}, {"log", hs_log, logl, 0.5, 2}, {"cbrt", hs_cbrt, cbrtl, -1e300, 1e300},
	};
	for (size_t i = 0; i < sizeof us / sizeof us[0]; i++) {
		double at = 0, w = worst_ulp(&us[i], N_ARGS / 2, &at);
		if (!(w <= 1.0)) {
			print_error("hs_%s: %.3f ulp at %a\n", us[i].name, w, at);
			fail();
		}
	}
}

static void test_ulp_two_arguments(void **state) {
	(void)state;
	double worst_a = 0, worst_p = 0;
	for (int i = 0; i < N_ARGS; i++) {
		double y = (uniform01() - 0.5) * exp2(60 * uniform01() - 30), x = (uniform01() - 0.5) * exp2(60 * uniform01() - 30);
		worst_a = fmax(worst_a, ulp_err(hs_atan2(y, x), atan2l(y, x)));
		double b = exp2(40 * uniform01() - 20), p = (uniform01() - 0.5) * 1400 / log(b); // results over the range
		worst_p = fmax(worst_p, ulp_err(hs_pow(b, p), powl(b, p)));
	}
	assert_true(worst_a <= 1.0);
	assert_true(worst_p <= 1.0);
	// negative bases with integer powers, and bases near 1 with large powers
	for (int i = 0; i < 20000; i++) {
		double b = -exp2(20 * uniform01() - 10), p = floor(120 * uniform01() - 60);
		assert_ulp(hs_pow(b, p), powl(b, p), 1.0);
		b = 1 + (uniform01() - 0.5) * 0x1p-20, p = (uniform01() - 0.5) * 0x1p30;
		assert_ulp(hs_pow(b, p), powl(b, p), 1.0);
	}
}

// arguments within a few ulps of multiples of pi/2, where the reduction cancels most bits
static void test_hard_reduction(void **state) {
	(void)state;
	for (int k = 1; k < 200000; k += 7) {
		double x = k * 1.57079632679489661923;
		for (int j = 0; j < 3; j++, x = nextafter(x, INFINITY)) {
			assert_ulp(hs_sin(x), sinl(x), 1.0);
			assert_ulp(hs_cos(x), cosl(x), 1.0);
			assert_ulp(hs_tan(x), tanl(x), 1.0);
		}
	}
	// the closest double to a multiple of pi/2 below 2^1024 (Muller's table): 6381956970095103 2^797
	double hard = 0x1.6ac5b262ca1ffp+849;
	assert_ulp(hs_sin(hard), sinl(hard), 1.0); assert_ulp(hs_cos(hard), cosl(hard), 1.0);
}

static void test_identities(void **state) {
	(void)state;
	for (int i = 0; i < 20000; i++) {
		double t = (uniform01() - 0.5) * 200, s = hs_sin(t), c = hs_cos(t);
		assert_near(s * s + c * c, 1.0, 4e-16);
		assert_near(hs_atan2(s, c), remainder(t, 2 * HS_PI), 1e-14);
		double x = exp2(80 * uniform01() - 40);
		assert_near(hs_exp(hs_log(x)) / x, 1.0, 3e-14);
		assert_near(hs_pow(x, 1.0 / 3) / hs_cbrt(x), 1.0, 1e-15);
		double a = uniform01() * 2 - 1;
		assert_near(hs_asin(a) + hs_acos(a), HS_PI / 2, 4.5e-16);
	}
}

// Last bits at fixed arguments: a change in any of these is a change in every world's state.
static void test_golden_bits(void **state) {
	(void)state;
	assert_same(hs_sin(0.5), 0x1.eaee8744b05fp-2); assert_same(hs_sin(100), -0x1.03425b78c4db8p-1);
	assert_same(hs_sin(1e22), -0x1.b453ab76bf397p-1); assert_same(hs_cos(2), -0x1.aa22657537205p-2);
	assert_same(hs_cos(100), 0x1.b981dbf665fdfp-1); assert_same(hs_tan(1), 0x1.8eb245cbee3a6p+0);
	assert_same(hs_tan(3), -0x1.23ef71254b86fp-3); assert_same(hs_atan(2), 0x1.1b6e192ebbe44p+0);
	assert_same(hs_asin(-0.3), -0x1.380159e14f6ffp-2); assert_same(hs_acos(0.99), 0x1.21df72882bfd8p-3);
	assert_same(hs_exp(10), 0x1.5829dcf95056p+14); assert_same(hs_exp(100), 0x1.3494a9b171bf5p+144);
	assert_same(hs_log(3), 0x1.193ea7aad030bp+0); assert_same(hs_cbrt(100), 0x1.290fca9c761f8p+2);
	assert_same(hs_pow(0.7, 55.5), 0x1.5b93b7d78ff7fp-29); assert_same(hs_pow(1.5, 1.0 / 3), 0x1.250bfe1b082f5p+0);
	assert_same(hs_atan2(-0.5, -3), -0x1.7cfc1dc00636ap+1); assert_same(hs_atan2(3, -0.25), 0x1.a76873ac2bc7cp+0);
	// and a hash of the bits over 3 x 10^4 arguments per function
	uint64_t h = 1469598103934665603ULL;
	for (int i = 0; i < 30000; i++) {
		double x = (i - 15000) * 0.00731, p = 0.5 + i * 1e-4;
		double v[11] = {hs_sin(x), hs_cos(x), hs_tan(x), hs_asin(x / 110), hs_acos(x / 110), hs_atan(x), hs_atan2(x, p),
		                hs_exp(x), hs_log(p), hs_pow(p, x), hs_cbrt(x)};
		for (int k = 0; k < 11; k++)
			h = (h ^ bits(v[k])) * 1099511628211ULL;
	}
	if (h != 0x1c72f79db3b4c9cfULL) {
		print_error("detmath bits hash %016llx changed\n", (unsigned long long)h);
		fail();
	}
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_special_values), cmocka_unit_test(test_atan2_quadrants),
	    cmocka_unit_test(test_pow_special),    cmocka_unit_test(test_known_values),
	    cmocka_unit_test(test_ulp_one_argument), cmocka_unit_test(test_ulp_two_arguments),
	    cmocka_unit_test(test_hard_reduction), cmocka_unit_test(test_identities),
	    cmocka_unit_test(test_golden_bits),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
