// expect.h — `expect` clauses: what a scenario says must happen, and the checks that test it.
// Every predicate is one row of a table (expect_predicates.c): its name, what it accepts, how its
// value is read, what it captures while the run passes, and how it is judged at the end.
#ifndef HS_HARNESS_EXPECT_H
#define HS_HARNESS_EXPECT_H

#include <stdbool.h>
#include <stdio.h>

#include "handspring.h"
#include "hs_harness.h"

#include "clause.h"

// Records what the expectations need from the scenario's current frame. Never allocates.
void hs_expect_capture(hs_scenario *s);
// One PASS/FAIL line per check to `report` (when not NULL); returns the failures.
int hs_expect_report(const hs_scenario *s, FILE *report);
void hs_expectations_free(hs_expectations *e);
// The line of the first failing clause (only `robust: true` ones when `robust_only`), 0 when none.
unsigned long hs_expect_first_failure(const hs_scenario *s, bool robust_only);

#endif
