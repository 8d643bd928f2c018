// world_scratch.h — the world's scratch arena (hs_world_scratch, world_internal.h): every per-step
// scratch array carved from one allocation.
#ifndef HS_WORLD_SCRATCH_H
#define HS_WORLD_SCRATCH_H

#include <stdbool.h>

#include "world_internal.h"

// Makes the arena hold the object-sized arrays (max_objects) and the shape-sized ones for at least
// `vertices`, `faces` and `edges` (and what they held before): a new allocation only when it grows,
// zeroed, the old one freed. False, the arena as it was, when out of memory.
bool hs_world_scratch_reserve(hs_world *world, int vertices, int faces, int edges);
// Frees the arena (the world's other parts untouched).
void hs_world_scratch_free(hs_world *world);

#endif
