// test_hgrid.c — the hierarchical grid of the broad phases (hgrid.c): a query finds every object
// whose bounds meet its box, in index order, whatever the mix of sizes; one huge object does not
// put the small ones in one cell; many objects in one place are all found.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdlib.h>

#include "hgrid.h"
#include "test_util.h"

#define N 600

static double unit(uint64_t *s) { // a fixed LCG in [0, 1)
	*s = *s * 6364136223846793005ull + 1442695040888963407ull;
	return (double)(*s >> 11) / (double)(1ull << 53);
}

static bool meets(hs_vec3 c, double h, hs_vec3 lo, hs_vec3 hi, int dims) {
	double x[3] = {c.x, c.y, c.z}, a[3] = {lo.x, lo.y, lo.z}, b[3] = {hi.x, hi.y, hi.z};
	for (int d = 0; d < dims; ++d)
		if (x[d] + h < a[d] || x[d] - h > b[d])
			return false;
	return true;
}

static int packed_levels(const hs_hgrid *g) {
	int packed = 0;
	for (int l = 0; l < g->levels; ++l)
		packed += g->win_n[l][0] > 0;
	return packed;
}

static int hashed_objects(const hs_hgrid *g) {
	int hashed = 0;
	for (int l = 0; l < g->levels; ++l)
		hashed += g->outside[l];
	return hashed;
}

// A point in the 40 m square (z in [0, 4]), or one of a square five times wider.
static hs_vec3 somewhere(uint64_t *s, bool far) {
	double w = far ? 200.0 : 40.0;
	return hs_v3(w * unit(s) - 0.5 * w, w * unit(s) - 0.5 * w, 4.0 * unit(s));
}

// Random objects of sizes over five decades (and a 400 m one): every query's result is ascending,
// holds each object whose bounds meet the box, and holds each object once. Packed: the levels are
// laid out densely after the first filing (the smallest do not fit the pool and stay hashed), some
// moves go far outside their windows (hashed), and the grid is packed again now and then.
static void check_against_scan(int dims, bool pack) {
	hs_hgrid g;
	assert_true(hs_hgrid_alloc(&g, N, dims));
	hs_vec3 c[N];
	int out[N];
	uint64_t s = 7;
	for (int i = 0; i < N; ++i) {
		g.half[i] = i == 17 ? 200.0 : 0.001 * pow(10.0, 4.0 * unit(&s));
		c[i] = somewhere(&s, false);
	}
	hs_hgrid_build(&g, N);
	assert_true(g.levels > 10);
	for (int i = 0; i < N; ++i)
		hs_hgrid_file(&g, i, c[i]);
	if (pack) {
		hs_hgrid_pack(&g);
		assert_true(packed_levels(&g) > 0 && packed_levels(&g) < g.levels); // some fit, some not
	}
	int hashed_seen = 0;
	for (int q = 0; q < 300; ++q) {
		if (q % 3 == 0) { // move some: filing again must follow
			int i = (int)(N * unit(&s));
			c[i] = somewhere(&s, pack && q % 6 == 0);
			hs_hgrid_file(&g, i, c[i]);
		}
		if (pack && q % 50 == 49)
			hs_hgrid_pack(&g);
		hashed_seen = hashed_objects(&g) > hashed_seen ? hashed_objects(&g) : hashed_seen;
		hs_vec3 lo = somewhere(&s, pack && q % 7 == 0);
		hs_vec3 hi = hs_add(lo, hs_scale(hs_v3(unit(&s), unit(&s), unit(&s)), q % 10 == 0 ? 30.0 : 0.5));
		int n = hs_hgrid_query(&g, lo, hi, out);
		for (int k = 1; k < n; ++k)
			assert_true(out[k - 1] < out[k]);
		int k = 0;
		for (int i = 0; i < N; ++i) {
			while (k < n && out[k] < i)
				++k;
			if (meets(c[i], g.half[i], lo, hi, dims))
				assert_true(k < n && out[k] == i);
		}
	}
	assert_true(hashed_seen > 0);
	hs_hgrid_free(&g);
}

static void test_query_finds_all_2d(void **state) {
	(void)state;
	check_against_scan(2, false);
	check_against_scan(2, true);
}

static void test_query_finds_all_3d(void **state) {
	(void)state;
	check_against_scan(3, false);
	check_against_scan(3, true);
}

// 900 cubes of 5 cm on a 30 × 30 grid, packed into one window: every query answers exactly as the
// same grid never packed (the same cells' objects), while some cubes leave the window (hashed),
// come back, and the grid is packed again.
static void test_packed_answers_as_hashed(void **state) {
	(void)state;
	enum { CUBES = 900 };
	hs_hgrid packed, hashed;
	assert_true(hs_hgrid_alloc(&packed, CUBES, 2) && hs_hgrid_alloc(&hashed, CUBES, 2));
	hs_vec3 c[CUBES];
	int a[CUBES], b[CUBES];
	for (int i = 0; i < CUBES; ++i) {
		packed.half[i] = hashed.half[i] = 0.025;
		c[i] = hs_v3(0.07 * (i % 30), 0.07 * (i / 30), 0.0);
	}
	hs_hgrid_build(&packed, CUBES);
	hs_hgrid_build(&hashed, CUBES);
	for (int i = 0; i < CUBES; ++i) {
		hs_hgrid_file(&packed, i, c[i]);
		hs_hgrid_file(&hashed, i, c[i]);
	}
	hs_hgrid_pack(&packed);
	assert_int_equal(packed_levels(&packed), 1);
	assert_int_equal(hashed_objects(&packed), 0);
	assert_int_equal(hashed_objects(&hashed), CUBES); // never packed: all in the hash
	hs_hgrid_file(&packed, 0, hs_v3(-0.9, 0.0, 0.0)); // out of the window: hashed
	assert_int_equal(hashed_objects(&packed), 1);
	hs_hgrid_file(&packed, 0, c[0]); // back: in its cell of the window
	assert_int_equal(hashed_objects(&packed), 0);
	uint64_t s = 11;
	for (int q = 0; q < 600; ++q) {
		int i = (int)(CUBES * unit(&s));
		if (q % 4 == 0) // a cube wanders: out of the window and beyond (q % 8), or back into it
			c[i] = q % 8 == 0 ? hs_v3(4.0 * unit(&s) - 1.0, 4.0 * unit(&s) - 1.0, 0.0)
			                  : hs_v3(2.1 * unit(&s), 2.1 * unit(&s), 0.0);
		hs_hgrid_file(&packed, i, c[i]);
		hs_hgrid_file(&hashed, i, c[i]);
		if (q == 300) {
			assert_true(hashed_objects(&packed) > 0);
			hs_hgrid_pack(&packed);
			assert_int_equal(hashed_objects(&packed), 0);
		}
		hs_vec3 lo = hs_v3(4.0 * unit(&s) - 1.0, 4.0 * unit(&s) - 1.0, 0.0);
		hs_vec3 hi = hs_add(lo, hs_v3(1.5 * unit(&s), 1.5 * unit(&s), 0.0)); // often across an edge
		int n = hs_hgrid_query(&packed, lo, hi, a);
		assert_int_equal(n, hs_hgrid_query(&hashed, lo, hi, b));
		for (int k = 0; k < n; ++k)
			assert_int_equal(a[k], b[k]);
	}
	hs_hgrid_free(&packed);
	hs_hgrid_free(&hashed);
}

// 4000 cubes of 5 cm and one 400 m box: a cube's query finds its few neighbours and the box, not
// all 4000 (a single grid with a cell twice the largest radius filed them all in one cell).
static void test_huge_object_among_small(void **state) {
	(void)state;
	enum { CUBES = 4000 };
	hs_hgrid g;
	assert_true(hs_hgrid_alloc(&g, CUBES + 1, 2));
	int *out = malloc((CUBES + 1) * sizeof *out);
	for (int i = 0; i < CUBES; ++i)
		g.half[i] = 0.025;
	g.half[CUBES] = 200.0;
	hs_hgrid_build(&g, CUBES + 1);
	assert_near(g.cell0, 0.05, 0.0);
	for (int i = 0; i < CUBES; ++i)
		hs_hgrid_file(&g, i, hs_v3(0.1 * (i % 64), 0.1 * (i / 64), 0.0));
	hs_hgrid_file(&g, CUBES, hs_v3(-210.0, 0.0, 0.0));
	int n = hs_hgrid_query(&g, hs_v3(3.175, 3.175, 0), hs_v3(3.225, 3.225, 0), out);
	assert_true(n <= 10);
	assert_int_equal(out[n - 1], CUBES);
	// the box's own query lists every cube (its bounds cover them) and itself
	n = hs_hgrid_query(&g, hs_v3(-410, -200, 0), hs_v3(-10, 200, 0), out);
	assert_int_equal(n, CUBES + 1);
	// all in one place: every one found, once, in order
	for (int i = 0; i < CUBES; ++i)
		hs_hgrid_file(&g, i, hs_v3(1.0, 1.0, 0.0));
	n = hs_hgrid_query(&g, hs_v3(0.99, 0.99, 0), hs_v3(1.01, 1.01, 0), out);
	assert_int_equal(n, CUBES + 1);
	for (int k = 0; k < n; ++k)
		assert_int_equal(out[k], k);
	free(out);
	hs_hgrid_free(&g);
}

static void test_sort_indices(void **state) {
	(void)state;
	int v[100];
	uint64_t s = 3;
	for (int n = 0; n <= 100; n += 7) {
		for (int k = 0; k < n; ++k)
			v[k] = (int)(1000 * unit(&s));
		hs_sort_indices(v, n);
		for (int k = 1; k < n; ++k)
			assert_true(v[k - 1] <= v[k]);
	}
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_query_finds_all_2d),
	    cmocka_unit_test(test_query_finds_all_3d),
	    cmocka_unit_test(test_packed_answers_as_hashed),
	    cmocka_unit_test(test_huge_object_among_small),
	    cmocka_unit_test(test_sort_indices),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
