// hand_trace.c — the hands' check points per frame as CSV (`handspring run --hands-out`): where
// the glove and tracker put each check point, and where rectification (1999 paper §3.2, docs/model.md
// §3) draws it back to an object's surface. Only the public API is used.
#include <inttypes.h>

#include "hs_harness.h"

void hs_hand_trace_write_header(FILE *out) {
	if (out)
		fputs("frame,t,hand,point,x,y,z,rx,ry,rz,touching\n", out);
}

void hs_hand_trace_write_frame(FILE *out, hs_scenario *scenario) {
	hs_world *world = hs_scenario_world(scenario);
	if (!out || !world)
		return;
	long frame = hs_world_frame(world);
	double t = (double)frame * hs_world_dt(world);
	for (int h = 0;; ++h) {
		hs_hand_id id = hs_world_hand_at(world, h);
		if (id.index1 == 0)
			break;
		hs_vec3 p[HS_HAND_POINTS], r[HS_HAND_POINTS];
		uint32_t touching = 0;
		if (hs_world_hand_points(world, id, p) != HS_OK ||
		    hs_world_hand_rectified_points(world, id, r, &touching) != HS_OK)
			continue;
		for (int i = 0; i < HS_HAND_POINTS; ++i) // 17 significant digits: every double reads back to its bits
			fprintf(out, "%ld,%.17g,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n", frame, t, h, i, p[i].x, p[i].y,
			        p[i].z, r[i].x, r[i].y, r[i].z, (int)(touching >> i & 1u));
	}
}
