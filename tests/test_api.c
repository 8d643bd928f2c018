// test_api.c — every public function of handspring.h given NULL pointers, invalid handles (0 and
// out of range) and non-finite or out-of-range numbers returns its documented error
// (HS_ERR_INVALID_ARGUMENT, HS_ERR_CAPACITY, a null handle, NULL, 0 or false) and never crashes;
// huge but finite inputs never let a non-finite value out. Calls that might abort run in a child
// process, so that one crash is reported as a failure of its own test, not of the whole file.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

#include "hs_bench.h"
#include "hs_harness.h"
#include "test_util.h"

static const double NaN = NAN;
static const double Inf = INFINITY;

// The shape handle of the last small_world.
static hs_shape_id small_shape;

// A world of the given kind with one 10 cm cube (handle 1) and one hand (handle 1), room for one
// more object.
static hs_world *small_world_of(hs_world_kind kind, hs_object_id *object, hs_hand_id *hand) {
	hs_world_def def = hs_default_world_def();
	def.kind = kind;
	def.max_objects = 2;
	def.max_shapes = 2;
	def.max_hands = 1;
	hs_status status = HS_ERR_NO_MEMORY;
	hs_world *w = hs_world_create(&def, &status);
	assert_non_null(w);
	assert_int_equal(status, HS_OK);
	hs_shape *cube = hs_shape_box(hs_v3(0.1, 0.1, 0.1), NULL);
	assert_non_null(cube);
	hs_object_def od = hs_default_object_def();
	od.shape = small_shape = hs_world_add_shape(w, cube, NULL);
	hs_shape_destroy(cube);
	od.position = hs_v3(0, 0, 0.05);
	*object = hs_world_add_object(w, &od, NULL);
	assert_int_equal(object->index1, 1);
	hs_hand_def hd = hs_default_hand_def();
	*hand = hs_world_add_hand(w, &hd, NULL);
	assert_int_equal(hand->index1, 1);
	return w;
}

static hs_world *small_world(hs_object_id *object, hs_hand_id *hand) {
	return small_world_of(HS_WORLD_HAND, object, hand);
}

// The status hs_world_create gives a world of `kind` with the spring definition `sd`.
static hs_status create_status(hs_world_kind kind, const hs_spring_def *sd) {
	hs_world_def def = hs_default_world_def();
	def.kind = kind;
	def.spring = *sd;
	hs_status status = HS_ERR_NO_MEMORY;
	hs_world *w = hs_world_create(&def, &status);
	if (w)
		assert_int_equal(status, HS_OK);
	else
		assert_int_not_equal(status, HS_OK);
	hs_world_destroy(w);
	return status;
}

// Runs `call` in a child; fails when the child does not exit normally with status 0.
static void survives(const char *what, void (*call)(void)) {
	fflush(stdout);
	fflush(stderr);
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		call();
		_exit(0);
	}
	int status = 0;
	assert_int_equal(waitpid(pid, &status, 0), pid);
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
		fail_msg("%s crashed (%s %d) instead of returning its documented error", what,
		         WIFSIGNALED(status) ? "signal" : "exit status", WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
}

static void assert_state_finite(const hs_world *w, hs_object_id id) {
	hs_object_state st;
	assert_int_equal(hs_world_object_state(w, id, &st), HS_OK);
	assert_true(hs_vec3_is_finite(st.position));
	assert_true(hs_quat_is_finite(st.orientation));
	assert_true(hs_vec3_is_finite(st.velocity));
}

// ---------------------------------------------------------------------------------------------
// status and shapes

// hs_bench.h: work is skipped in a new world; the knob turns only before the first object.
static void test_skip_work_knob(void **state) {
	(void)state;
	hs_world_def def = hs_default_world_def();
	hs_world *w = hs_world_create(&def, NULL);
	assert_non_null(w);
	assert_true(hs_world_skip_work(w));
	assert_int_equal(hs_world_set_skip_work(w, false), HS_OK);
	assert_false(hs_world_skip_work(w));
	hs_shape *box = hs_shape_box(hs_v3(0.1, 0.1, 0.1), NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, box, NULL);
	od.position = hs_v3(0, 0, 0.05);
	hs_shape_destroy(box);
	assert_int_equal(hs_world_add_object(w, &od, NULL).index1, 1);
	assert_int_equal(hs_world_set_skip_work(w, true), HS_ERR_INVALID_ARGUMENT);
	assert_false(hs_world_skip_work(w));
	assert_int_equal(hs_world_set_skip_work(NULL, true), HS_ERR_INVALID_ARGUMENT);
	assert_false(hs_world_skip_work(NULL));
	hs_world_destroy(w);
}

static void test_status_string(void **state) {
	(void)state;
	for (int s = HS_OK; s <= HS_ERR_NO_MEMORY; ++s)
		assert_non_null(hs_status_string((hs_status)s));
	assert_string_equal(hs_status_string((hs_status)77), "unknown status");
	assert_string_equal(hs_status_string((hs_status)-1), "unknown status");
}

static void test_shape_builders(void **state) {
	(void)state;
	static const double bad[] = {0.0, -1.0, NAN, INFINITY, -INFINITY, -0.0};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
		double b = bad[i];
		hs_status st = HS_OK;
		assert_null(hs_shape_box(hs_v3(b, 1, 1), &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_box(hs_v3(1, 1, b), &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_pyramid(b, 1, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_pyramid(1, b, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_l_block(hs_v3(1, b, 1), 0.1, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_l_block(hs_v3(1, 1, 1), b, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_ellipsoid(hs_v3(1, b, 1), &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_sphere(b, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		assert_null(hs_shape_box(hs_v3(b, b, b), NULL)); // status may be NULL
	}
	hs_status st = HS_OK;
	assert_null(hs_shape_l_block(hs_v3(1, 1, 1), 1.0, &st)); // thickness must be below x and z
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	// overflowing sizes: volume or radius not finite
	st = HS_OK;
	assert_null(hs_shape_box(hs_v3(1e300, 1e300, 1e300), &st));
	assert_int_not_equal(st, HS_OK);
	hs_shape_destroy(NULL);
}

static void test_polyhedron(void **state) {
	(void)state;
	const hs_vec3 v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
	const int fv[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
	const int fs[4] = {3, 3, 3, 3};
	char why[128];
	hs_status st = HS_OK;
	hs_shape *ok = hs_shape_polyhedron(v, 4, fv, fs, 4, why, sizeof why, &st);
	assert_non_null(ok);
	hs_shape_destroy(ok);
	st = HS_OK;
	assert_null(hs_shape_polyhedron(NULL, 4, fv, fs, 4, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_null(hs_shape_polyhedron(v, 4, NULL, fs, 4, NULL, 0, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_null(hs_shape_polyhedron(v, 4, fv, NULL, 4, why, 0, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_null(hs_shape_polyhedron(v, -4, fv, fs, 4, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_null(hs_shape_polyhedron(v, 4, fv, fs, -1, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_null(hs_shape_polyhedron(NULL, 0, NULL, NULL, 0, why, sizeof why, &st)); // empty
	assert_int_equal(st, HS_ERR_DEGENERATE);
	const hs_vec3 nan_v[4] = {{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}, {0, 0, 1}};
	st = HS_OK;
	assert_null(hs_shape_polyhedron(nan_v, 4, fv, fs, 4, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	const hs_vec3 inf_v[4] = {{0, 0, 0}, {INFINITY, 0, 0}, {0, 1, 0}, {0, 0, 1}};
	st = HS_OK;
	assert_null(hs_shape_polyhedron(inf_v, 4, fv, fs, 4, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	const hs_vec3 huge_v[4] = {{0, 0, 0}, {1e200, 0, 0}, {0, 1e200, 0}, {0, 0, 1e200}};
	st = HS_OK;
	assert_null(hs_shape_polyhedron(huge_v, 4, fv, fs, 4, why, sizeof why, &st)); // volume overflows
	assert_int_equal(st, HS_ERR_DEGENERATE);
	const int bad_index[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 9};
	st = HS_OK;
	assert_null(hs_shape_polyhedron(v, 4, bad_index, fs, 4, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_DEGENERATE);
	const int negative_index[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, -3};
	st = HS_OK;
	assert_null(hs_shape_polyhedron(v, 4, negative_index, fs, 4, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_DEGENERATE);
	const int bad_sizes[4] = {3, 3, 3, -3};
	st = HS_OK;
	assert_null(hs_shape_polyhedron(v, 4, fv, bad_sizes, 4, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_DEGENERATE);
	const int big_sizes[4] = {3, 3, 3, 1000000};
	st = HS_OK;
	assert_null(hs_shape_polyhedron(v, 4, fv, big_sizes, 4, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_DEGENERATE);
}

static void test_shape_queries(void **state) {
	(void)state;
	hs_shape *a = hs_shape_box(hs_v3(1, 1, 1), NULL);
	assert_non_null(a);
	hs_quat id = hs_quat_identity();
	double depth = -1.0;
	hs_vec3 dir = {0, 0, 0};
	assert_false(hs_shapes_overlap(NULL, hs_v3(0, 0, 0), id, a, hs_v3(0, 0, 0), id));
	assert_false(hs_shapes_overlap(a, hs_v3(0, 0, 0), id, NULL, hs_v3(0, 0, 0), id));
	assert_false(hs_shapes_penetration(NULL, hs_v3(0, 0, 0), id, a, hs_v3(0, 0, 0), id, &depth, &dir));
	assert_false(hs_shapes_penetration(a, hs_v3(0, 0, 0), id, a, hs_v3(0, 0, 0), id, NULL, &dir));
	assert_false(hs_shapes_penetration(a, hs_v3(0, 0, 0), id, a, hs_v3(0, 0, 0), id, &depth, NULL));
	// non-finite poses interfere with nothing
	assert_false(hs_shapes_overlap(a, hs_v3(NaN, 0, 0), id, a, hs_v3(0, 0, 0), id));
	assert_false(hs_shapes_overlap(a, hs_v3(0, 0, 0), id, a, hs_v3(0, Inf, 0), id));
	assert_false(hs_shapes_penetration(a, hs_v3(0, 0, NaN), id, a, hs_v3(0, 0, 0), id, &depth, &dir));
	assert_false(hs_shapes_overlap(a, hs_v3(0, 0, 0), hs_q(NaN, 0, 0, 0), a, hs_v3(0, 0, 0), id));
	assert_near(depth, -1.0, 0.0); // untouched
	hs_shape_destroy(a);
}

// ---------------------------------------------------------------------------------------------
// worlds and objects

static void test_world_create(void **state) {
	(void)state;
	hs_status st = HS_OK;
	assert_null(hs_world_create(NULL, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	assert_null(hs_world_create(NULL, NULL));
	hs_world_def good = hs_default_world_def();
	hs_world_def d;
#define REJECT(field, value)                                                                            \
	do {                                                                                                \
		d = good;                                                                                       \
		d.field = (value);                                                                              \
		st = HS_OK;                                                                                     \
		hs_world *w_ = hs_world_create(&d, &st);                                                        \
		if (w_) {                                                                                       \
			hs_world_destroy(w_);                                                                       \
			fail_msg("hs_world_create accepted " #field " = " #value);                                   \
		}                                                                                               \
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);                                                  \
	} while (0)
	REJECT(dt, 0.0);
	REJECT(dt, -1.0 / 60);
	REJECT(dt, NaN);
	REJECT(dt, Inf);
	REJECT(gravity.z, NaN);
	REJECT(gravity.x, -Inf);
	REJECT(floor_tolerance, 0.0);
	REJECT(floor_tolerance, -1e-6);
	REJECT(floor_tolerance, NaN);
	REJECT(max_objects, -1);
	REJECT(max_shapes, 0);
	REJECT(max_shapes, -5);
	REJECT(max_hands, -1);
	REJECT(max_hands, 65);
	REJECT(grasp_threshold_deg, 0.0);
	REJECT(grasp_threshold_deg, 180.5);
	REJECT(grasp_threshold_deg, NaN);
	REJECT(stacking, (hs_stacking)7);
	hs_world_destroy(NULL);
}

// A dt so large that g dt² overflows must not reach the state as an infinite velocity.
static void test_world_dt_extremes(void **state) {
	(void)state;
	static const double dts[] = {1e300, 1e200, 1e-300, 5e-324};
	for (size_t k = 0; k < sizeof dts / sizeof dts[0]; ++k) {
		hs_world_def def = hs_default_world_def();
		def.dt = dts[k];
		hs_status st = HS_OK;
		hs_world *w = hs_world_create(&def, &st);
		if (!w) { // rejecting it is fine
			assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
			continue;
		}
		hs_shape *cube = hs_shape_box(hs_v3(0.1, 0.1, 0.1), NULL);
		hs_object_def od = hs_default_object_def();
		od.shape = hs_world_add_shape(w, cube, NULL);
		hs_shape_destroy(cube);
		od.position = hs_v3(0, 0, 1);
		od.velocity = hs_v3(1, 0, 0);
		hs_object_id id = hs_world_add_object(w, &od, NULL);
		if (id.index1 != 0) {
			assert_state_finite(w, id);
			for (int f = 0; f < 3; ++f) {
				assert_int_equal(hs_world_step(w), HS_OK);
				assert_state_finite(w, id);
			}
			assert_true(isfinite(hs_world_time(w)));
		}
		hs_world_destroy(w);
	}
}

static void test_world_shapes(void **state) {
	(void)state;
	hs_object_id obj;
	hs_hand_id hand;
	hs_world *w = small_world(&obj, &hand);
	hs_shape *cube = hs_shape_box(hs_v3(0.1, 0.1, 0.1), NULL);
	hs_status st = HS_OK;
	assert_int_equal(hs_world_add_shape(NULL, cube, &st).index1, 0);
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_int_equal(hs_world_add_shape(w, NULL, &st).index1, 0);
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	hs_shape empty;
	memset(&empty, 0, sizeof empty);
	st = HS_OK;
	assert_int_equal(hs_world_add_shape(w, &empty, &st).index1, 0); // no vertices, no volume
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_add_shape(w, cube, &st).index1, 2);
	st = HS_OK;
	assert_int_equal(hs_world_add_shape(w, cube, &st).index1, 0); // max_shapes = 2
	assert_int_equal(st, HS_ERR_CAPACITY);
	hs_shape_destroy(cube);
	assert_non_null(hs_world_shape(w, small_shape));
	assert_null(hs_world_shape(w, (hs_shape_id){1, 0, 0})); // no world tag
	assert_null(hs_world_shape(w, (hs_shape_id){0}));
	assert_null(hs_world_shape(w, (hs_shape_id){3, 0, 0}));
	assert_null(hs_world_shape(w, (hs_shape_id){UINT32_MAX, 0, 0}));
	assert_null(hs_world_shape(NULL, small_shape));
	hs_world_destroy(w);
}

// Handles know their world and generation (Box2D's b2BodyId): one world's handle is refused by
// another built the same way, and a handle of another generation by its own world.
static void test_handles_know_their_world(void **state) {
	(void)state;
	hs_object_id obj_a, obj_b;
	hs_hand_id hand_a, hand_b;
	hs_world *a = small_world(&obj_a, &hand_a);
	hs_shape_id shape_a = small_shape;
	hs_world *b = small_world(&obj_b, &hand_b);
	assert_int_equal(obj_a.index1, obj_b.index1); // the same index, different worlds
	assert_int_not_equal(obj_a.world, obj_b.world);
	assert_int_not_equal(obj_a.world, 0);
	hs_object_state out;
	assert_int_equal(hs_world_object_state(a, obj_a, &out), HS_OK);
	assert_int_equal(hs_world_object_state(b, obj_a, &out), HS_ERR_INVALID_ARGUMENT);
	assert_null(hs_world_shape(b, shape_a));
	hs_object_def od = hs_default_object_def();
	od.shape = shape_a;
	hs_status st = HS_OK;
	assert_int_equal(hs_world_add_object(b, &od, &st).index1, 0);
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	uint8_t s[HS_GLOVE_SENSORS] = {0};
	assert_int_equal(hs_world_set_hand(b, hand_a, hs_v3(0, 0, 0.3), hs_quat_identity(), s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(a, hand_a, hs_v3(0, 0, 0.3), hs_quat_identity(), s), HS_OK);
	hs_object_id stale = obj_a;
	stale.generation++;
	assert_int_equal(hs_world_object_state(a, stale, &out), HS_ERR_INVALID_ARGUMENT);
	hs_hand_id stale_hand = hand_a;
	stale_hand.generation = 0;
	hs_vec3 points[HS_HAND_POINTS];
	assert_int_equal(hs_world_hand_points(a, stale_hand, points), HS_ERR_INVALID_ARGUMENT);
	// the handles the world hands out by index are the ones it made
	hs_object_id at = hs_world_object_at(a, 0);
	assert_true(at.index1 == obj_a.index1 && at.world == obj_a.world && at.generation == obj_a.generation);
	hs_hand_id hat = hs_world_hand_at(a, 0);
	assert_true(hat.index1 == hand_a.index1 && hat.world == hand_a.world && hat.generation == hand_a.generation);
	hs_shape_id sat = hs_world_shape_at(a, 0);
	assert_true(sat.index1 == shape_a.index1 && sat.world == shape_a.world);
	assert_int_equal(hs_world_object_at(a, 1).index1, 0);
	assert_int_equal(hs_world_hand_at(a, 1).index1, 0);
	assert_int_equal(hs_world_shape_at(a, 1).index1, 0);
	assert_int_equal(hs_world_hand_at(NULL, 0).index1, 0);
	assert_int_equal(hs_world_shape_at(NULL, 0).index1, 0);
	hs_world_destroy(a);
	hs_world_destroy(b);
}

static void test_world_objects(void **state) {
	(void)state;
	hs_object_id obj;
	hs_hand_id hand;
	hs_world *w = small_world(&obj, &hand);
	hs_object_def good = hs_default_object_def();
	good.shape = small_shape;
	good.position = hs_v3(1, 0, 0.05);
	hs_object_def d;
	hs_status st;
#define REJECT_OBJECT(field, value)                                                                     \
	do {                                                                                                \
		d = good;                                                                                       \
		d.field = (value);                                                                              \
		st = HS_OK;                                                                                     \
		if (hs_world_add_object(w, &d, &st).index1 != 0)                                                \
			fail_msg("hs_world_add_object accepted " #field " = " #value);                               \
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);                                                  \
	} while (0)
	REJECT_OBJECT(shape.index1, 0);
	REJECT_OBJECT(shape.index1, 2);
	REJECT_OBJECT(shape.index1, UINT32_MAX);
	REJECT_OBJECT(position.x, NaN);
	REJECT_OBJECT(position.z, Inf);
	REJECT_OBJECT(velocity.y, NaN);
	REJECT_OBJECT(velocity.x, -Inf);
	REJECT_OBJECT(angular_velocity.z, NaN);
	REJECT_OBJECT(orientation.w, NaN);
	REJECT_OBJECT(orientation.w, 2.0);
	REJECT_OBJECT(orientation.w, 0.0);
	REJECT_OBJECT(density, 0.0);
	REJECT_OBJECT(density, -500.0);
	REJECT_OBJECT(density, NaN);
	REJECT_OBJECT(density, Inf);
	st = HS_OK;
	assert_int_equal(hs_world_add_object(NULL, &good, &st).index1, 0);
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_int_equal(hs_world_add_object(w, NULL, &st).index1, 0);
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_add_object(w, &good, NULL).index1, 2);
	st = HS_OK;
	assert_int_equal(hs_world_add_object(w, &good, &st).index1, 0); // max_objects = 2
	assert_int_equal(st, HS_ERR_CAPACITY);
	// state: invalid handles and NULL
	hs_object_state out;
	assert_int_equal(hs_world_object_state(w, (hs_object_id){0}, &out), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_object_state(w, (hs_object_id){3, 0, 0}, &out), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_object_state(w, (hs_object_id){UINT32_MAX, 0, 0}, &out), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_object_state(w, obj, NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_object_state(NULL, obj, &out), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_object_count(NULL), 0);
	assert_int_equal(hs_world_object_count(w), 2);
	assert_int_equal(hs_world_object_at(w, -1).index1, 0);
	assert_int_equal(hs_world_object_at(w, 2).index1, 0);
	assert_int_equal(hs_world_object_at(w, 1).index1, 2);
	assert_int_equal(hs_world_object_at(NULL, 0).index1, 0);
	// stepping and the read-outs
	assert_int_equal(hs_world_step(NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_frame(NULL), 0);
	assert_true(hs_world_time(NULL) == 0.0);
	assert_true(hs_world_dt(NULL) == 0.0);
	(void)hs_world_hash(NULL);
	hs_world_counters c = hs_world_get_counters(NULL);
	assert_int_equal(c.object_steps, 0);
	assert_int_equal(c.numeric_faults, 0);
	assert_int_equal(hs_world_contacts(NULL, NULL, 4), 0);
	assert_int_equal(hs_world_step(w), HS_OK);
	assert_true(hs_world_contacts(w, NULL, 4) >= 0);
	hs_contact cs[2];
	assert_true(hs_world_contacts(w, cs, -3) >= 0);
	hs_world_destroy(w);
}

// Huge but finite inputs: everything the world reports stays finite (caught faults are counted).
static void test_world_huge_numbers(void **state) {
	(void)state;
	hs_world_def def = hs_default_world_def();
	def.gravity = hs_v3(0, 0, -1e300);
	hs_status created = HS_OK;
	assert_null(hs_world_create(&def, &created)); // beyond HS_MAX_GRAVITY: rejected at the boundary
	assert_int_equal(created, HS_ERR_INVALID_ARGUMENT);
	def.gravity = hs_v3(0, 0, -HS_MAX_GRAVITY);
	hs_world *w = hs_world_create(&def, NULL);
	assert_non_null(w);
	hs_shape *cube = hs_shape_box(hs_v3(1e-3, 1e-3, 1e-3), NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, cube, NULL);
	hs_shape_destroy(cube);
	hs_object_id ids[4];
	od.position = hs_v3(1e308, -1e308, 1e308);
	od.velocity = hs_v3(1e308, 1e308, -1e308);
	od.angular_velocity = hs_v3(1e308, 0, 1e300);
	ids[0] = hs_world_add_object(w, &od, NULL);
	od.position = hs_v3(0, 0, 1e-300);
	od.velocity = hs_v3(0, 0, 0);
	ids[1] = hs_world_add_object(w, &od, NULL);
	od.position = hs_v3(-1e300, 1e300, 5);
	ids[2] = hs_world_add_object(w, &od, NULL);
	od.position = hs_v3(0, 0, 1e308);
	od.velocity = hs_v3(0, 0, 1e308);
	ids[3] = hs_world_add_object(w, &od, NULL);
	hs_hand_def hd = hs_default_hand_def();
	hs_hand_id hand = hs_world_add_hand(w, &hd, NULL);
	uint8_t s[HS_GLOVE_SENSORS];
	assert_int_equal(hs_hand_posture(&hd, HS_POSTURE_FIST, 1.0, s), HS_OK);
	for (int f = 0; f < 20; ++f) {
		hs_vec3 huge = f % 2 ? hs_v3(1e308, -1e308, 1e308) : hs_v3(-1e300, 1e300, 5);
		assert_int_equal(hs_world_set_hand(w, hand, huge, hs_quat_identity(), s), HS_ERR_INVALID_ARGUMENT);
		hs_vec3 wrist = f % 2 ? hs_v3(HS_MAX_COORDINATE, -HS_MAX_COORDINATE, HS_MAX_COORDINATE) : hs_v3(0, 0, 5);
		assert_int_equal(hs_world_set_hand(w, hand, wrist, hs_quat_identity(), s), HS_OK);
		assert_int_equal(hs_world_step(w), HS_OK);
		for (int i = 0; i < 4; ++i)
			if (ids[i].index1)
				assert_state_finite(w, ids[i]);
		hs_vec3 points[HS_HAND_POINTS];
		assert_int_equal(hs_world_hand_points(w, hand, points), HS_OK);
		hs_contact cs[64];
		int n = hs_world_contacts(w, cs, 64);
		for (int k = 0; k < n && k < 64; ++k) {
			assert_true(hs_vec3_is_finite(cs[k].point));
			assert_true(hs_vec3_is_finite(cs[k].normal));
		}
	}
	hs_world_destroy(w);
}

// ---------------------------------------------------------------------------------------------
// hands

static void test_hand_functions(void **state) {
	(void)state;
	hs_hand_def def = hs_default_hand_def();
	uint8_t s[HS_GLOVE_SENSORS];
	memset(s, 100, sizeof s);
	hs_hand_joints j = hs_hand_joints_from_sensors(&def, NULL); // NULL sensors: zero angles
	assert_true(j.thumb_roll == 0.0 && j.mcp[0] == 0.0 && j.wrist_yaw == 0.0);
	hs_hand_sensors_from_angles(NULL, s);
	hs_hand_sensors_from_angles(&j, NULL);
	hs_hand_joints bad = hs_hand_joints_from_sensors(&def, s);
	bad.thumb_roll = NaN;
	bad.mcp[1] = Inf;
	bad.wrist_pitch = -Inf;
	hs_hand_sensors_from_angles(&bad, s); // NaN reads as zero, infinities clamp
	assert_int_equal(s[HS_SENSOR_THUMB_ROLL], 0);
	assert_int_equal(s[HS_SENSOR_MIDDLE_MCP], 255);
	assert_int_equal(s[HS_SENSOR_WRIST_PITCH], 0);
	hs_vec3 points[HS_HAND_POINTS], lines[HS_HAND_LINES][2];
	hs_hand_kinematics(&def, hs_v3(0, 0, 0), hs_quat_identity(), NULL, points, lines);
	hs_hand_kinematics(&def, hs_v3(0, 0, 0), hs_quat_identity(), s, NULL, NULL);
	hs_vec3 c, axis;
	hs_hand_grip(&def, NULL, &c, &axis);
	hs_hand_grip(&def, s, NULL, NULL);
	// postures
	assert_int_equal(hs_hand_posture(NULL, HS_POSTURE_OPEN, 0, s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_hand_posture(&def, HS_POSTURE_OPEN, 0, NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_hand_posture(&def, (hs_posture)42, 0.5, s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_hand_posture(&def, (hs_posture)-1, 0.5, s), HS_ERR_INVALID_ARGUMENT);
	static const hs_posture amounts[] = {HS_POSTURE_FIST, HS_POSTURE_PINCH, HS_POSTURE_POINT, HS_POSTURE_GRASP};
	for (size_t k = 0; k < 4; ++k) {
		assert_int_equal(hs_hand_posture(&def, amounts[k], NaN, s), HS_ERR_INVALID_ARGUMENT);
		assert_int_equal(hs_hand_posture(&def, amounts[k], Inf, s), HS_ERR_INVALID_ARGUMENT);
		assert_int_equal(hs_hand_posture(&def, amounts[k], -Inf, s), HS_ERR_INVALID_ARGUMENT);
		assert_int_equal(hs_hand_posture(&def, amounts[k], -0.5, s), HS_ERR_INVALID_ARGUMENT);
	}
	hs_hand_def broken = def;
	broken.finger_radius = NaN;
	assert_int_equal(hs_hand_posture(&broken, HS_POSTURE_FIST, 0.5, s), HS_ERR_INVALID_ARGUMENT);
}

// The hand functions take `def` by pointer like the others: NULL must not abort (they assert).
static void call_joints_null_def(void) {
	uint8_t s[HS_GLOVE_SENSORS] = {0};
	hs_hand_joints j = hs_hand_joints_from_sensors(NULL, s);
	(void)j;
}
static void call_kinematics_null_def(void) {
	uint8_t s[HS_GLOVE_SENSORS] = {0};
	hs_vec3 points[HS_HAND_POINTS];
	hs_hand_kinematics(NULL, hs_v3(0, 0, 0), hs_quat_identity(), s, points, NULL);
}
static void call_grip_null_def(void) {
	uint8_t s[HS_GLOVE_SENSORS] = {0};
	hs_vec3 c, axis;
	hs_hand_grip(NULL, s, &c, &axis);
}

static void test_hand_null_def(void **state) {
	(void)state;
	survives("hs_hand_joints_from_sensors(NULL, sensors)", call_joints_null_def);
	survives("hs_hand_kinematics(NULL, ...)", call_kinematics_null_def);
	survives("hs_hand_grip(NULL, ...)", call_grip_null_def);
}

static void test_world_hands(void **state) {
	(void)state;
	hs_object_id obj;
	hs_hand_id hand;
	hs_world *w = small_world(&obj, &hand);
	hs_hand_def good = hs_default_hand_def();
	hs_hand_def d;
	hs_status st;
#define REJECT_HAND(field, value)                                                                       \
	do {                                                                                                \
		d = good;                                                                                       \
		d.field = (value);                                                                              \
		st = HS_OK;                                                                                     \
		if (hs_world_add_hand(w, &d, &st).index1 != 0)                                                  \
			fail_msg("hs_world_add_hand accepted " #field " = " #value);                                 \
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);                                                  \
	} while (0)
	REJECT_HAND(finger_radius, 0.0);
	REJECT_HAND(finger_radius, NaN);
	REJECT_HAND(finger_radius, Inf);
	REJECT_HAND(dip_per_pip, NaN);
	REJECT_HAND(dip_per_pip, -1.0);
	REJECT_HAND(segment_length[2][1], 0.0);
	REJECT_HAND(segment_length[0][0], NaN);
	REJECT_HAND(base[3].y, Inf);
	st = HS_OK;
	assert_int_equal(hs_world_add_hand(NULL, &good, &st).index1, 0);
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_int_equal(hs_world_add_hand(w, NULL, &st).index1, 0);
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_int_equal(hs_world_add_hand(w, &good, &st).index1, 0); // max_hands = 1
	assert_int_equal(st, HS_ERR_CAPACITY);
	uint8_t s[HS_GLOVE_SENSORS] = {0};
	hs_quat id = hs_quat_identity();
	hs_vec3 p = hs_v3(0, 0, 0.3);
	assert_int_equal(hs_world_set_hand(NULL, hand, p, id, s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, (hs_hand_id){0}, p, id, s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, (hs_hand_id){2, 0, 0}, p, id, s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, (hs_hand_id){UINT32_MAX, 0, 0}, p, id, s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, hand, p, id, NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, hand, hs_v3(NaN, 0, 0), id, s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, hand, hs_v3(0, -Inf, 0), id, s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, hand, p, hs_q(NaN, 0, 0, 0), s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, hand, p, hs_q(2, 0, 0, 0), s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, hand, p, hs_q(0, 0, 0, 0), s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand(w, hand, p, id, s), HS_OK);
	hs_vec3 points[HS_HAND_POINTS];
	assert_int_equal(hs_world_hand_points(NULL, hand, points), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_hand_points(w, (hs_hand_id){0}, points), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_hand_points(w, (hs_hand_id){9, 0, 0}, points), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_hand_points(w, hand, NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_hand_points(w, hand, points), HS_OK);
	hs_world_destroy(w);
}

// ---------------------------------------------------------------------------------------------
// springs

static void test_springs(void **state) {
	(void)state;
	hs_object_id obj;
	hs_hand_id hand;
	hs_world *w = small_world(&obj, &hand);
	hs_spring_def good = hs_default_spring_def();
	// everything that needs the spring model refuses in a hand world
	assert_false(hs_world_springs_enabled(w));
	assert_false(hs_world_springs_enabled(NULL));
	assert_int_equal(hs_world_set_stylus(w, hs_v3(0, 0, 1), hs_quat_identity(), false), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_attach(w, obj), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_detach(w), HS_ERR_INVALID_ARGUMENT);
	hs_spring_state ss;
	hs_spring_object so;
	hs_tracker_state ts;
	hs_tracker_sample sample;
	hs_release rel;
	assert_int_equal(hs_world_spring_state(w, &ss), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_object(w, obj, &so), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_state(w, &ts), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_sample(w, 0, &sample), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_last_release(w, &rel), HS_ERR_INVALID_ARGUMENT);
	// invalid definitions
	hs_spring_def d;
#define REJECT_SPRING(field, value)                                                                     \
	do {                                                                                                \
		d = good;                                                                                       \
		d.field = (value);                                                                              \
		if (create_status(HS_WORLD_SPRING, &d) != HS_ERR_INVALID_ARGUMENT)                              \
			fail_msg("hs_world_create accepted a spring world with " #field " = " #value);             \
		if (create_status(HS_WORLD_HAND, &d) != HS_OK) /* a hand world never reads it */              \
			fail_msg("hs_world_create refused a hand world with spring." #field " = " #value);         \
	} while (0)
	REJECT_SPRING(integrator, (hs_integrator)9);
	REJECT_SPRING(friction_static, NaN);
	REJECT_SPRING(friction_static, -0.1);
	REJECT_SPRING(friction_sliding, 0.9); // above static
	REJECT_SPRING(restitution, 1.5);
	REJECT_SPRING(restitution, NaN);
	REJECT_SPRING(rest_length_ref, 0.0);
	REJECT_SPRING(rest_mass_ref, Inf);
	REJECT_SPRING(rest_exponent, NaN);
	REJECT_SPRING(rest_length_min, 2.0); // above max
	REJECT_SPRING(tracker_rate, 0.0);
	REJECT_SPRING(tracker_rate, NaN);
	REJECT_SPRING(tracker_window, 2);
	REJECT_SPRING(tracker_window, HS_TRACKER_CAPACITY + 1);
	REJECT_SPRING(rest_speed, -1.0);
	REJECT_SPRING(motion_speed, 0.05); // below rest_speed
	REJECT_SPRING(catch_radius, NaN);
	REJECT_SPRING(grab_range, -1.0);
	REJECT_SPRING(select_range, 0.0);
	d = good;
	d.walls = (hs_spring_walls){true, 1.0, -1.0, -1.0, 1.0};
	assert_int_equal(create_status(HS_WORLD_SPRING, &d), HS_ERR_INVALID_ARGUMENT);
	d.walls = (hs_spring_walls){true, -1.0, 1.0, NaN, 1.0};
	assert_int_equal(create_status(HS_WORLD_SPRING, &d), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(create_status((hs_world_kind)2, &good), HS_ERR_INVALID_ARGUMENT); // no such kind
	assert_int_equal(create_status(HS_WORLD_SPRING, &good), HS_OK);
	assert_false(hs_world_springs_enabled(w));
	hs_world_destroy(w); // the same world, made a spring world
	w = small_world_of(HS_WORLD_SPRING, &obj, &hand);
	assert_true(hs_world_springs_enabled(w));
	// no stylus yet: attaching refuses
	assert_int_equal(hs_world_spring_attach(w, obj), HS_ERR_INVALID_ARGUMENT);
	// the stylus
	hs_quat id = hs_quat_identity();
	assert_int_equal(hs_world_set_stylus(NULL, hs_v3(0, 0, 1), id, false), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_stylus(w, hs_v3(NaN, 0, 1), id, false), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_stylus(w, hs_v3(0, Inf, 1), id, false), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_stylus(w, hs_v3(0, 0, 1), hs_q(NaN, 0, 0, 0), false), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_stylus(w, hs_v3(0, 0, 1), hs_q(0.5, 0, 0, 0), false), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_stylus(w, hs_v3(0, 0, 1), id, false), HS_OK);
	// handles
	assert_int_equal(hs_world_spring_attach(NULL, obj), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_attach(w, (hs_object_id){0}), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_attach(w, (hs_object_id){2, 0, 0}), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_attach(w, (hs_object_id){UINT32_MAX, 0, 0}), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_detach(NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_detach(w), HS_OK); // nothing attached: nothing to do
	assert_int_equal(hs_world_spring_state(NULL, &ss), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_state(w, NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_object(w, (hs_object_id){0}, &so), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_object(w, (hs_object_id){5, 0, 0}, &so), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_object(w, obj, NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_object(NULL, obj, &so), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_state(NULL, &ts), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_state(w, NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_sample(w, 0, &sample), HS_ERR_INVALID_ARGUMENT); // no sample yet
	assert_int_equal(hs_world_spring_last_release(NULL, &rel), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_last_release(w, NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_spring_attach(w, obj), HS_OK);
	for (int f = 0; f < 30; ++f) {
		assert_int_equal(hs_world_set_stylus(w, hs_v3(0, 0, 1), id, f < 20), HS_OK);
		assert_int_equal(hs_world_step(w), HS_OK);
		assert_state_finite(w, obj);
	}
	assert_int_equal(hs_world_tracker_sample(w, -1, &sample), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_sample(w, HS_TRACKER_CAPACITY, &sample), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_sample(w, 1 << 30, &sample), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_sample(w, 0, NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_sample(NULL, 0, &sample), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_tracker_sample(w, 0, &sample), HS_OK);
	assert_int_equal(hs_world_spring_object(w, obj, &so), HS_OK);
	assert_true(isfinite(so.mass) && isfinite(so.stiffness) && isfinite(so.damping));
	hs_world_destroy(w);
}

// ---------------------------------------------------------------------------------------------
// scenarios, catalog, trajectories

static void test_scenario_functions(void **state) {
	(void)state;
	hs_error err;
	memset(&err, 'x', sizeof err);
	assert_null(hs_scenario_load(NULL, &err));
	assert_true(strlen(err.message) > 0 && strlen(err.message) < sizeof err.message);
	assert_null(hs_scenario_load(NULL, NULL));
	assert_null(hs_scenario_load("/nonexistent/x.yaml", NULL));
	assert_null(hs_scenario_load("", &err));
	assert_true(strlen(err.message) > 0);
	hs_scenario_destroy(NULL);
	assert_null(hs_scenario_name(NULL));
	assert_null(hs_scenario_description(NULL));
	assert_null(hs_scenario_world(NULL));
	assert_null(hs_scenario_object_name(NULL, 0));
	assert_int_equal(hs_scenario_frame_count(NULL), 0);
	assert_false(hs_scenario_step(NULL));
	assert_int_equal(hs_scenario_check(NULL, NULL), 0);
	assert_int_equal(hs_scenario_check(NULL, stdout), 0);
	assert_int_equal(hs_scenario_expectation_count(NULL), 0);
	assert_true(hs_scenario_dt(NULL) == 0.0);
	assert_int_equal(hs_scenario_object_count(NULL), 0);
	hs_scenario *s = hs_scenario_load("scenarios/drop_cube.yaml", &err);
	if (!s)
		fail_msg("%s", err.message);
	assert_null(hs_scenario_object_name(s, -1));
	assert_null(hs_scenario_object_name(s, hs_scenario_object_count(s)));
	assert_null(hs_scenario_object_name(s, 1 << 30));
	while (hs_scenario_step(s)) {
	}
	assert_false(hs_scenario_step(s)); // past the end: still false, no crash
	assert_int_equal(hs_scenario_check(s, NULL), 0);
	// trajectories: NULL files and scenarios
	hs_trajectory_write_header(NULL);
	hs_trajectory_write_frame(NULL, s);
	hs_trajectory_write_frame(stdout, NULL);
	hs_trajectory_write_frame(NULL, NULL);
	hs_scenario_destroy(s);
	char why[256];
	assert_false(hs_trajectory_compare(NULL, NULL, 0.0, NULL, why, sizeof why));
	assert_true(strlen(why) > 0);
	assert_false(hs_trajectory_compare(NULL, NULL, 0.0, "x", NULL, 0));
	FILE *a = tmpfile(), *b = tmpfile();
	assert_non_null(a);
	assert_non_null(b);
	assert_false(hs_trajectory_compare(a, b, NaN, "x", why, sizeof why)); // tolerance must be >= 0
	assert_false(hs_trajectory_compare(a, b, -1.0, "x", why, 1));
	assert_false(hs_trajectory_compare(a, NULL, 0.0, "x", why, sizeof why));
	fclose(a);
	fclose(b);
}

static void test_catalog_functions(void **state) {
	(void)state;
	hs_catalog cat;
	hs_error err;
	memset(&cat, 0x5a, sizeof cat);
	assert_false(hs_catalog_load(NULL, &cat, &err));
	assert_int_equal(cat.count, 0);
	assert_true(strlen(err.message) > 0);
	assert_false(hs_catalog_load("scenarios", NULL, &err));
	assert_false(hs_catalog_load("/nonexistent_hs_dir", &cat, NULL));
	assert_false(hs_catalog_load("scenarios/drop_cube.yaml", &cat, &err)); // a file, not a folder
	assert_true(strlen(err.message) > 0);
	hs_catalog_free(NULL);
	assert_true(hs_catalog_load("scenarios", &cat, NULL));
	hs_catalog_free(&cat);
	hs_catalog_free(&cat); // twice: the first cleared it
}

// ---------------------------------------------------------------------------------------------
// hostile files made at run time (binary, too large to commit, or machine-dependent): the
// library and the tool ($HS_TOOL, default build/handspring) give one "PATH:LINE: what" line, exit 2

static char tmp_dir[64];

static const char *tmp_file(const char *name) {
	static char path[160];
	if (!tmp_dir[0]) {
		snprintf(tmp_dir, sizeof tmp_dir, "/tmp/hs_api_XXXXXX");
		assert_non_null(mkdtemp(tmp_dir));
	}
	snprintf(path, sizeof path, "%s/%s", tmp_dir, name);
	return path;
}

static void write_file(const char *path, const void *data, size_t n) {
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(data, 1, n, f), n);
	assert_int_equal(fclose(f), 0);
}

// The tool's exit status and first stderr line for `run path`.
static int run_tool(const char *path, char *line, size_t line_size) {
	const char *tool = getenv("HS_TOOL");
	if (!tool || !*tool)
		tool = "build/handspring";
	char err_name[] = "/tmp/hs_api_err_XXXXXX";
	int err = mkstemp(err_name);
	assert_true(err >= 0);
	unlink(err_name);
	fflush(stdout);
	fflush(stderr);
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		int null = open("/dev/null", O_WRONLY);
		dup2(null, 1);
		dup2(err, 2);
		execl(tool, tool, "run", path, (char *)NULL);
		_exit(127);
	}
	int status = 0;
	assert_int_equal(waitpid(pid, &status, 0), pid);
	lseek(err, 0, SEEK_SET);
	ssize_t n = read(err, line, line_size - 1);
	close(err);
	line[n > 0 ? n : 0] = '\0';
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static void expect_message(const char *path, const char *want) {
	hs_error err;
	memset(&err, 'x', sizeof err);
	hs_scenario *s = hs_scenario_load(path, &err);
	if (s) {
		hs_scenario_destroy(s);
		fail_msg("%s loaded; expected: %s", path, want);
	}
	assert_string_equal(err.message, want);
	char line[1024];
	int status = run_tool(path, line, sizeof line);
	if (status == 127)
		fail_msg("could not run the tool (set HS_TOOL)");
	assert_int_equal(status, 2);
	char want_line[600];
	snprintf(want_line, sizeof want_line, "%s\n", want);
	assert_string_equal(line, want_line);
}

static const char scenario_head[] = "description: hostile input\ndt: 1/60\nduration: 1\n"
                                    "objects:\n  - { name: a, shape: cube, size: 0.1, position: [0, 0, 0.05] }\n";

static void scenario_with_record(const char *yaml_name, const char *record) {
	char text[512];
	snprintf(text, sizeof text, "%shands:\n  - name: right\n    record: %s\n", scenario_head, record);
	write_file(tmp_file(yaml_name), text, strlen(text));
}

static void test_hostile_binary_record(void **state) {
	(void)state;
	static const char data[] = "t,x,y,z,qw,qx,qy,qz,s0,s1,s2,s3,s4,s5,s6,s7,s8,s9,s10,s11,s12,s13,s14,s15,s16,s17\n"
	                           "0,0,0,0.3,1,0\0\0\0\x7f" "ELF\x02\x01\x01\n";
	char csv[200], want[400];
	snprintf(csv, sizeof csv, "%s", tmp_file("binary.csv"));
	write_file(csv, data, sizeof data - 1);
	scenario_with_record("binary.yaml", "binary.csv");
	snprintf(want, sizeof want, "%s:2: not a text file (NUL byte)", csv);
	expect_message(tmp_file("binary.yaml"), want);
}

static void test_hostile_record_is_directory(void **state) {
	(void)state;
	char dir[200], want[400];
	snprintf(dir, sizeof dir, "%s", tmp_file("folder.csv"));
	assert_int_equal(mkdir(dir, 0700), 0);
	scenario_with_record("folder.yaml", "folder.csv");
	snprintf(want, sizeof want, "%s:1: cannot read recorded input: Is a directory", dir);
	expect_message(tmp_file("folder.yaml"), want);
	rmdir(dir);
}

static void test_hostile_binary_scenario(void **state) {
	(void)state;
	static const unsigned char data[] = {0x1f, 0x8b, 0x08, 0x00, 'd', 't', ':', 0x00, 0xff, '\n'}; // gzip
	char path[200], want[400];
	snprintf(path, sizeof path, "%s", tmp_file("zipped.yaml"));
	write_file(path, data, sizeof data);
	snprintf(want, sizeof want, "%s:1: not a text file (NUL byte at byte 3)", path);
	expect_message(path, want);
}

// 100,001 objects and a hand with 100,001 keys: over the limits, said before any is built.
static void test_hostile_absurd_counts(void **state) {
	(void)state;
	size_t cap = 8u << 20, n = 0;
	char *text = malloc(cap);
	assert_non_null(text);
	n += (size_t)snprintf(text + n, cap - n, "description: hostile input\ndt: 1/60\nduration: 1\nobjects:\n");
	for (int i = 0; i < 100001; ++i)
		n += (size_t)snprintf(text + n, cap - n, "  - {}\n");
	char path[200], want[400];
	snprintf(path, sizeof path, "%s", tmp_file("many_objects.yaml"));
	write_file(path, text, n);
	snprintf(want, sizeof want, "%s:5: 'objects' must hold 1 to 100000 objects, got 100001", path);
	expect_message(path, want);
	n = (size_t)snprintf(text, cap, "%shands:\n  - name: right\n    keys:\n", scenario_head);
	for (int i = 0; i < 100001; ++i)
		n += (size_t)snprintf(text + n, cap - n, "      - { t: 0.5 }\n");
	snprintf(path, sizeof path, "%s", tmp_file("many_keys.yaml"));
	write_file(path, text, n);
	snprintf(want, sizeof want, "%s:9: 'keys' must be a list of 1 to 100000 keys, got 100001", path);
	expect_message(path, want);
	free(text);
}

// A recorded file with one line of 4 MB: one message, no crash.
static void test_hostile_long_line(void **state) {
	(void)state;
	size_t n = 4u << 20;
	char *text = malloc(n + 200);
	assert_non_null(text);
	int head = snprintf(text, 200, "t,x,y,z,qw,qx,qy,qz,s0,s1,s2,s3,s4,s5,s6,s7,s8,s9,s10,s11,s12,s13,s14,s15,s16,s17\n");
	memset(text + head, '7', n);
	text[(size_t)head + n] = '\n';
	char csv[200], want[400];
	snprintf(csv, sizeof csv, "%s", tmp_file("long.csv"));
	write_file(csv, text, (size_t)head + n + 1);
	free(text);
	scenario_with_record("long.yaml", "long.csv");
	snprintf(want, sizeof want, "%s:2: expected 26 numbers (t,x,y,z,qw,qx,qy,qz,s0,...,s17), column 1 is not a number", csv);
	expect_message(tmp_file("long.yaml"), want);
}

// A scenario at a path of 600 bytes: the message still ends with the line and the reason (a long
// path is shortened; hs_error.message holds 512 bytes).
static void test_hostile_long_path(void **state) {
	(void)state;
	char path[1024];
	snprintf(path, sizeof path, "%s", tmp_file(""));
	for (int level = 0; level < 4; ++level) {
		size_t n = strlen(path);
		memset(path + n, 'a' + level, 150);
		path[n + 150] = '\0';
		mkdir(path, 0700); // may exist from an earlier level's run: fine
		strcat(path, "/");
	}
	strcat(path, "bad_dt.yaml");
	assert_true(strlen(path) > 600);
	static const char text[] = "description: hostile input\ndt: fast\nduration: 1\n"
	                           "objects:\n  - { name: a, shape: cube, size: 0.1, position: [0, 0, 0.05] }\n";
	write_file(path, text, sizeof text - 1);
	hs_error err;
	assert_null(hs_scenario_load(path, &err));
	const char *tail = "bad_dt.yaml:2: 'dt' must be a number, got 'fast'";
	size_t n = strlen(err.message), t = strlen(tail);
	if (n < t || strcmp(err.message + n - t, tail) != 0)
		fail_msg("the line and the reason are lost: \"%s\"", err.message);
	char line[1024];
	assert_int_equal(run_tool(path, line, sizeof line), 2);
	assert_true(strlen(line) > t && strncmp(line + strlen(line) - t - 1, tail, t) == 0);
}

static int remove_tmp_dir(void **state) {
	(void)state;
	if (tmp_dir[0]) {
		char cmd[128];
		snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp_dir);
		if (system(cmd) != 0)
			return 1;
	}
	return 0;
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_skip_work_knob),
	    cmocka_unit_test(test_status_string),     cmocka_unit_test(test_shape_builders),
	    cmocka_unit_test(test_polyhedron),        cmocka_unit_test(test_shape_queries),
	    cmocka_unit_test(test_world_create),      cmocka_unit_test(test_world_dt_extremes),
	    cmocka_unit_test(test_world_shapes),      cmocka_unit_test(test_world_objects),
	    cmocka_unit_test(test_handles_know_their_world),
	    cmocka_unit_test(test_world_huge_numbers), cmocka_unit_test(test_hand_functions),
	    cmocka_unit_test(test_hand_null_def),     cmocka_unit_test(test_world_hands),
	    cmocka_unit_test(test_springs),           cmocka_unit_test(test_scenario_functions),
	    cmocka_unit_test(test_catalog_functions), cmocka_unit_test(test_hostile_binary_record),
	    cmocka_unit_test(test_hostile_record_is_directory), cmocka_unit_test(test_hostile_binary_scenario),
	    cmocka_unit_test(test_hostile_absurd_counts), cmocka_unit_test(test_hostile_long_line),
	    cmocka_unit_test(test_hostile_long_path),
	};
	return cmocka_run_group_tests_name("api", tests, NULL, remove_tmp_dir);
}
