// state.c — PLACEHOLDER until the state block lands: saving and loading are refused.
#include "internal.h"

size_t hs_world_state_size(const hs_world *world) {
	(void)world;
	return 0;
}

hs_status hs_world_save_state(const hs_world *world, void *buffer, size_t size) {
	(void)world, (void)buffer, (void)size;
	return HS_ERR_INVALID_ARGUMENT;
}

hs_status hs_world_load_state(hs_world *world, const void *buffer, size_t size) {
	(void)world, (void)buffer, (void)size;
	return HS_ERR_INVALID_ARGUMENT;
}

const char *hs_world_state_error(const hs_world *world) {
	(void)world;
	return "not implemented";
}
