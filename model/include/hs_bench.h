// hs_bench.h — knobs for benchmarks and tests, not part of the installed API: they change how
// much work a step does, never its result.
//
// Built into libhandspring (the harness and bench/ call it), but this header is not installed:
// a program using the library has no reason to turn the savings off.
#ifndef HANDSPRING_BENCH_H
#define HANDSPRING_BENCH_H

#include <stdbool.h>

#include "handspring.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Bounding-volume rejection, the broad-phase grid and sleeping: on (true) in every new world;
/// off only to measure what they save (every object is looked at every frame, with the same bits).
/// Set before the first object is added: HS_ERR_INVALID_ARGUMENT for a NULL world or a world that
/// has objects.
hs_status hs_world_set_skip_work(hs_world *world, bool on);
/// Whether a world skips work (false for NULL).
bool hs_world_skip_work(const hs_world *world);

#ifdef __cplusplus
}
#endif

#endif
