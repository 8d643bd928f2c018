// scenario_warn.c — what a scenario that loads may still mean by mistake, said as warnings
// (hs_scenario_warnings; the run goes on, the tool's --strict refuses it): an object that starts
// under the floor, two objects that overlap a little at the start (more than 1 mm is an error:
// overlap.c), a hand that starts under the floor, a sphere in a world of the hand model (exact
// spheres are the spring model's; scenarios/README.md, "Errors and warnings").
// Touching is not a mistake: stacked objects, objects on the floor and fingers resting on it sit
// at depth 0, and rounding in their poses stays far below the tolerances here.
#include <math.h>

#include "joint_plausible.h"
#include "overlap.h"
#include "scenario_internal.h"
#include "scenario_parser.h"
#include "scenario_warn.h"

// m: how deep a point of one object may lie inside another before it is warned of
#define TOUCH_TOLERANCE 1e-6

static unsigned long line_of(const hs_scenario_parser *p, const yaml_node_t *list, int i) {
	return hs_yaml_line(hs_yaml_item(&p->y, list, i));
}

// The object's lowest point (m): its vertices placed by its pose; a sphere's exact bottom.
static double lowest_z(const hs_world *w, hs_object_id id, bool *sphere) {
	const hs_shape *shape = hs_world_shape(w, hs_world_object_shape(w, id));
	hs_object_state st;
	*sphere = false;
	if (!shape || hs_world_object_state(w, id, &st) != HS_OK)
		return 0.0;
	*sphere = shape->kind == HS_SHAPE_SPHERE;
	if (*sphere)
		return st.position.z - shape->sphere_radius;
	double z = INFINITY;
	for (int v = 0; v < shape->vertex_count; ++v)
		z = fmin(z, st.position.z + hs_quat_rotate(st.orientation, shape->vertices[v]).z);
	return z;
}

// Objects under the floor and spheres in a hand world: the first of each, and how many more.
static void warn_objects(hs_scenario_parser *p, const yaml_node_t *objects, double floor_tolerance) {
	hs_scenario *s = p->s;
	char shown[HS_SHOWN_PATH + 4];
	const char *path = hs_shown_path(p->y.path, shown);
	int under = -1, under_more = 0, sphere = -1, sphere_more = 0;
	double under_z = 0.0;
	for (int i = 0; i < s->object_count; ++i) {
		bool is_sphere;
		double z = lowest_z(s->world, s->ids[i], &is_sphere);
		if (z < -floor_tolerance && under >= 0)
			under_more++;
		if (z < -floor_tolerance && under < 0) {
			under = i;
			under_z = z;
		}
		if (is_sphere && !s->springs && sphere >= 0)
			sphere_more++;
		if (is_sphere && !s->springs && sphere < 0)
			sphere = i;
	}
	if (under >= 0)
		hs_scenario_warn(s, "%s:%lu: warning: object '%s' starts %.3g mm under the floor (its lowest point at z = %.6g m)%s",
		                 path, line_of(p, objects, under), s->object_names[under], -under_z * 1e3, under_z,
		                 under_more ? " (and more objects)" : "");
	if (sphere >= 0)
		hs_scenario_warn(s, "%s:%lu: warning: object '%s' is a sphere, which only a spring world (with a 'stylus') "
		                 "models as one: the hand model uses its 16 x 8 polyhedron%s",
		                 path, line_of(p, objects, sphere), s->object_names[sphere],
		                 sphere_more ? " (and more spheres)" : "");
}

static void warn_overlap(hs_scenario_parser *p, const yaml_node_t *objects) {
	hs_scenario *s = p->s;
	int a, b;
	double depth;
	if (!hs_find_overlap_beyond(s->world, TOUCH_TOLERANCE, &a, &b, &depth))
		return;
	char shown[HS_SHOWN_PATH + 4];
	hs_scenario_warn(s, "%s:%lu: warning: objects '%s' (line %lu) and '%s' overlap at the start: a point of one lies "
	                 "%.3g mm inside the other (touching is fine; more than %g mm is an error)",
	                 hs_shown_path(p->y.path, shown), line_of(p, objects, b), s->object_names[a],
	                 line_of(p, objects, a), s->object_names[b], depth * 1e3, HS_OVERLAP_TOLERANCE * 1e3);
}

// Each hand whose wrist, or more than half of whose check points (finger joints and tips), start
// more than HS_HAND_FLOOR_SLACK under the floor (recorded real hands rest on a table a little below
// it: the tracker's noise).
static void warn_hands(hs_scenario_parser *p, const yaml_node_t *hands) {
	hs_scenario *s = p->s;
	char shown[HS_SHOWN_PATH + 4];
	for (int h = 0; hands && h < s->hands.count; ++h) {
		hs_vec3 wrist, points[HS_HAND_POINTS];
		hs_quat rot;
		uint8_t sensors[HS_GLOVE_SENSORS];
		hs_hand_script_sample(&s->hands.scripts[h], 0.0, &wrist, &rot, sensors);
		hs_hand_kinematics(&s->hands.defs[h], wrist, rot, sensors, points, NULL);
		int under = 0;
		for (int i = 0; i < HS_HAND_POINTS; ++i)
			under += points[i].z < -HS_HAND_FLOOR_SLACK;
		if (wrist.z < -HS_HAND_FLOOR_SLACK || 2 * under > HS_HAND_POINTS)
			hs_scenario_warn(s, "%s:%lu: warning: hand '%s' starts under the floor: its wrist at z = %.3g mm, %d of its "
			                 "%d check points more than %g mm under it",
			                 hs_shown_path(p->y.path, shown), line_of(p, hands, h), s->hands.names[h], wrist.z * 1e3,
			                 under, HS_HAND_POINTS, HS_HAND_FLOOR_SLACK * 1e3);
	}
}

void hs_warn_start(hs_scenario_parser *p, const yaml_node_t *objects, const yaml_node_t *hands, double floor_tolerance) {
	warn_objects(p, objects, floor_tolerance);
	warn_overlap(p, objects);
	warn_hands(p, hands);
}
