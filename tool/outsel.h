// outsel.h — what `run` and `all` write of a run (docs/tool.md): the objects, the frames (every
// Nth, from a time to a time), and progress on stderr for long runs (tool/outsel.c).
#ifndef HS_OUTSEL_H
#define HS_OUTSEL_H

#include <stdbool.h>
#include <stdint.h>

#include "hs_harness.h"

typedef struct hs_outsel {
	const char *objects; // --objects a,b: names, comma-separated (NULL: every object)
	long every;          // --every N: every Nth frame of those kept (1)
	double from, to;     // --from T, --to T: s (to < 0: to the end)
	uint8_t *selected;   // per object of the bound scenario
	long from_frame, to_frame;
	double started, shown; // s: when the run began, when progress was last shown
	bool progress;       // stderr is a terminal
} hs_outsel;

#define HS_OUTSEL_USAGE                                                                                \
	"  --objects A,B      write only these objects' rows (names as in the file)\n"                      \
	"  --every N          write every Nth frame (of those from --from on)\n"                             \
	"  --from T, --to T   write the frames from time T s, up to time T s\n"

void hs_outsel_init(hs_outsel *sel);
// argv[*i] is one of the options above: its value is read (*i advanced). True when it was one;
// then *error is set (with the message) when the value is bad.
bool hs_outsel_option(hs_outsel *sel, int argc, char **argv, int *i, char *error, size_t error_size);
// Resolves the object names and the times for a loaded scenario; false with the message in `error`
// (`lenient`: names the scenario does not have are passed over, as `all` does).
bool hs_outsel_bind(hs_outsel *sel, hs_scenario *scenario, bool lenient, char *error, size_t error_size);
// True when frame `frame` is written.
bool hs_outsel_keep(const hs_outsel *sel, long frame);
// Progress on stderr (a terminal only, once a run has taken over a second): frame of frames.
void hs_outsel_progress(hs_outsel *sel, long frame, long frames);
void hs_outsel_free(hs_outsel *sel);

#endif
