// world_base.c — what every stage of a step may ask of the world and tell it: the frame, its time,
// the work counters and the numeric faults. It calls nothing, so the stages below the step
// pipelines (step_hand.c, step_spring.c) never call up into them.
#include <string.h>

#include "hs_bench.h"
#include "world_internal.h"

long hs_world_frame(const hs_world *world) { return world ? world->state.frame : 0; }
double hs_world_time(const hs_world *world) { return world ? (double)world->state.frame * world->model.def.dt : 0.0; }
double hs_world_dt(const hs_world *world) { return world ? world->model.def.dt : 0.0; }

void hs_world_note_fault(hs_world_counters *counters, hs_world_state *state, int object) {
	counters->numeric_faults++;
	if (state->first_fault_frame < 0) {
		state->first_fault_frame = state->frame;
		state->first_fault_object = object;
	}
}

hs_status hs_world_first_fault(const hs_world *world, long *frame, hs_object_id *object) {
	if (!world)
		return HS_ERR_INVALID_ARGUMENT;
	if (frame)
		*frame = world->state.first_fault_frame;
	if (object)
		*object = hs_object_handle(&world->model, world->state.first_fault_object);
	return HS_OK;
}

hs_world_counters hs_world_get_counters(const hs_world *world) {
	hs_world_counters none;
	memset(&none, 0, sizeof none);
	return world ? world->counters : none;
}

hs_status hs_world_set_skip_work(hs_world *world, bool on) {
	if (!world || world->model.object_count > 0) // the grid and the awake list are set up as objects come
		return HS_ERR_INVALID_ARGUMENT;
	world->model.skip_work = on;
	return HS_OK;
}

bool hs_world_skip_work(const hs_world *world) { return world && world->model.skip_work; }
