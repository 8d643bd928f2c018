// harness_internal.h — kept only for tests that still include it (tests/test_alloc.c,
// tests/stress.c): it gathers the private headers a test may want. The harness's own files never
// include it; each includes the header of every concept it uses.
#ifndef HS_HARNESS_INTERNAL_H
#define HS_HARNESS_INTERNAL_H

#include "error.h"
#include "hand_script.h"
#include "number.h"
#include "record.h"

#endif
