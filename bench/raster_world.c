// raster_world.c — one frame of a world drawn with raster.c: the floor, the objects' faces, the
// hands' finger segments and palms (raster.h says what each looks like).
#include <stdlib.h>

#include "raster.h"

#define RW_MAX_VERTICES 1024 // an object with more vertices is drawn as far as this many reach

static void draw_floor(bench_raster *r) {
	hs_vec3 up = hs_v3(0.0, 0.0, 1.0);
	hs_vec3 a = hs_v3(-1.0, 0.0, 0.0), b = hs_v3(1.0, 0.0, 0.0), c = hs_v3(1.0, 2.0, 0.0), d = hs_v3(-1.0, 2.0, 0.0);
	bench_raster_triangle(r, a, b, c, up, 0x707070u);
	bench_raster_triangle(r, a, c, d, up, 0x707070u);
}

static void draw_object(bench_raster *r, const hs_world *world, hs_object_id id) {
	hs_object_state os;
	const hs_shape *shape = hs_world_shape(world, hs_world_object_shape(world, id));
	if (!shape || hs_world_object_state(world, id, &os) != HS_OK)
		return;
	hs_vec3 v[RW_MAX_VERTICES];
	int nv = shape->vertex_count < RW_MAX_VERTICES ? shape->vertex_count : RW_MAX_VERTICES;
	for (int i = 0; i < nv; ++i)
		v[i] = hs_add(os.position, hs_quat_rotate(os.orientation, shape->vertices[i]));
	uint32_t rgb = os.contact == HS_CONTACT_GRASP ? 0xd04030u : os.contact != HS_CONTACT_NONE ? 0xe09030u : 0x4070d0u;
	for (int f = 0; f < shape->face_count; ++f) {
		const hs_face *face = &shape->faces[f];
		const int *idx = &shape->face_vertices[face->first_index];
		hs_vec3 n = hs_quat_rotate(os.orientation, face->normal);
		for (int k = 1; k + 1 < face->index_count; ++k) // a fan from the face's first vertex
			if (idx[0] < nv && idx[k] < nv && idx[k + 1] < nv)
				bench_raster_triangle(r, v[idx[0]], v[idx[k]], v[idx[k + 1]], n, rgb);
	}
}

// A finger segment from a to b: the four sides of a square tube of half-width `radius`.
static void draw_segment(bench_raster *r, hs_vec3 a, hs_vec3 b, double radius) {
	hs_vec3 axis = hs_sub(b, a);
	if (hs_length(axis) <= 0.0)
		return;
	axis = hs_normalize(axis);
	hs_vec3 other = axis.z * axis.z < 0.5 ? hs_v3(0.0, 0.0, 1.0) : hs_v3(1.0, 0.0, 0.0);
	hs_vec3 e[4];
	e[0] = hs_normalize(hs_cross(axis, other));
	e[1] = hs_cross(axis, e[0]);
	e[2] = hs_scale(e[0], -1.0);
	e[3] = hs_scale(e[1], -1.0);
	for (int s = 0; s < 4; ++s) { // side s faces e[s]; its edges lie at e[s] ± e[s + 1]
		hs_vec3 u = hs_scale(hs_add(e[s], e[(s + 1) % 4]), radius), w = hs_scale(hs_sub(e[s], e[(s + 1) % 4]), radius);
		hs_vec3 a0 = hs_add(a, u), a1 = hs_add(a, w), b0 = hs_add(b, u), b1 = hs_add(b, w);
		bench_raster_triangle(r, a0, a1, b1, e[s], 0xe0b090u);
		bench_raster_triangle(r, a0, b1, b0, e[s], 0xe0b090u);
	}
}

// The palm: the polygon of the five finger bases (check points finger × 4), two-sided (the side
// facing away from the eye is culled).
static void draw_palm(bench_raster *r, const hs_vec3 p[HS_HAND_POINTS]) {
	for (int f = 1; f + 1 < 5; ++f) {
		hs_vec3 a = p[0], b = p[f * 4], c = p[(f + 1) * 4];
		hs_vec3 n = hs_cross(hs_sub(b, a), hs_sub(c, a));
		if (hs_length(n) <= 0.0)
			continue;
		n = hs_normalize(n);
		bench_raster_triangle(r, a, b, c, n, 0xd0a080u);
		bench_raster_triangle(r, a, c, b, hs_scale(n, -1.0), 0xd0a080u);
	}
}

static void draw_hand(bench_raster *r, const hs_world *world, hs_hand_id hand, double radius) {
	hs_vec3 p[HS_HAND_POINTS];
	if (hs_world_hand_points(world, hand, p) != HS_OK)
		return;
	for (int f = 0; f < 5; ++f)
		for (int s = 0; s < 3; ++s)
			draw_segment(r, p[f * 4 + s], p[f * 4 + s + 1], radius);
	draw_palm(r, p);
}

uint64_t bench_draw_world(bench_raster *r, const hs_world *world) {
	bench_raster_clear(r);
	draw_floor(r);
	int n = hs_world_object_count(world);
	for (int i = 0; i < n; ++i)
		draw_object(r, world, hs_world_object_at(world, i));
	double radius = hs_default_hand_def().finger_radius;
	for (int h = 0;; ++h) {
		hs_hand_id hand = hs_world_hand_at(world, h);
		if (!hand.index1)
			break;
		draw_hand(r, world, hand, radius);
	}
	return bench_raster_checksum(r);
}
