// scenario_access.c — what a loaded scenario holds and has run so far, asked by the tool, the
// checks, the state file and the warnings: its names, objects, hands, input files, warnings and
// faults. Queries only (and hs_scenario_warn's append); the scenario's life is scenario.c's.
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenario_internal.h"

hs_object_state hs_scenario_state_of(const hs_scenario *s, int object) {
	hs_object_state st;
	memset(&st, 0, sizeof st);
	hs_world_object_state(s->world, s->ids[object], &st);
	return st;
}

int hs_scenario_index_of(const hs_scenario *s, hs_object_id id) {
	return id.index1 >= 1 && id.index1 <= (uint32_t)s->object_count ? (int)id.index1 - 1 : -1;
}

bool hs_scenario_warn(hs_scenario *s, const char *fmt, ...) {
	char line[640];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(line, sizeof line, fmt, ap);
	va_end(ap);
	size_t have = s->warnings ? strlen(s->warnings) : 0, add = strlen(line);
	char *grown = realloc(s->warnings, have + add + 2);
	if (!grown)
		return false;
	memcpy(grown + have, line, add);
	memcpy(grown + have + add, "\n", 2);
	s->warnings = grown;
	return true;
}

const char *hs_scenario_warnings(const hs_scenario *s) { return s && s->warnings ? s->warnings : ""; }

int hs_scenario_hand_count(const hs_scenario *s) { return s ? s->hands.count : 0; }

const char *hs_scenario_hand_name(const hs_scenario *s, int hand) {
	return s && hand >= 0 && hand < s->hands.count ? s->hands.names[hand] : NULL;
}

bool hs_scenario_hand_fit(const hs_scenario *s, int hand, double *rms_mm, long *samples, const char **record) {
	if (!s || hand < 0 || hand >= s->hands.count || !s->hands.fits[hand].joints)
		return false;
	const hs_hand_fit *fit = &s->hands.fits[hand];
	if (rms_mm)
		*rms_mm = fit->rms_mm;
	if (samples)
		*samples = fit->samples;
	if (record)
		*record = fit->record;
	return true;
}

int hs_scenario_input_count(const hs_scenario *s) { return s ? s->inputs.count : 0; }

const char *hs_scenario_input_path(const hs_scenario *s, int i) {
	return s && i >= 0 && i < s->inputs.count ? s->inputs.paths[i] : NULL;
}

const char *hs_scenario_name(const hs_scenario *s) { return s ? s->name : NULL; }
const char *hs_scenario_description(const hs_scenario *s) { return s ? s->description : NULL; }
hs_world *hs_scenario_world(hs_scenario *s) { return s ? s->world : NULL; }
long hs_scenario_frame_count(const hs_scenario *s) { return s ? s->frames : 0; }
double hs_scenario_dt(const hs_scenario *s) { return s ? s->dt : 0.0; }
int hs_scenario_object_count(const hs_scenario *s) { return s ? s->object_count : 0; }

const char *hs_scenario_object_name(const hs_scenario *s, int i) {
	return s && i >= 0 && i < s->object_count ? s->object_names[i] : NULL;
}

// Non-finite values the world caught (and froze) so far: a run with any is not to be trusted. An
// object whose state is not finite now counts as one too, whether or not the world has counted it
// yet (a crafted state file, each of whose numbers the world accepts, can step an object to NaN a
// frame before the world counts it: the report must not pass it).
long hs_scenario_faults(const hs_scenario *s) {
	long faults = hs_world_get_counters(s->world).numeric_faults + s->fault_offset;
	for (int i = 0; faults == 0 && i < s->object_count; ++i) {
		hs_object_state st;
		if (hs_world_object_state(s->world, s->ids[i], &st) == HS_OK &&
		    !(hs_vec3_is_finite(st.position) && hs_quat_is_finite(st.orientation) && hs_vec3_is_finite(st.velocity)))
			faults = 1;
	}
	return faults;
}

int hs_scenario_expectation_count(const hs_scenario *s) {
	return s ? s->expect.check_count + (s->step_status != HS_OK) + (hs_scenario_faults(s) > 0) : 0;
}
