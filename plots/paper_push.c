// paper_push.c — data for the 1999 paper's Fig. 3 (pushing an object at one point, eq. 1-2), from
// the catalog's hand/push_off_centre: at the first frame the fingertip pushes the box alone, the
// contact point C and where the finger drives it, B (hs_contact.point, .finger), the box's G before
// the step, and eq. 1-2 evaluated on them: CB = T + R, T ∥ CG, R ⊥ CG, θ = atan(|R| / |CG|), axis
// X ∥ R × CG. It then checks the model did exactly that: G moved by T and the box turned by θ (to
// 1e-9 m and 1e-9 rad; exit 1 if not). Also the box's outline (its edges seen from above) before
// that frame, after it and at the end, and the fingertip's path.
//
// usage: paper_push OUTDIR [SCENARIO] — writes OUTDIR/paper_push.csv (the frame's vectors),
// OUTDIR/paper_push_outline.csv (edges and the fingertip's path) and their sidecars .txt
#include <math.h>
#include <stdio.h>

#include "hs_harness.h"
#include "plot_run.h"

// The object's edges seen from above (x, y, dx, dy), tagged with `pose`.
static void outline(FILE *f, const char *pose, const hs_shape *shape, hs_object_state st) {
	for (int e = 0; e < shape->edge_count; ++e) {
		hs_vec3 a = hs_add(st.position, hs_quat_rotate(st.orientation, shape->vertices[shape->edges[e].a]));
		hs_vec3 b = hs_add(st.position, hs_quat_rotate(st.orientation, shape->vertices[shape->edges[e].b]));
		fprintf(f, "%s,%.9g,%.9g,%.9g,%.9g\n", pose, a.x, a.y, b.x - a.x, b.y - a.y);
	}
}

typedef struct push_frame {
	long frame;
	hs_vec3 c, b, g0, g1, t, r, x;
	double theta, turned;
} push_frame;

// Eq. 1-2 on the frame's single contact; the model's own motion of the box beside it.
static push_frame split(long frame, hs_contact c, hs_object_state before, hs_object_state after) {
	push_frame p = {.frame = frame, .c = c.point, .b = c.finger, .g0 = before.position, .g1 = after.position};
	hs_vec3 cb = hs_sub(c.finger, c.point), cg = hs_sub(before.position, c.point);
	hs_vec3 u = hs_normalize(cg);
	p.t = hs_scale(u, hs_dot(cb, u));
	p.r = hs_sub(cb, p.t);
	p.theta = atan(hs_length(p.r) / hs_length(cg));
	p.x = hs_normalize(hs_cross(p.r, cg));
	p.turned = hs_quat_angle(hs_quat_mul(after.orientation, hs_quat_conj(before.orientation)));
	return p;
}

static int write_frame(const char *dir, const push_frame *p, const char *scenario) {
	FILE *f = plot_run_file(dir, "paper_push", "csv");
	if (!f)
		return 1;
	fprintf(f, "frame,cx,cy,cz,bx,by,bz,gx,gy,gz,tx,ty,tz,rx,ry,rz,theta_deg,ax,ay,az,g1x,g1y,g1z,turned_deg\n");
	fprintf(f, "%ld,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,"
	           "%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n",
	        p->frame, p->c.x, p->c.y, p->c.z, p->b.x, p->b.y, p->b.z, p->g0.x, p->g0.y, p->g0.z, p->t.x, p->t.y, p->t.z,
	        p->r.x, p->r.y, p->r.z, p->theta * 180.0 / HS_PI, p->x.x, p->x.y, p->x.z, p->g1.x, p->g1.y, p->g1.z,
	        p->turned * 180.0 / HS_PI);
	return (fclose(f) != 0) |
	       plot_run_about(dir, "paper_push",
	                      "paper_push.csv: %s, the first frame a fingertip pushes the box at one point (state 1)\n"
	                      "one row: frame; C (cx, cy, cz) the contact point, B (bx..) where the finger drives it,\n"
	                      "G (gx..) the box's centre before the step, m; eq. 1: CB = T + R, T (tx..) along CG, R (rx..)\n"
	                      "normal to it, m; eq. 2: theta_deg = atan(|R| / |CG|), deg, about the unit axis (ax, ay, az)\n"
	                      "along R x CG through G; g1x.. the box's centre after the step, m, and turned_deg the angle\n"
	                      "it turned in the step, deg, as the model moved it (checked: G moved by T, turned by theta)\n",
	                      scenario);
}

int main(int argc, char **argv) {
	hs_scenario *s;
	FILE *out;
	int status = plot_run_open(argc, argv, "paper_push_outline", "scenarios/hand/push_off_centre.yaml", &s, &out);
	if (status)
		return status;
	hs_world *w = hs_scenario_world(s);
	hs_object_id id = hs_world_object_at(w, 0);
	const hs_shape *shape = hs_world_shape(w, hs_world_object_shape(w, id));
	fprintf(out, "pose,x,y,dx,dy\n");
	hs_object_state before, after;
	hs_world_object_state(w, id, &before);
	outline(out, "start", shape, before);
	push_frame p = {.frame = -1};
	hs_vec3 tip_prev = hs_v3(NAN, NAN, NAN);
	while (hs_scenario_step(s)) {
		hs_world_object_state(w, id, &after);
		hs_contact cs[64];
		int n = hs_world_contacts(w, cs, 64);
		hs_vec3 pts[HS_HAND_POINTS];
		hs_world_hand_points(w, hs_world_hand_at(w, 0), pts);
		if (!isnan(tip_prev.x) && hs_distance(tip_prev, pts[7]) > 0) // the fingertip's path, frame to frame
			fprintf(out, "tip,%.9g,%.9g,%.9g,%.9g\n", tip_prev.x, tip_prev.y, pts[7].x - tip_prev.x, pts[7].y - tip_prev.y);
		tip_prev = pts[7];
		if (p.frame < 0 && n == 1 && after.contact == HS_CONTACT_PUSH_ONE) {
			p = split(hs_world_frame(w), cs[0], before, after);
			outline(out, "pushed", shape, after);
		}
		before = after;
	}
	outline(out, "end", shape, after);
	int bad = p.frame < 0;
	if (!bad && (hs_distance(hs_add(p.g0, p.t), p.g1) > 1e-9 || fabs(p.turned - p.theta) > 1e-9)) {
		fprintf(stderr, "paper_push: frame %ld: G moved %.3g m from G + T, turned %.12g deg against theta %.12g\n", p.frame,
		        hs_distance(hs_add(p.g0, p.t), p.g1), p.turned * 180.0 / HS_PI, p.theta * 180.0 / HS_PI);
		bad = 1;
	} else if (bad) {
		fprintf(stderr, "paper_push: no frame pushes the object at one point\n");
	}
	if (plot_run_about(argv[1], "paper_push_outline",
	                   "paper_push_outline.csv: %s, seen from above: the box's edges (x, y) to (x + dx, y + dy), m,\n"
	                   "at the start (pose start), after the first push frame (pushed) and at the end (end); the index\n"
	                   "fingertip's path, frame to frame (pose tip)\n",
	                   hs_scenario_name(s)) != 0 || (!bad && write_frame(argv[1], &p, hs_scenario_name(s)) != 0))
		bad = 1;
	return plot_run_close(s, out) | bad;
}
