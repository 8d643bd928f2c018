// test_alloc.c — the step never allocates (handspring.h: "Never allocates"; docs/model.md §10).
//
// Every heap allocation of the process is counted while a world steps: hand-model worlds (paper
// and support stacking, hands grasping, pushing and throwing), spring worlds (stylus, spring,
// throw, catch, tracker noise, walls, collisions) and every catalog scenario through
// hs_scenario_step. The count must stay 0.
//  - plain build: malloc, calloc, realloc, free and the aligned allocators are interposed here and
//    forward to glibc's __libc_* entry points (glibc routes its own internal calls through them too);
//  - AddressSanitizer build: ASan owns malloc, so its allocator hooks count instead
//    (__sanitizer_install_malloc_and_free_hooks), and the allocated byte total is compared too.
// Either way the counter is proven live first: a counted malloc must register.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "world_internal.h"
#include "test_util.h"

#if defined(__SANITIZE_ADDRESS__)
#define HS_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HS_ASAN 1
#endif
#endif

static volatile int counting;        // count allocations while set
static volatile long allocations;    // malloc, calloc, realloc (any), aligned allocations
static volatile long deallocations;  // free of a non-null pointer

#ifdef HS_ASAN
// the sanitizer's allocator interface (declared here: gcc ships no allocator_interface.h)
int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void *, size_t),
                                              void (*free_hook)(const volatile void *));
size_t __sanitizer_get_current_allocated_bytes(void);

static void on_malloc(const volatile void *ptr, size_t size) {
	(void)ptr;
	(void)size;
	if (counting)
		allocations++;
}

static void on_free(const volatile void *ptr) {
	if (counting && ptr)
		deallocations++;
}

static void install_counter(void) { // once: every installed pair of hooks is called
	static int installed;
	if (!installed)
		assert_true(__sanitizer_install_malloc_and_free_hooks(on_malloc, on_free) != 0);
	installed = 1;
}
static size_t allocated_bytes(void) { return __sanitizer_get_current_allocated_bytes(); }
#else
// glibc's own allocator under its exported names
void *__libc_malloc(size_t size);
void *__libc_calloc(size_t count, size_t size);
void *__libc_realloc(void *ptr, size_t size);
void __libc_free(void *ptr);
void *__libc_memalign(size_t alignment, size_t size);

void *malloc(size_t size) {
	if (counting)
		allocations++;
	return __libc_malloc(size);
}

void *calloc(size_t count, size_t size) {
	if (counting)
		allocations++;
	return __libc_calloc(count, size);
}

void *realloc(void *ptr, size_t size) {
	if (counting)
		allocations++;
	return __libc_realloc(ptr, size);
}

void free(void *ptr) {
	if (counting && ptr)
		deallocations++;
	__libc_free(ptr);
}

void *aligned_alloc(size_t alignment, size_t size) {
	if (counting)
		allocations++;
	return __libc_memalign(alignment, size);
}

int posix_memalign(void **out, size_t alignment, size_t size) {
	if (counting)
		allocations++;
	void *p = __libc_memalign(alignment, size);
	if (!p)
		return 12; // ENOMEM
	*out = p;
	return 0;
}

static void install_counter(void) {}
static size_t allocated_bytes(void) { return 0; }
#endif

static size_t bytes_before;

static void count_begin(void) {
	allocations = 0;
	deallocations = 0;
	bytes_before = allocated_bytes();
	counting = 1;
}

// Stops counting; fails with `what` when anything was allocated or freed.
static void count_end_expect_none(const char *what) {
	counting = 0;
	size_t bytes_after = allocated_bytes();
	if (allocations != 0 || deallocations != 0)
		fail_msg("%s: %ld allocations and %ld frees while stepping", what, allocations, deallocations);
	assert_true(bytes_after == bytes_before);
}

// The counter is live: a malloc made while counting registers (volatile: not optimised away).
static void test_counter_is_live(void **state) {
	(void)state;
	install_counter();
	count_begin();
	void *volatile p = malloc(24);
	void *volatile q = calloc(3, 8);
	p = realloc(p, 4096);
	counting = 0;
	assert_non_null(p);
	assert_non_null(q);
	assert_true(allocations >= 3);
	free(p);
	free(q);
	count_begin();
	count_end_expect_none("nothing");
}

static hs_shape_id add_shape(hs_world *w, hs_shape *shape) {
	assert_non_null(shape);
	hs_shape_id id = hs_world_add_shape(w, shape, NULL);
	hs_shape_destroy(shape);
	assert_int_not_equal(id.index1, 0);
	return id;
}

static hs_object_id add_object(hs_world *w, hs_shape_id shape, hs_vec3 pos, hs_quat rot, hs_vec3 vel) {
	hs_object_def od = hs_default_object_def();
	od.shape = shape;
	od.position = pos;
	od.orientation = rot;
	od.velocity = vel;
	hs_object_id id = hs_world_add_object(w, &od, NULL);
	assert_int_not_equal(id.index1, 0);
	return id;
}

// A hand-model world with every kind of motion: flight, landing, tipping, resting, a hand that
// grasps, lifts and throws a cube, pushes another; objects stacked and interfering.
static void run_hand_world(hs_stacking stacking) {
	hs_world_def def = hs_default_world_def();
	def.stacking = stacking;
	def.max_objects = 12;
	hs_world *w = hs_world_create(&def, NULL);
	assert_non_null(w);
	hs_shape_id cube = add_shape(w, hs_shape_box(hs_v3(0.05, 0.05, 0.05), NULL));
	hs_shape_id box = add_shape(w, hs_shape_box(hs_v3(0.2, 0.1, 0.05), NULL));
	hs_shape_id pyramid = add_shape(w, hs_shape_pyramid(0.1, 0.1, NULL));
	hs_shape_id ell = add_shape(w, hs_shape_ellipsoid(hs_v3(0.06, 0.04, 0.03), NULL));
	hs_shape_id l = add_shape(w, hs_shape_l_block(hs_v3(0.1, 0.05, 0.1), 0.02, NULL));
	hs_shape_id ball = add_shape(w, hs_shape_sphere(0.03, NULL));
	hs_object_id target = add_object(w, cube, hs_v3(0, 0, 0.025), hs_quat_identity(), hs_v3(0, 0, 0));
	add_object(w, cube, hs_v3(0.5, 0, 0.5), hs_quat_from_rpy(0.3, 0.2, 0.1), hs_v3(0.5, 0, 1));
	add_object(w, box, hs_v3(1, 0, 0.09), hs_quat_from_rpy(0, 0.9, 0), hs_v3(0, 0, 0));
	add_object(w, pyramid, hs_v3(1.5, 0, 0.2), hs_quat_from_rpy(3.1, 0, 0), hs_v3(0, 0, 0));
	add_object(w, ell, hs_v3(2, 0, 0.3), hs_quat_identity(), hs_v3(0, 1, 0));
	add_object(w, l, hs_v3(2.5, 0, 0.3), hs_quat_from_rpy(0.5, 0, 0.7), hs_v3(0, 0, 0));
	add_object(w, ball, hs_v3(3, 0, 0.2), hs_quat_identity(), hs_v3(0, 0, 0));
	add_object(w, cube, hs_v3(3.5, 0, 0.025), hs_quat_identity(), hs_v3(0, 0, 0)); // a stack
	add_object(w, cube, hs_v3(3.51, 0, 0.08), hs_quat_identity(), hs_v3(0, 0, 0));
	add_object(w, cube, hs_v3(0.09, 0, 0.025), hs_quat_identity(), hs_v3(0, 0, 0)); // next to the target
	hs_hand_def hd = hs_default_hand_def();
	hs_hand_id hand = hs_world_add_hand(w, &hd, NULL);
	assert_int_not_equal(hand.index1, 0);
	uint8_t wide[HS_GLOVE_SENSORS], grasp[HS_GLOVE_SENSORS], s[HS_GLOVE_SENSORS];
	assert_int_equal(hs_hand_posture(&hd, HS_POSTURE_GRASP, 0.12, wide), HS_OK);
	assert_int_equal(hs_hand_posture(&hd, HS_POSTURE_GRASP, 0.05, grasp), HS_OK);
	hs_vec3 c, axis;
	hs_hand_grip(&hd, grasp, &c, &axis);
	hs_contact contacts[64];
	bool grasped = false;
	size_t state_size = hs_world_state_size(w);
	unsigned char *saved = malloc(state_size);
	assert_non_null(saved);
	count_begin();
	for (int f = 0; f < 400; ++f) {
		double t = (f + 1) / 60.0;
		double down = t < 1.0 ? 0.2 * (1.0 - t) : 0.0, close = t < 1.0 ? 0.0 : (t < 1.5 ? (t - 1.0) * 2.0 : 1.0);
		double lift = t < 1.5 ? 0.0 : (t < 3.0 ? (t - 1.5) * 0.3 : 0.45);
		double side = t < 2.0 ? 0.0 : (t - 2.0) * 2.0; // fast sideways at the end: a throw on release
		if (t > 3.0)
			close = 0.0;
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			s[i] = (uint8_t)(wide[i] + close * (grasp[i] - wide[i]) + 0.5);
		hs_vec3 grip = hs_v3(side, 0, 0.025 + down + lift);
		hs_world_set_hand(w, hand, hs_sub(grip, c), hs_quat_identity(), s);
		assert_int_equal(hs_world_step(w), HS_OK);
		hs_object_state st;
		assert_int_equal(hs_world_object_state(w, target, &st), HS_OK);
		grasped = grasped || st.contact == HS_CONTACT_GRASP;
		hs_world_contacts(w, contacts, 64);
		(void)hs_world_hash(w);
		(void)hs_world_get_counters(w);
		if (f == 200) // saving and loading the state allocate nothing either
			assert_int_equal(hs_world_save_state(w, saved, state_size), HS_OK);
		if (f == 210)
			assert_int_equal(hs_world_load_state(w, saved, state_size), HS_OK);
	}
	count_end_expect_none(stacking == HS_STACKING_PAPER ? "hand world, paper stacking" : "hand world, support stacking");
	free(saved);
	assert_true(grasped); // the run did exercise the grasp
	hs_world_destroy(w);
}

static void test_hand_world_paper(void **state) {
	(void)state;
	install_counter();
	run_hand_world(HS_STACKING_PAPER);
}

static void test_hand_world_support(void **state) {
	(void)state;
	install_counter();
	run_hand_world(HS_STACKING_SUPPORT);
}

// A spring world: pick, lift, swing, throw, catch, drop, collisions, walls, tracker noise.
static void test_spring_world(void **state) {
	(void)state;
	install_counter();
	for (int integrator = 0; integrator < 4; ++integrator) {
		hs_world_def def = hs_default_world_def();
		def.max_objects = 8;
		def.kind = HS_WORLD_SPRING;
		def.spring.integrator = (hs_integrator)integrator;
		def.spring.walls = (hs_spring_walls){true, -1.0, 3.0, -1.0, 1.0};
		hs_world *w = hs_world_create(&def, NULL);
		assert_non_null(w);
		hs_shape_id ball = add_shape(w, hs_shape_sphere(0.05, NULL));
		hs_shape_id box = add_shape(w, hs_shape_box(hs_v3(0.1, 0.1, 0.1), NULL));
		hs_object_id a = add_object(w, ball, hs_v3(0, 0, 0.05), hs_quat_identity(), hs_v3(0, 0, 0));
		add_object(w, box, hs_v3(1, 0, 0.05), hs_quat_identity(), hs_v3(-1, 0, 0));
		add_object(w, ball, hs_v3(0.5, 0.02, 0.5), hs_quat_identity(), hs_v3(0, 0, 0));
		add_object(w, box, hs_v3(2.9, 0, 0.2), hs_quat_identity(), hs_v3(3, 0, 0));
		count_begin();
		for (int f = 0; f < 600; ++f) {
			double t = (f + 1) / 60.0;
			hs_vec3 p = t < 1.0 ? hs_v3(0, 0, 0.05) : t < 3.0 ? hs_v3(0, 0, 0.05 + 0.3 * (t - 1.0)) : hs_v3(3.0 * (t - 3.0), 0, 0.65);
			bool button = t > 0.5 && t < 4.0;
			assert_int_equal(hs_world_set_stylus(w, p, hs_quat_identity(), button), HS_OK);
			assert_int_equal(hs_world_step(w), HS_OK);
			if (f == 300)
				assert_int_equal(hs_world_spring_attach(w, a), HS_OK);
			if (f == 320)
				assert_int_equal(hs_world_spring_detach(w), HS_OK);
			hs_spring_state ss;
			hs_tracker_state ts;
			hs_tracker_sample sample;
			hs_release rel;
			hs_spring_object so;
			assert_int_equal(hs_world_spring_state(w, &ss), HS_OK);
			assert_int_equal(hs_world_tracker_state(w, &ts), HS_OK);
			hs_world_tracker_sample(w, 0, &sample);
			assert_int_equal(hs_world_spring_last_release(w, &rel), HS_OK);
			assert_int_equal(hs_world_spring_object(w, a, &so), HS_OK);
		}
		count_end_expect_none("spring world");
		hs_world_destroy(w);
	}
}

// Every catalog scenario: loading allocates, hs_scenario_step must not.
static void test_catalog_steps(void **state) {
	(void)state;
	install_counter();
	hs_catalog cat;
	hs_error err;
	if (!hs_catalog_load("scenarios", &cat, &err))
		fail_msg("%s", err.message);
	assert_true(cat.count > 0);
	for (int i = 0; i < cat.count; ++i) {
		hs_scenario *s = hs_scenario_load(cat.paths[i], &err);
		if (!s)
			fail_msg("%s", err.message);
		count_begin();
		while (hs_scenario_step(s)) {
		}
		count_end_expect_none(cat.names[i]);
		hs_scenario_destroy(s);
	}
	hs_catalog_free(&cat);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_counter_is_live),  cmocka_unit_test(test_hand_world_paper),
	    cmocka_unit_test(test_hand_world_support), cmocka_unit_test(test_spring_world),
	    cmocka_unit_test(test_catalog_steps),
	};
	return cmocka_run_group_tests_name("alloc", tests, NULL, NULL);
}
