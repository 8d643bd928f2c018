// scenario_warn.h — warnings about a scenario's start (scenario_warn.c).
#ifndef HS_HARNESS_SCENARIO_WARN_H
#define HS_HARNESS_SCENARIO_WARN_H

#include "scenario_parser.h"

// Adds a warning (hs_scenario_warn) for each mistake the start of a loaded scenario shows: an
// object under the floor (below -floor_tolerance), two objects overlapping by more than 1 µm, a
// hand's check point under the floor, a sphere in a world without a stylus. `objects` and `hands`
// (NULL: none) are the file's lists, for the lines the warnings name.
void hs_warn_start(hs_scenario_parser *p, const yaml_node_t *objects, const yaml_node_t *hands, double floor_tolerance);

#endif
