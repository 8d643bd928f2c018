// paper_normals.c — data for the 1999 paper's Fig. 4 (the pseudo-normal of an edge and the grasp
// check), from the catalog's hand/two_hands_pass: the first frame a hand touches the block at three
// or more parts, one of them a check line across an edge. For each contact: C, the normal (a face's,
// or the edge's pseudo-normal: the unit vector from G to the foot of the perpendicular from G onto
// the edge line, [H] §3.2), and for an edge the foot; every pair's angle; the block's state. It
// checks each pseudo-normal against the edge's own geometry (to 1e-12; exit 1 if not).
//
// usage: paper_normals OUTDIR [SCENARIO] — writes OUTDIR/paper_normals.csv (one row per contact),
// OUTDIR/paper_normals_edges.csv (the block's edges) and OUTDIR/paper_normals.vars, and sidecars
#include <math.h>
#include <stdio.h>

#include "hs_harness.h"
#include "plot_run.h"

// The foot of the perpendicular from G onto the line through the shape's edge e, world frame.
static hs_vec3 edge_foot(const hs_shape *shape, int e, hs_object_state st) {
	hs_vec3 a = hs_add(st.position, hs_quat_rotate(st.orientation, shape->vertices[shape->edges[e].a]));
	hs_vec3 b = hs_add(st.position, hs_quat_rotate(st.orientation, shape->vertices[shape->edges[e].b]));
	hs_vec3 d = hs_sub(b, a);
	return hs_add(a, hs_scale(d, hs_dot(hs_sub(st.position, a), d) / hs_dot(d, d)));
}

// The first frame with >= 3 contacts on one object, one at an edge; its count, or 0.
static int find_frame(hs_scenario *s, hs_contact *cs, int max, hs_object_id *object) {
	hs_world *w = hs_scenario_world(s);
	while (hs_scenario_step(s)) {
		int n = hs_world_contacts(w, cs, max);
		for (int i = 0; i < n && i < max; ++i) {
			int same = 0;
			for (int j = 0; j < n && j < max; ++j)
				same += cs[j].object.index1 == cs[i].object.index1;
			if (cs[i].edge && same >= 3) {
				*object = cs[i].object;
				int k = 0; // keep that object's contacts only
				for (int j = 0; j < n && j < max; ++j)
					if (cs[j].object.index1 == object->index1)
						cs[k++] = cs[j];
				return k;
			}
		}
	}
	return 0;
}

int main(int argc, char **argv) {
	const char *path;
	FILE *out, *vars;
	int status = plot_run_outputs(argc, argv, "paper_normals", "scenarios/hand/two_hands_pass.yaml", &path, &out, &vars);
	if (status)
		return status;
	hs_scenario *s = plot_run_load(path, 0.0, false, 0);
	FILE *edges = plot_run_file(argv[1], "paper_normals_edges", "csv");
	if (!s || !edges)
		return 1;
	hs_world *w = hs_scenario_world(s);
	hs_contact cs[64];
	hs_object_id id = {0};
	int n = find_frame(s, cs, 64, &id), bad = n == 0;
	hs_object_state st;
	hs_world_object_state(w, id, &st);
	const hs_shape *shape = n ? hs_world_shape(w, hs_world_object_shape(w, id)) : NULL;
	fprintf(out, "contact,part,edge,cx,cy,cz,nx,ny,nz,footx,footy,footz\n");
	for (int i = 0; i < n; ++i) {
		hs_vec3 foot = cs[i].edge ? edge_foot(shape, cs[i].feature, st) : hs_v3(NAN, NAN, NAN);
		if (cs[i].edge && hs_distance(hs_normalize(hs_sub(foot, st.position)), cs[i].normal) > 1e-12) {
			fprintf(stderr, "paper_normals: contact %d: the pseudo-normal is not G's perpendicular to its edge\n", i);
			bad = 1;
		}
		fprintf(out, "%d,%d,%d,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n", i + 1, cs[i].part, cs[i].edge,
		        cs[i].point.x, cs[i].point.y, cs[i].point.z, cs[i].normal.x, cs[i].normal.y, cs[i].normal.z, foot.x,
		        foot.y, foot.z);
	}
	fprintf(edges, "x,y,z,dx,dy,dz\n");
	for (int e = 0; shape && e < shape->edge_count; ++e) {
		hs_vec3 a = hs_add(st.position, hs_quat_rotate(st.orientation, shape->vertices[shape->edges[e].a]));
		hs_vec3 b = hs_add(st.position, hs_quat_rotate(st.orientation, shape->vertices[shape->edges[e].b]));
		fprintf(edges, "%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n", a.x, a.y, a.z, b.x - a.x, b.y - a.y, b.z - a.z);
	}
	double widest = 0.0; // the largest angle between two normals, deg
	char pairs[512] = "";
	size_t len = 0;
	for (int i = 0; i < n; ++i)
		for (int j = i + 1; j < n; ++j) {
			double a = acos(fmax(-1.0, fmin(1.0, hs_dot(cs[i].normal, cs[j].normal)))) * 180.0 / HS_PI;
			widest = fmax(widest, a);
			if (len < sizeof pairs)
				len += (size_t)snprintf(pairs + len, sizeof pairs - len, "%sθ%d%d = %.1f°", len ? ", " : "", i + 1, j + 1, a);
		}
	fprintf(vars, "frame = %ld\nstate = %d\ngx = %.12g\ngy = %.12g\ngz = %.12g\nwidest = %.9g\npairs = \"%s\"\n",
	        hs_world_frame(w), (int)st.contact, st.position.x, st.position.y, st.position.z, widest, pairs);
	bad |= plot_run_about(argv[1], "paper_normals",
	                      "paper_normals.csv: %s, frame %ld: the hand's contacts with one object, one row each\n"
	                      "contact: 1.. ; part: check point 0-19 or check line 20-79; edge: 1 a check line across an edge\n"
	                      "cx, cy, cz: the contact point C, m; nx, ny, nz: the face normal or the edge's pseudo-normal\n"
	                      "footx..: for an edge, the foot of the perpendicular from G onto it, m (the pseudo-normal's\n"
	                      "direction from G); nan for a face\n",
	                      hs_scenario_name(s), hs_world_frame(w)) |
	       plot_run_about(argv[1], "paper_normals_edges",
	                      "paper_normals_edges.csv: the object's edges at that frame, (x, y, z) to (x + dx, ...), m\n");
	fclose(edges);
	fclose(vars);
	while (hs_scenario_step(s)) // the rest of the run, so that its expectations are judged whole
		;
	return plot_run_close(s, out) | bad;
}
