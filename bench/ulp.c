// ulp.c — `make ulp`: accuracy and cost of the own elementary functions (hs_sin ...).
// For each function: at least 10^7 arguments (random over the useful domains plus hard cases),
// worst and mean error in ulps against long double libm (64-bit significand, its own error
// ~2^-11 double ulp), the same for glibc's double libm and, where GSL has the function, GSL;
// then ns per call for hs_* and libm over the same arguments. Usage: ulp [arguments per function]
// `ulp --hash` prints a hash of the bits of ~1.9·10^6 results instead, the same on every machine
// (`make ulp-cross` compares it across i686 and aarch64 builds, made with -DHS_ULP_NO_GSL).
#ifndef HS_ULP_NO_GSL
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_exp.h>
#include <gsl/gsl_sf_log.h>
#include <gsl/gsl_sf_trig.h>
#endif
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hs_math.h"

typedef struct gen_ctx {
	uint64_t s;
} gen_ctx;

static uint64_t next_u64(gen_ctx *g) { // splitmix64
	uint64_t z = (g->s += 0x9e3779b97f4a7c15ULL);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}
static double uni(gen_ctx *g, double a, double b) { // uniform in [a, b)
	return a + (b - a) * ((double)(next_u64(g) >> 11) * 0x1p-53);
}
static double sgn(gen_ctx *g) { return (next_u64(g) & 1) ? -1.0 : 1.0; }
static double logu(gen_ctx *g, double e0, double e1) { // |x| log-uniform in [2^e0, 2^e1)
	return ldexp(uni(g, 1.0, 2.0), (int)floor(uni(g, e0, e1)));
}

// error of v in ulps of the double nearest ref
static double ulp_err(double v, long double ref) {
	if (isnan(ref) || isnan(v))
		return isnan(ref) && isnan(v) ? 0.0 : INFINITY;
	if (isinf((double)ref) || isinf(v)) // ref beyond DBL_MAX: only the same infinity is right
		return (double)ref == v ? 0.0 : INFINITY;
	int e;
	frexpl(ref, &e);
	if (ref == 0)
		e = -1073;
	long double ulp = ldexpl(1.0L, (e - 53 < -1074) ? -1074 : e - 53);
	return (double)(fabsl((long double)v - ref) / ulp);
}

// ---- argument generators, one per domain ----
typedef void (*gen_fn)(gen_ctx *g, double *x, double *y);
typedef struct domain {
	const char *desc;
	gen_fn gen;
} domain;

#define PIO2 1.57079632679489661923
static void g_pio4(gen_ctx *g, double *x, double *y) { *x = uni(g, -PIO2 / 2, PIO2 / 2), *y = 0; }
static void g_model(gen_ctx *g, double *x, double *y) { *x = uni(g, -100, 100), *y = 0; }
static void g_1e5(gen_ctx *g, double *x, double *y) { *x = uni(g, -1e5, 1e5), *y = 0; }
static void g_wide(gen_ctx *g, double *x, double *y) { *x = sgn(g) * logu(g, -40, 30), *y = 0; }
static void g_huge(gen_ctx *g, double *x, double *y) { *x = sgn(g) * logu(g, 30, 1024), *y = 0; }
static void g_near_kpio2(gen_ctx *g, double *x, double *y) { // within 32 ulps of k pi/2
	double v = floor(uni(g, 1, 1e6)) * PIO2, dir = (next_u64(g) & 1) ? INFINITY : 0;
	for (int i = (int)(next_u64(g) % 32); i > 0; i--)
		v = nextafter(v, dir);
	*x = v, *y = 0;
}
static double any_double(gen_ctx *g) { // uniform over the bit patterns, NaNs skipped
	double v;
	do {
		uint64_t b = next_u64(g);
		memcpy(&v, &b, sizeof v);
	} while (isnan(v));
	return v;
}
static void g_any(gen_ctx *g, double *x, double *y) { *x = any_double(g), *y = 0; }
static void g_atan2_any(gen_ctx *g, double *y, double *x) { *y = any_double(g), *x = any_double(g); }
static void g_unit(gen_ctx *g, double *x, double *y) { *x = uni(g, -1, 1), *y = 0; }
static void g_near1(gen_ctx *g, double *x, double *y) { *x = sgn(g) * (1 - logu(g, -53, -1)), *y = 0; }
static void g_half(gen_ctx *g, double *x, double *y) { *x = sgn(g) * uni(g, 0.45, 0.55), *y = 0; }
static void g_small(gen_ctx *g, double *x, double *y) { *x = sgn(g) * logu(g, -60, -1), *y = 0; }
static void g_atan_wide(gen_ctx *g, double *x, double *y) { *x = sgn(g) * logu(g, -40, 60), *y = 0; }
static void g_two(gen_ctx *g, double *x, double *y) { *x = uni(g, -2, 2), *y = 0; }
static void g_atan2(gen_ctx *g, double *y, double *x) { *y = sgn(g) * logu(g, -30, 30), *x = sgn(g) * logu(g, -30, 30); }
static void g_atan2_unit(gen_ctx *g, double *y, double *x) { *y = uni(g, -1, 1), *x = uni(g, -1, 1); }
static void g_atan2_far(gen_ctx *g, double *y, double *x) { *y = sgn(g) * logu(g, -1000, 1000), *x = sgn(g) * logu(g, -1000, 1000); }
static void g_exp_all(gen_ctx *g, double *x, double *y) { *x = uni(g, -745, 709.78), *y = 0; }
static void g_exp_sub(gen_ctx *g, double *x, double *y) { *x = uni(g, -745.1, -708), *y = 0; }
static void g_exp_mid(gen_ctx *g, double *x, double *y) { *x = uni(g, -10, 10), *y = 0; }
static void g_exp_small(gen_ctx *g, double *x, double *y) { *x = sgn(g) * logu(g, -60, 3), *y = 0; }
static void g_pos_all(gen_ctx *g, double *x, double *y) { // any positive double, subnormals too
	*x = ldexp(uni(g, 0.5, 1.0), (int)floor(uni(g, -1074, 1025))), *y = 0;
	if (*x == 0)
		*x = 0x1p-1074;
}
static void g_log_mid(gen_ctx *g, double *x, double *y) { *x = uni(g, 0.5, 2.0), *y = 0; }
static void g_log_near1(gen_ctx *g, double *x, double *y) { *x = 1 + sgn(g) * logu(g, -52, -5), *y = 0; }
static void g_pow(gen_ctx *g, double *x, double *y) { *x = logu(g, -20, 20), *y = uni(g, -50, 50); }
static void g_pow_big(gen_ctx *g, double *x, double *y) { // results spread over the whole range
	*x = logu(g, -60, 60);
	if (*x == 1)
		*x = 2;
	*y = uni(g, -744, 709) / log(*x);
}
static void g_pow_near1(gen_ctx *g, double *x, double *y) { *x = 1 + sgn(g) * logu(g, -52, -10), *y = sgn(g) * logu(g, 0, 50); }
static void g_pow_neg(gen_ctx *g, double *x, double *y) { *x = -logu(g, -10, 10), *y = floor(uni(g, -60, 60)); }
static void g_cbrt_all(gen_ctx *g, double *x, double *y) {
	g_pos_all(g, x, y);
	*x *= sgn(g);
}
static void g_cbrt_mid(gen_ctx *g, double *x, double *y) { *x = uni(g, -10, 10), *y = 0; }

// ---- the functions ----
static long double r_sin(long double x) { return sinl(x); }
static long double r_cos(long double x) { return cosl(x); }
static long double r_tan(long double x) { return tanl(x); }
static long double r_asin(long double x) { return asinl(x); }
static long double r_acos(long double x) { return acosl(x); }
static long double r_atan(long double x) { return atanl(x); }
static long double r_exp(long double x) { return expl(x); }
static long double r_log(long double x) { return logl(x); }
static long double r_cbrt(long double x) { return cbrtl(x); }
static long double r_atan2(long double y, long double x) { return atan2l(y, x); }
static long double r_pow(long double x, long double y) { return powl(x, y); }
static double l_sin(double x) { return sin(x); }
static double l_cos(double x) { return cos(x); }
static double l_tan(double x) { return tan(x); }
static double l_asin(double x) { return asin(x); }
static double l_acos(double x) { return acos(x); }
static double l_atan(double x) { return atan(x); }
static double l_exp(double x) { return exp(x); }
static double l_log(double x) { return log(x); }
static double l_cbrt(double x) { return cbrt(x); }
static double l_atan2(double y, double x) { return atan2(y, x); }
static double l_pow(double x, double y) { return pow(x, y); }
#ifndef HS_ULP_NO_GSL
static double gs_sin(double x) { return gsl_sf_sin(x); }
static double gs_cos(double x) { return gsl_sf_cos(x); }
static double gs_exp(double x) { return x < 709.78 ? gsl_sf_exp(x) : INFINITY; }
static double gs_log(double x) { return gsl_sf_log(x); }
#else
#define gs_sin 0
#define gs_cos 0
#define gs_exp 0
#define gs_log 0
#endif

#define MAX_DOM 7
typedef struct func {
	const char *name;
	double (*hs1)(double), (*lm1)(double), (*gs1)(double);
	long double (*ref1)(long double);
	double (*hs2)(double, double), (*lm2)(double, double);
	long double (*ref2)(long double, long double);
	int tdom; // the domain whose arguments time the function
	domain dom[MAX_DOM];
} func;

static const func funcs[] = {
	{"sin", hs_sin, l_sin, gs_sin, r_sin, 0, 0, 0, 1,
	 {{"|x|<pi/4", g_pio4}, {"|x|<100", g_model}, {"|x|<1e5", g_1e5}, {"2^-40..2^30", g_wide},
	  {"2^30..2^1024", g_huge}, {"near k pi/2", g_near_kpio2}, {"any double", g_any}}},
	{"cos", hs_cos, l_cos, gs_cos, r_cos, 0, 0, 0, 1,
	 {{"|x|<pi/4", g_pio4}, {"|x|<100", g_model}, {"|x|<1e5", g_1e5}, {"2^-40..2^30", g_wide},
	  {"2^30..2^1024", g_huge}, {"near k pi/2", g_near_kpio2}, {"any double", g_any}}},
	{"tan", hs_tan, l_tan, 0, r_tan, 0, 0, 0, 1,
	 {{"|x|<pi/4", g_pio4}, {"|x|<100", g_model}, {"|x|<1e5", g_1e5}, {"2^-40..2^30", g_wide},
	  {"2^30..2^1024", g_huge}, {"near k pi/2", g_near_kpio2}, {"any double", g_any}}},
	{"asin", hs_asin, l_asin, 0, r_asin, 0, 0, 0, 0,
	 {{"|x|<1", g_unit}, {"near ±1", g_near1}, {"near ±1/2", g_half}, {"2^-60..1/2", g_small}}},
	{"acos", hs_acos, l_acos, 0, r_acos, 0, 0, 0, 0,
	 {{"|x|<1", g_unit}, {"near ±1", g_near1}, {"near ±1/2", g_half}, {"2^-60..1/2", g_small}}},
	{"atan", hs_atan, l_atan, 0, r_atan, 0, 0, 0, 0,
	 {{"|x|<2", g_two}, {"2^-40..2^60", g_atan_wide}, {"2^-60..1/2", g_small}, {"any double", g_any}}},
	{"atan2", 0, 0, 0, 0, hs_atan2, l_atan2, r_atan2, 0,
	 {{"|y|,|x|<1", g_atan2_unit}, {"2^-30..2^30", g_atan2}, {"2^-1000..2^1000", g_atan2_far}, {"any doubles", g_atan2_any}}},
	{"exp", hs_exp, l_exp, gs_exp, r_exp, 0, 0, 0, 3,
	 {{"-745..709.78", g_exp_all}, {"subnormal results", g_exp_sub}, {"2^-60..8", g_exp_small}, {"|x|<10", g_exp_mid}}},
	{"log", hs_log, l_log, gs_log, r_log, 0, 0, 0, 0,
	 {{"all x>0", g_pos_all}, {"0.5..2", g_log_mid}, {"1±2^-52..2^-5", g_log_near1}}},
	{"pow", 0, 0, 0, 0, hs_pow, l_pow, r_pow, 0,
	 {{"x 2^±20, |y|<50", g_pow}, {"results 2^±1074", g_pow_big}, {"x near 1", g_pow_near1},
	  {"x<0, y integer", g_pow_neg}}},
	{"cbrt", hs_cbrt, l_cbrt, 0, r_cbrt, 0, 0, 0, 1, {{"all x", g_cbrt_all}, {"|x|<10", g_cbrt_mid}}},
};
#define NFUNCS (sizeof funcs / sizeof funcs[0])

typedef struct stats {
	double max, sum, worst_x, worst_y, lm_max, gs_max;
	long n;
} stats;

static void measure_one(const func *f, double x, double y, stats *st) {
	double v, e, lv;
	if (f->hs1) {
		long double r = f->ref1(x);
		v = f->hs1(x), lv = f->lm1(x);
		e = ulp_err(v, r);
		st->lm_max = fmax(st->lm_max, ulp_err(lv, r));
		if (f->gs1)
			st->gs_max = fmax(st->gs_max, ulp_err(f->gs1(x), r));
	} else {
		long double r = f->ref2(x, y);
		v = f->hs2(x, y), lv = f->lm2(x, y);
		e = ulp_err(v, r);
		st->lm_max = fmax(st->lm_max, ulp_err(lv, r));
	}
	if (e > st->max)
		st->max = e, st->worst_x = x, st->worst_y = y;
	st->sum += e;
	st->n++;
}

static double now_ns(void) {
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

#define TN 4096
volatile double sink;
// ns per call over the arguments of the function's timing domain: the best of 15 runs, hs_* and
// libm alternating so that both see the same load on the machine
static void cost(const func *f, double *ns_hs, double *ns_lm) {
	static double xs[TN], ys[TN];
	gen_ctx g = {12345};
	for (int i = 0; i < TN; i++)
		f->dom[f->tdom].gen(&g, &xs[i], &ys[i]);
	double best[2] = {INFINITY, INFINITY};
	for (int rep = 0; rep < 30; rep++) {
		int which = rep & 1;
		double acc = 0, t0 = now_ns();
		for (int k = 0; k < 50; k++)
			for (int i = 0; i < TN; i++)
				acc += f->hs1 ? (which ? f->lm1 : f->hs1)(xs[i]) : (which ? f->lm2 : f->hs2)(xs[i], ys[i]);
		best[which] = fmin(best[which], (now_ns() - t0) / (50.0 * TN));
		sink = acc;
	}
	*ns_hs = best[0], *ns_lm = best[1];
}

static uint64_t fnv(uint64_t h, double v) {
	uint64_t b;
	memcpy(&b, &v, sizeof b);
	return (h ^ b) * 1099511628211ULL;
}
// FNV-1a over the bits of every function at fixed arguments: the model's range (as in
// tests/test_detmath.c), then arguments uniform over all bit patterns (huge, tiny, subnormal)
static uint64_t detmath_hash(void) {
	uint64_t h = 1469598103934665603ULL;
	for (int i = 0; i < 30000; i++) {
		double x = (i - 15000) * 0.00731, p = 0.5 + i * 1e-4;
		double v[11] = {hs_sin(x), hs_cos(x), hs_tan(x), hs_asin(x / 110), hs_acos(x / 110), hs_atan(x), hs_atan2(x, p),
		                hs_exp(x), hs_log(p), hs_pow(p, x), hs_cbrt(x)};
		for (int k = 0; k < 11; k++)
			h = fnv(h, v[k]);
	}
	gen_ctx g = {1};
	for (int i = 0; i < 200000; i++) {
		double x = any_double(&g), y = any_double(&g);
		double v[8] = {hs_sin(x), hs_cos(x), hs_tan(x), hs_atan2(y, x), hs_log(fabs(x)), hs_cbrt(x), hs_exp(x * 1e-300),
		               hs_pow(fabs(x), fmod(y, 64.0))};
		for (int k = 0; k < 8; k++)
			h = fnv(h, v[k]);
	}
	return h;
}

int main(int argc, char **argv) {
	if (argc > 1 && strcmp(argv[1], "--hash") == 0) {
		printf("%016llx\n", (unsigned long long)detmath_hash());
		return 0;
	}
	long per_func = argc > 1 ? atol(argv[1]) : 10000000L;
#ifndef HS_ULP_NO_GSL
	gsl_set_error_handler_off();
#endif
	printf("ulp errors against long double libm; %ld arguments per function\n\n", per_func);
	printf("%-6s %-20s %9s %9s %9s  %-36s %9s %9s\n", "func", "domain", "n", "max ulp", "mean ulp",
	       "worst at", "libm max", "GSL max");
	for (size_t fi = 0; fi < NFUNCS; fi++) {
		const func *f = &funcs[fi];
		int nd = 0;
		while (nd < MAX_DOM && f->dom[nd].gen)
			nd++;
		stats all = {0};
		for (int d = 0; d < nd; d++) {
			stats st = {0};
			gen_ctx g = {(uint64_t)(0x1234567 + 977 * (int)fi + d)};
			for (long i = 0; i < per_func / nd + 1; i++) {
				double x, y;
				f->dom[d].gen(&g, &x, &y);
				measure_one(f, x, y, &st);
			}
			char at[64];
			if (f->hs1)
				snprintf(at, sizeof at, "%a", st.worst_x);
			else
				snprintf(at, sizeof at, "%a,%a", st.worst_x, st.worst_y);
			printf("%-6s %-20s %9ld %9.4f %9.4f  %-36s %9.4f ", f->name, f->dom[d].desc, st.n, st.max,
			       st.sum / (double)st.n, at, st.lm_max);
			if (f->gs1)
				printf("%9.4f\n", st.gs_max);
			else
				printf("%9s\n", "-");
			if (st.max > all.max)
				all.max = st.max;
			all.sum += st.sum, all.n += st.n;
		}
		printf("%-6s %-20s %9ld %9.4f %9.4f\n\n", f->name, "ALL", all.n, all.max, all.sum / (double)all.n);
		fflush(stdout);
	}
	printf("%-6s %10s %10s %7s\n", "func", "hs ns", "libm ns", "ratio");
	for (size_t fi = 0; fi < NFUNCS; fi++) {
		double a = 0, b = 0;
		cost(&funcs[fi], &a, &b);
		printf("%-6s %10.2f %10.2f %7.2f\n", funcs[fi].name, a, b, a / b);
	}
	return 0;
}
