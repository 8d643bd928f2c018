// golden.h — `handspring check` (golden.c): a folder of scenarios against their goldens.
#ifndef HS_GOLDEN_H
#define HS_GOLDEN_H

#include "hs_harness.h"

extern const char *const hs_check_usage;
// `handspring check` with the arguments after `check`; the exit status.
int hs_check_main(int argc, char **argv);

#endif
