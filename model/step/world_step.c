// world_step.c — hs_world_step: one frame of the world's own model, fixed by its kind when it was
// made (hs_world_def.kind), through that kind's pipeline (step.h).
#include "step.h"

hs_status hs_world_step(hs_world *world) {
	if (!world)
		return HS_ERR_INVALID_ARGUMENT;
	if (world->model.def.kind == HS_WORLD_SPRING)
		hs_step_spring(world);
	else
		hs_step_hand(world);
	return HS_OK;
}
