// hand_trace.c — what the hands and the stylus do, per frame, as CSV (`handspring run --hands-out`,
// `handspring all --hands-dir`): the hands' check points where the glove and tracker put them and
// where rectification (1999 paper §3.2, docs/model.md §3) draws them back to an object's surface,
// the contacts of the frame with their objects' contact states (Fig. 12), and in spring worlds the
// stylus, the spring's two ends with its extension, and the selection candidate. One long table,
// a `kind` column saying what a row is, so gnuplot and Python's csv read it as it is. Only the
// public API is used.
#include <inttypes.h>
#include <stdlib.h>

#include "hs_harness.h"

#define HS_TRACE_CONTACTS 64 // contacts kept on the stack; a frame with more takes them from the heap

void hs_hand_trace_write_header(FILE *out) {
	if (out)
		fputs("frame,t,kind,hand,index,x,y,z,u,v,w,flag,object,value\n", out);
}

// 17 significant digits: every double reads back to its bits
static void row(FILE *out, long frame, double t, const char *kind, int hand, int index, hs_vec3 p, hs_vec3 q,
                int flag, const char *object, const char *value) {
	char h[16] = "";
	if (hand >= 0)
		snprintf(h, sizeof h, "%d", hand);
	fprintf(out, "%ld,%.17g,%s,%s,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%s,%s\n", frame, t, kind, h, index, p.x,
	        p.y, p.z, q.x, q.y, q.z, flag, object ? object : "", value ? value : "");
}

static const char *name_of(const hs_scenario *s, const hs_world *w, hs_object_id id) {
	for (int i = 0; i < hs_world_object_count(w); ++i)
		if (hs_world_object_at(w, i).index1 == id.index1)
			return hs_scenario_object_name(s, i);
	return "";
}

static void hands(FILE *out, hs_scenario *s, hs_world *w, long frame, double t) {
	for (int h = 0;; ++h) {
		hs_hand_id id = hs_world_hand_at(w, h);
		if (id.index1 == 0)
			break;
		hs_vec3 p[HS_HAND_POINTS], r[HS_HAND_POINTS];
		uint32_t touching = 0;
		if (hs_world_hand_points(w, id, p) != HS_OK || hs_world_hand_rectified_points(w, id, r, &touching) != HS_OK)
			continue;
		for (int i = 0; i < HS_HAND_POINTS; ++i)
			row(out, frame, t, "point", h, i, p[i], r[i], (int)(touching >> i & 1u), NULL, NULL);
	}
	hs_contact few[HS_TRACE_CONTACTS], *cs = few;
	int n = hs_world_contacts(w, few, HS_TRACE_CONTACTS);
	if (n > HS_TRACE_CONTACTS && (cs = malloc((size_t)n * sizeof *cs)) != NULL) // a crowded frame
		hs_world_contacts(w, cs, n);
	int shown = cs == few && n > HS_TRACE_CONTACTS ? HS_TRACE_CONTACTS : n;
	if (!cs)
		cs = few;
	for (int k = 0; k < shown; ++k) {
		hs_object_state st;
		char state[8] = "";
		if (hs_world_object_state(w, cs[k].object, &st) == HS_OK)
			snprintf(state, sizeof state, "%d", (int)st.contact);
		row(out, frame, t, "contact", (int)cs[k].hand.index1 - 1, cs[k].part, cs[k].point, cs[k].normal,
		    cs[k].edge ? 1 : 0, name_of(s, w, cs[k].object), state);
	}
	if (cs != few)
		free(cs);
}

static void stylus(FILE *out, hs_scenario *s, hs_world *w, long frame, double t) {
	hs_spring_state ss;
	if (!hs_world_springs_enabled(w) || hs_world_spring_state(w, &ss) != HS_OK)
		return;
	const char *attached = ss.attached.index1 ? name_of(s, w, ss.attached) : "";
	char kind[8];
	snprintf(kind, sizeof kind, "%d", (int)ss.attach_kind);
	hs_vec3 axis = hs_quat_rotate(ss.stylus_orientation, hs_v3(1.0, 0.0, 0.0)); // the pointing ray
	row(out, frame, t, "stylus", -1, 0, ss.stylus, axis, ss.button ? 1 : 0, attached, kind);
	hs_object_state st;
	if (ss.attached.index1 && hs_world_object_state(w, ss.attached, &st) == HS_OK) {
		char ext[32];
		snprintf(ext, sizeof ext, "%.17g", ss.extension);
		row(out, frame, t, "spring", -1, 0, ss.anchor, st.position, 1, attached, ext);
	}
	if (ss.candidate.index1 && hs_world_object_state(w, ss.candidate, &st) == HS_OK)
		row(out, frame, t, "candidate", -1, 0, st.position, hs_v3(0.0, 0.0, 0.0), 0, name_of(s, w, ss.candidate), NULL);
}

void hs_hand_trace_write_frame(FILE *out, hs_scenario *scenario) {
	hs_world *world = hs_scenario_world(scenario);
	if (!out || !world)
		return;
	long frame = hs_world_frame(world);
	double t = (double)frame * hs_world_dt(world);
	hands(out, scenario, world, frame, t);
	stylus(out, scenario, world, frame, t);
}
