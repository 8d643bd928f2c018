// spring.c — the Responsive Workbench spring model (placeholder until the spring issue lands).
#include <stdlib.h>

#include "internal.h"

void hs_spring_step(hs_world *world) { (void)world; }

void hs_spring_system_destroy(hs_spring_system *system) { free(system); }
