// cli.h — what the tool's commands share (cli.c): exit statuses, options and usage errors, and a
// scenario run writing its trajectory.
#ifndef HS_TOOL_CLI_H
#define HS_TOOL_CLI_H

#include <stdbool.h>
#include <stdio.h>

#include "hs_harness.h"
#include "outsel.h"

enum { EXIT_PASS = 0, EXIT_FAILED = 1, EXIT_BAD_INPUT = 2 };

// Prints "handspring COMMAND: " and the message (fmt with arg), then the usage; EXIT_BAD_INPUT.
int hs_cli_usage_error(const char *command, const char *usage, const char *fmt, const char *arg);
// --help or -h.
bool hs_cli_is_help(const char *arg);
// "--name VALUE" or "--name=VALUE" at argv[*i]; advances *i past the value.
bool hs_cli_option_value(int argc, char **argv, int *i, const char *name, const char **value, bool *missing);
// A folder option `name` at argv[*i]: true when it was that option (*status set when its value is missing).
bool hs_cli_dir_option(int argc, char **argv, int *i, const char *name, const char **value, int *status,
                       const char *command, const char *usage);
// DIR/NAME.csv (malloc'd; NULL when out of memory).
char *hs_cli_join_csv(const char *dir, const char *name);
// Runs a scenario writing its trajectory to outs[k] (the first one, and `hands`, through `sel`; the
// others whole: goldens).
void hs_cli_run_scenario(hs_scenario *s, FILE **outs, int out_count, FILE *hands, hs_outsel *sel);
// Names a scenario's input files to the output layer, so no output overwrites one (output.h).
void hs_cli_add_inputs(const hs_scenario *s);

#endif
