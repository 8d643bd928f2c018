// world_step.c — hs_world_step: one frame of the world's own model, the hand or the spring model,
// through that model's pipeline (step.h).
#include "step.h"

hs_status hs_world_step(hs_world *world) {
	if (!world)
		return HS_ERR_INVALID_ARGUMENT;
	if (world->spring) // the workbench model replaces the 1999 motion in its worlds
		hs_step_spring(world);
	else
		hs_step_hand(world);
	return HS_OK;
}
