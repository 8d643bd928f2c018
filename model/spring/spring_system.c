// spring_system.c — the spring model's system of a spring world (spring_system.h): made with the
// world (hs_world_create, for a world whose kind is HS_WORLD_SPRING) and freed with it. Everything
// a step needs is allocated here, for up to the world's max_objects.
#include <stdlib.h>

#include "spring_system.h"

void hs_spring_system_destroy(hs_spring_system *system) {
	if (!system)
		return;
	free(system->geom);
	free(system->on_floor);
	free(system->sliding);
	free(system->separated);
	hs_hgrid_free(&system->grid);
	free(system->near);
	free(system->touch);
	free(system->events);
	free(system->version);
	free(system->nb);
	free(system->nb_start);
	free(system->nb_pos);
	free(system->box_lo);
	free(system->box_hi);
	free(system->nb_lo);
	free(system->nb_hi);
	free(system->params);
	free(system->params_mass);
	free(system->moved);
	free(system->active);
	free(system->warm);
	free(system->rest_index);
	free(system->rest);
	free(system->load);
	free(system->held);
	free(system);
}

hs_spring_system *hs_spring_system_create(const hs_spring_def *def, int max_objects, double time) {
	hs_spring_system *sys = calloc(1, sizeof *sys);
	if (!sys)
		return NULL;
	size_t cap = max_objects > 0 ? (size_t)max_objects : 1;
	sys->geom = calloc(cap, sizeof *sys->geom);
	sys->on_floor = calloc(cap, sizeof *sys->on_floor);
	sys->sliding = calloc(cap, sizeof *sys->sliding);
	sys->separated = calloc(cap, sizeof *sys->separated);
	sys->near = calloc(cap, sizeof *sys->near);
	sys->nb_capacity = (int)(HS_SPRING_NEAR_PER_OBJECT * cap);
	sys->nb = calloc((size_t)sys->nb_capacity, sizeof *sys->nb);
	sys->nb_start = calloc(cap + 1, sizeof *sys->nb_start);
	sys->nb_pos = calloc(cap, sizeof *sys->nb_pos);
	sys->box_lo = calloc(cap, sizeof *sys->box_lo);
	sys->box_hi = calloc(cap, sizeof *sys->box_hi);
	sys->nb_lo = calloc(cap, sizeof *sys->nb_lo);
	sys->nb_hi = calloc(cap, sizeof *sys->nb_hi);
	sys->moved = calloc(cap, sizeof *sys->moved);
	sys->event_capacity = (int)(HS_SPRING_TOUCHES_PER_OBJECT * cap);
	sys->events = calloc((size_t)sys->event_capacity, sizeof *sys->events);
	sys->version = calloc(cap, sizeof *sys->version);
	sys->params = calloc(cap, sizeof *sys->params);
	sys->params_mass = calloc(cap, sizeof *sys->params_mass);
	sys->touch_capacity = (int)(HS_SPRING_TOUCHES_PER_OBJECT * cap);
	sys->touch = calloc((size_t)sys->touch_capacity, sizeof *sys->touch);
	sys->warm = calloc((size_t)sys->touch_capacity, sizeof *sys->warm);
	sys->active = calloc(cap, sizeof *sys->active);
	sys->rest_index = malloc(cap * sizeof *sys->rest_index);
	for (size_t i = 0; sys->rest_index && i < cap; ++i)
		sys->rest_index[i] = -1;
	for (size_t i = 0; sys->params_mass && i < cap; ++i)
		sys->params_mass[i] = NAN; // no parameters cached
	sys->rest = calloc(cap, sizeof *sys->rest);
	sys->load = calloc(cap, sizeof *sys->load);
	sys->held = calloc(cap, sizeof *sys->held);
	bool grid = hs_hgrid_alloc(&sys->grid, (int)cap, 3);
	sys->grid_count = -1;
	if (!sys->geom || !sys->on_floor || !sys->sliding || !sys->separated ||
	    !sys->near || !sys->nb || !sys->nb_start || !sys->nb_pos || !sys->box_lo || !sys->box_hi || !sys->nb_lo || !sys->nb_hi || !grid || !sys->touch || !sys->warm || !sys->active || !sys->rest_index || !sys->rest || !sys->load ||
	    !sys->held || !sys->events || !sys->version || !sys->params || !sys->params_mass ||
	    !sys->moved) {
		hs_spring_system_destroy(sys);
		return NULL;
	}
	sys->def = *def;
	sys->capacity = (int)cap;
	hs_tracker_init(&sys->tracker, def, time);
	sys->rot = sys->rot_prev = hs_quat_identity();
	sys->attached = -1;
	sys->candidate = -1;
	hs_spring_technique_init(&sys->tech);
	sys->axis = hs_v3(0.0, 0.0, -1.0);
	return sys;
}
