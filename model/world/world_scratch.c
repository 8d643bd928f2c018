// world_scratch.c — the scratch arena of world_scratch.h. Its size is known when the world is made
// (its objects) and when a shape is added (the largest shape's vertices, faces and edges), so the
// arena is laid out twice: once to measure it, once to carve it.
#include <stddef.h>
#include <stdlib.h>

#include "world_scratch.h"

typedef struct carver {
	char *base; // NULL while measuring
	size_t used;
} carver;

// `count` elements of `size` bytes, each block at the alignment of any type.
static void *take(carver *c, size_t count, size_t size) {
	size_t align = _Alignof(max_align_t);
	size_t at = (c->used + align - 1u) / align * align;
	c->used = at + count * size;
	return c->base ? c->base + at : NULL;
}

static void lay_out(hs_world_scratch *s, carver *c, size_t objects, size_t springs, size_t vertices, size_t faces,
                    size_t edges) {
	s->moved_from = take(c, objects, sizeof *s->moved_from);
	s->posed = take(c, vertices + 1u, sizeof *s->posed); // room for a closing hull point
	s->points = take(c, vertices + 1u, sizeof *s->points);
	s->hull = take(c, vertices + 1u, sizeof *s->hull);
	s->queue = take(c, objects, sizeof *s->queue);
	s->candidates = take(c, objects, sizeof *s->candidates);
	s->found = take(c, objects, sizeof *s->found);
	s->face_pick = take(c, faces, sizeof *s->face_pick);
	s->edge_pick = take(c, edges, sizeof *s->edge_pick);
	s->edge_mark = take(c, edges, sizeof *s->edge_mark);
	s->spring.saved_pos = take(c, springs, sizeof *s->spring.saved_pos);
	s->spring.saved_vel = take(c, springs, sizeof *s->spring.saved_vel);
	s->spring.path_pos = take(c, springs, sizeof *s->spring.path_pos);
	s->spring.path_vel = take(c, springs, sizeof *s->spring.path_vel);
	s->spring.path_t0 = take(c, springs, sizeof *s->spring.path_t0);
	s->spring.layer = take(c, springs, sizeof *s->spring.layer);
	s->spring.in_layer = take(c, springs, sizeof *s->spring.in_layer);
}

static int at_least(int a, int b) { return a > b ? a : b; }

bool hs_world_scratch_reserve(hs_world *world, int vertices, int faces, int edges) {
	hs_world_scratch *s = &world->scratch;
	if (s->arena && vertices <= s->vertex_room && faces <= s->pick_faces && edges <= s->pick_edges)
		return true;
	vertices = at_least(vertices, s->vertex_room);
	faces = at_least(faces, s->pick_faces);
	edges = at_least(edges, s->pick_edges);
	size_t objects = world->model.def.max_objects > 0 ? (size_t)world->model.def.max_objects : 1u;
	size_t springs = world->model.def.kind == HS_WORLD_SPRING ? objects : 0u;
	hs_world_scratch measured = *s;
	carver c = {NULL, 0};
	lay_out(&measured, &c, objects, springs, (size_t)vertices, (size_t)faces, (size_t)edges);
	void *arena = calloc(1, c.used); // zeroed: edge_mark is all 0 between uses
	if (!arena)
		return false;
	free(s->arena);
	s->arena = arena;
	c = (carver){arena, 0};
	lay_out(s, &c, objects, springs, (size_t)vertices, (size_t)faces, (size_t)edges);
	s->vertex_room = vertices;
	s->pick_faces = faces;
	s->pick_edges = edges;
	s->candidate_count = 0;
	s->near = world->cache.every; // `found` moved: no answer points into the old arena
	return true;
}

void hs_world_scratch_free(hs_world *world) {
	free(world->scratch.arena);
	world->scratch = (hs_world_scratch){0};
}
