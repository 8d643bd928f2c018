// paper_hull.c — data for the 1999 paper's Figs. 5 and 6 (an object on the floor, [H] §4.2), from
// catalog scenarios at chosen frames. From the public state alone (the object's pose and velocity,
// its shape's vertices, hs_object_state.floor_contacts) it finds the floor vertices V_i (within the
// default floor_tolerance of z = 0), their convex hull, Gm (eq. 4 as docs/model.md §5 reads it: the
// step's proposed displacement, v dt + g dt²), G' (eq. 5: G projected onto the floor along Gm) and
// the case: G' inside the hull → stable (Fig. 5(a)); else (1) one vertex, (2) two: G' not between
// the perpendiculars through V1, V2 → (2)-a about the nearer vertex, else (2)-b about the line V1V2,
// (3) more: V1, V2 the two hull vertices nearest G', then as (2). Eq. 6-7 give the turn θ.
// It then steps one frame and checks the model did that (exit 1 if not): stable → unmoved and
// resting; unstable → the pivot vertices stay where they were on the floor, the other floor
// vertices lift, and the object turned about the predicted axis by θ (no more than θ when the turn
// brought another vertex down).
//
// usage: paper_hull OUTDIR — writes OUTDIR/paper_hull.csv (one row per panel),
// OUTDIR/paper_hull_shapes.csv (what each panel draws), OUTDIR/paper_hull.vars and the sidecars
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "hs_harness.h"
#include "plot_run.h"

enum { MAX_V = 64 };
typedef enum { CASE_STABLE, CASE_ONE, CASE_TWO_A, CASE_TWO_B, CASE_MANY } floor_case;
static const char *const case_code[] = {"stable", "1", "2a", "2b", "3"};

typedef struct panel_def {
	const char *scenario, *figure;
	long frame;
	floor_case expect;
} panel_def;

// Each of the paper's cases at a frame where the object is on the floor and the model steps it there
// (scenarios/*.yaml say why each starts as it does).
static const panel_def panels[] = {
	{"box_tip_short", "Fig. 5(a)", 14, CASE_STABLE},          // landed back on its base
	{"box_tip_past", "Fig. 5(b)", 10, CASE_TWO_B},            // on an edge, G' past it
	{"pyramid_apex", "Fig. 6 (1)", 6, CASE_ONE},              // on its apex
	{"l_block_on_end_edge", "Fig. 6 (2)-a", 0, CASE_TWO_A},   // G' beyond one end of its edge
	{"pyramid_edge", "Fig. 6 (2)-b", 2, CASE_TWO_B},          // on an edge, G' over its base
	{"l_block_on_end", "Fig. 6 (3)", 0, CASE_MANY},           // on a face G' lies outside of
};
enum { PANELS = sizeof panels / sizeof panels[0] };

typedef struct p2 {
	double x, y;
} p2;

typedef struct floor_view {
	hs_object_state st;
	hs_vec3 gm;              // eq. 4
	p2 gp;                   // G', eq. 5
	int n, idx[MAX_V];       // the floor vertices: shape vertex indices
	hs_vec3 v[MAX_V];        // and where they are
	int hull_n, hull[MAX_V]; // indices into v, counter-clockwise
	floor_case kase;
	int pair[2];           // rules (2)-(3): V1 (the nearer G') and V2, indices into v
	int pivot_n, pivot[2]; // indices into v: the vertex, or V1 and V2 of the line
	hs_vec3 c, axis;       // eq. 6-7: C (a vertex, or the foot of G on the line) and the unit axis X
	double theta;          // rad
} floor_view;

static hs_vec3 posed(const hs_shape *shape, hs_object_state st, int i) {
	return hs_add(st.position, hs_quat_rotate(st.orientation, shape->vertices[i]));
}

static p2 xy(hs_vec3 v) { return (p2){v.x, v.y}; }

static double cross2(p2 o, p2 a, p2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

static double dist2(p2 a, p2 b) { return hypot(a.x - b.x, a.y - b.y); }

// Andrew's monotone chain on the floor vertices' (x, y): hull indices into v, counter-clockwise,
// collinear and repeated points dropped; its count (1 for a single point).
static int convex_hull(const hs_vec3 *v, int n, int *hull) {
	int order[MAX_V], chain[2 * MAX_V + 1], k = 0;
	for (int i = 0; i < n; ++i) { // insertion sort by x, then y
		int j = i;
		while (j > 0 && (v[order[j - 1]].x > v[i].x || (v[order[j - 1]].x == v[i].x && v[order[j - 1]].y > v[i].y))) {
			order[j] = order[j - 1];
			--j;
		}
		order[j] = i;
	}
	for (int pass = 0; pass < 2; ++pass) { // lower chain, then upper
		int start = k;
		for (int s = 0; s < n; ++s) {
			int i = order[pass ? n - 1 - s : s];
			while (k >= start + 2 && cross2(xy(v[chain[k - 2]]), xy(v[chain[k - 1]]), xy(v[i])) <= 0.0)
				--k;
			chain[k++] = i;
		}
		--k; // each chain's last point starts the other
	}
	if (k == 2 && dist2(xy(v[chain[0]]), xy(v[chain[1]])) == 0.0)
		k = 1;
	memcpy(hull, chain, (size_t)(k > 0 ? k : 1) * sizeof *hull);
	return k > 0 ? k : (n > 0);
}

// Fig. 5: G' inside the hull (a point or a segment holds nothing up); 1e-12 m of rounding allowed.
static bool inside_hull(const floor_view *f) {
	if (f->hull_n < 3)
		return false;
	for (int i = 0; i < f->hull_n; ++i) {
		p2 a = xy(f->v[f->hull[i]]), b = xy(f->v[f->hull[(i + 1) % f->hull_n]]);
		if (cross2(a, b, f->gp) < -1e-12 * dist2(a, b))
			return false;
	}
	return true;
}

// Rule (3): the two hull vertices nearest G', as V1 and V2 (the first of equals wins).
static void nearest_two(const floor_view *f, int *v1, int *v2) {
	*v1 = *v2 = -1;
	for (int i = 0; i < f->hull_n; ++i) {
		int h = f->hull[i];
		double d = dist2(xy(f->v[h]), f->gp);
		if (*v1 < 0 || d < dist2(xy(f->v[*v1]), f->gp)) {
			*v2 = *v1;
			*v1 = h;
		} else if (*v2 < 0 || d < dist2(xy(f->v[*v2]), f->gp)) {
			*v2 = h;
		}
	}
}

// Rules (1)-(3): the case, the pivot and C.
static void classify(floor_view *f) {
	if (inside_hull(f)) {
		f->kase = CASE_STABLE;
		return;
	}
	if (f->hull_n == 1) {
		f->kase = CASE_ONE;
		f->pivot_n = 1;
		f->pivot[0] = f->hull[0];
		f->c = f->v[f->pivot[0]];
		return;
	}
	int a = f->hull[0], b = f->hull[1];
	if (f->hull_n > 2)
		nearest_two(f, &a, &b);
	else if (dist2(xy(f->v[b]), f->gp) < dist2(xy(f->v[a]), f->gp))
		a = f->hull[1], b = f->hull[0];
	f->pair[0] = f->pivot[0] = a;
	f->pair[1] = f->pivot[1] = b;
	p2 v1 = xy(f->v[a]), v2 = xy(f->v[b]);
	double dx = v2.x - v1.x, dy = v2.y - v1.y;
	double u = ((f->gp.x - v1.x) * dx + (f->gp.y - v1.y) * dy) / (dx * dx + dy * dy);
	if (u < 0.0 || u > 1.0) { // (2)-a: G' not between the perpendiculars: rule (1) about V1, the nearer
		f->pivot_n = 1;
		f->c = f->v[a];
	} else { // (2)-b: about the line V1 V2; C the foot of G on it
		f->pivot_n = 2;
		hs_vec3 line = hs_normalize(hs_sub(f->v[b], f->v[a]));
		f->c = hs_add(f->v[a], hs_scale(line, hs_dot(hs_sub(f->st.position, f->v[a]), line)));
	}
	f->kase = f->hull_n > 2 ? CASE_MANY : f->pivot_n == 1 ? CASE_TWO_A : CASE_TWO_B;
}

// Eq. 6-7: Gm = T + R, T ∥ CG; θ = atan(|R| / |CG|) about X through C, X along CG × R (the paper's
// R × T, T pointing from G to C); about a line only R's part across it turns (docs/model.md §5).
static void turn(floor_view *f) {
	hs_vec3 cg = hs_sub(f->st.position, f->c), u = hs_normalize(cg);
	hs_vec3 r = hs_sub(f->gm, hs_scale(u, hs_dot(f->gm, u)));
	if (f->pivot_n == 2) {
		hs_vec3 line = hs_normalize(hs_sub(f->v[f->pivot[1]], f->v[f->pivot[0]]));
		r = hs_sub(r, hs_scale(line, hs_dot(r, line)));
		f->axis = hs_dot(hs_cross(cg, r), line) >= 0.0 ? line : hs_neg(line);
	} else {
		f->axis = hs_normalize(hs_cross(cg, r));
	}
	f->theta = atan(hs_length(r) / hs_length(cg));
}

// The floor as the paper sees it at this frame, from the object's state and its shape.
static floor_view look(hs_world *w, hs_object_id id, const hs_shape *shape) {
	floor_view f = {.kase = CASE_STABLE};
	hs_world_def def = hs_default_world_def(); // the catalog scenarios drawn keep its g and tolerance
	hs_world_object_state(w, id, &f.st);
	for (int i = 0; i < shape->vertex_count && f.n < MAX_V; ++i) {
		hs_vec3 p = posed(shape, f.st, i);
		if (p.z <= def.floor_tolerance) {
			f.idx[f.n] = i;
			f.v[f.n++] = p;
		}
	}
	double dt = hs_world_dt(w);
	f.gm = hs_add(hs_scale(f.st.velocity, dt), hs_scale(def.gravity, dt * dt));
	double s = f.gm.z < 0.0 ? f.st.position.z / -f.gm.z : 0.0; // straight down if Gm does not point down
	f.gp = (p2){f.st.position.x + s * f.gm.x, f.st.position.y + s * f.gm.y};
	f.hull_n = f.n ? convex_hull(f.v, f.n, f.hull) : 0;
	classify(&f);
	if (f.kase != CASE_STABLE)
		turn(&f);
	return f;
}

typedef struct next_view {
	hs_object_state st;
	double turned; // rad
	hs_vec3 axis;  // unit, of the relative turn
	int floor_n;   // vertices on the floor
	bool landed;   // a vertex not on the floor before is now
} next_view;

static next_view step_once(hs_scenario *s, hs_object_id id, const hs_shape *shape, const floor_view *f) {
	next_view nx = {.turned = 0.0};
	hs_scenario_step(s);
	hs_world_object_state(hs_scenario_world(s), id, &nx.st);
	hs_quat dq = hs_quat_mul(nx.st.orientation, hs_quat_conj(f->st.orientation));
	if (dq.w < 0.0)
		dq = hs_q(-dq.w, -dq.x, -dq.y, -dq.z);
	nx.turned = hs_quat_angle(dq);
	double sv = sin(0.5 * nx.turned);
	nx.axis = sv > 0.0 ? hs_scale(hs_v3(dq.x, dq.y, dq.z), 1.0 / sv) : hs_v3(0, 0, 0);
	double tol = hs_default_world_def().floor_tolerance;
	for (int i = 0; i < shape->vertex_count; ++i) {
		if (posed(shape, nx.st, i).z > tol)
			continue;
		nx.floor_n++;
		bool was = false;
		for (int k = 0; k < f->n; ++k)
			was |= f->idx[k] == i;
		nx.landed |= !was;
	}
	return nx;
}

// Says what the model did not do; 1.
__attribute__((format(printf, 1, 2))) static int fail(const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	fputs("paper_hull: ", stderr);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	return 1;
}

// 0 when the model did what the case says; else 1, after saying what it did not.
static int check(const char *name, long frame, const panel_def *p, const floor_view *f, const next_view *nx,
                 const hs_shape *shape) {
	int bad = 0;
	double tol = hs_default_world_def().floor_tolerance;
	if (f->n != f->st.floor_contacts)
		bad |= fail("%s frame %ld: %d floor vertices, the model counts %d\n", name, frame, f->n, f->st.floor_contacts);
	if (f->kase != p->expect)
		bad |= fail("%s frame %ld: case %s, not %s\n", name, frame, case_code[f->kase], case_code[p->expect]);
	if (f->kase == CASE_STABLE) {
		if (hs_distance(nx->st.position, f->st.position) > 1e-12 || nx->turned > 1e-12 || !nx->st.resting)
			bad |= fail("%s frame %ld: stable, but next frame moved %.3g m, turned %.3g rad%s\n", name, frame + 1,
			            hs_distance(nx->st.position, f->st.position), nx->turned,
			            nx->st.resting ? "" : ", not resting");
		return bad;
	}
	for (int k = 0; k < f->n; ++k) {
		hs_vec3 now = posed(shape, nx->st, f->idx[k]);
		bool pivot = false;
		for (int j = 0; j < f->pivot_n; ++j)
			pivot |= dist2(xy(f->v[k]), xy(f->v[f->pivot[j]])) <= 1e-9;
		if (pivot && (hs_distance(now, f->v[k]) > 1e-9 || now.z > tol))
			bad |= fail("%s frame %ld: pivot vertex %d moved %.3g m\n", name, frame + 1, f->idx[k],
			            hs_distance(now, f->v[k]));
		if (!pivot && now.z <= tol)
			bad |= fail("%s frame %ld: vertex %d stayed on the floor\n", name, frame + 1, f->idx[k]);
	}
	bool angle_ok = nx->landed ? nx->turned <= f->theta + 1e-9 : fabs(nx->turned - f->theta) <= 1e-9;
	if (!(nx->turned > 0.0) || hs_dot(nx->axis, f->axis) < 1.0 - 1e-9 || !angle_ok)
		bad |= fail("%s frame %ld: turned %.12g deg about (%.6f %.6f %.6f), eq. 7: %.12g deg about "
		            "(%.6f %.6f %.6f)\n",
		            name, frame + 1, nx->turned * 180.0 / HS_PI, nx->axis.x, nx->axis.y, nx->axis.z,
		            f->theta * 180.0 / HS_PI, f->axis.x, f->axis.y, f->axis.z);
	return bad;
}

// V1, V2, ... : rule (2)'s pair first (rule (3)'s renaming), or rule (1)'s vertex, then the others;
// label[k] is v[k]'s number.
static void number_vertices(const floor_view *f, int *label) {
	int next = 1;
	for (int k = 0; k < f->n; ++k)
		label[k] = 0;
	if (f->kase == CASE_ONE)
		label[f->pivot[0]] = next++;
	else if (f->kase != CASE_STABLE)
		for (int j = 0; j < 2; ++j)
			label[f->pair[j]] = next++;
	for (int k = 0; k < f->n; ++k)
		if (!label[k])
			label[k] = next++;
}

static void edges(FILE *o, int panel, const char *kind, const hs_shape *shape, hs_object_state st) {
	for (int e = 0; e < shape->edge_count; ++e) {
		hs_vec3 a = posed(shape, st, shape->edges[e].a), b = posed(shape, st, shape->edges[e].b);
		fprintf(o, "%d,%s,0,%.9g,%.9g,%.9g,%.9g\n", panel, kind, a.x, a.y, b.x - a.x, b.y - a.y);
	}
}

// What panel `panel` draws, one row each: the outline now and next frame, the hull's edges, the
// floor vertices (numbered), the perpendiculars through V1 and V2 and the pivot.
static void write_shapes(FILE *o, int panel, const floor_view *f, const next_view *nx, const hs_shape *shape) {
	int label[MAX_V];
	number_vertices(f, label);
	edges(o, panel, "outline", shape, f->st);
	edges(o, panel, "next", shape, nx->st);
	for (int i = 0; f->hull_n > 1 && i < f->hull_n; ++i) {
		hs_vec3 a = f->v[f->hull[i]], b = f->v[f->hull[(i + 1) % f->hull_n]];
		if (f->hull_n > 2 || i == 0)
			fprintf(o, "%d,hull,0,%.9g,%.9g,%.9g,%.9g\n", panel, a.x, a.y, b.x - a.x, b.y - a.y);
	}
	for (int k = 0; k < f->n; ++k)
		fprintf(o, "%d,vertex,%d,%.9g,%.9g,0,0\n", panel, label[k], f->v[k].x, f->v[k].y);
	if (f->kase != CASE_STABLE && f->kase != CASE_ONE) { // rule (2)'s perpendiculars through V1 and V2
		int a = f->pair[0], b = f->pair[1];
		hs_vec3 d = hs_normalize(hs_sub(f->v[b], f->v[a]));
		double half = 0.2;
		for (int j = 0; j < 2; ++j) {
			hs_vec3 p = f->v[j ? b : a];
			fprintf(o, "%d,perp,%d,%.9g,%.9g,%.9g,%.9g\n", panel, j + 1, p.x + half * d.y, p.y - half * d.x,
			        -2.0 * half * d.y, 2.0 * half * d.x);
		}
	}
	if (f->pivot_n == 1)
		fprintf(o, "%d,pivot,1,%.9g,%.9g,0,0\n", panel, f->c.x, f->c.y);
	else if (f->pivot_n == 2)
		fprintf(o, "%d,pivot,2,%.9g,%.9g,%.9g,%.9g\n", panel, f->v[f->pivot[0]].x, f->v[f->pivot[0]].y,
		        f->v[f->pivot[1]].x - f->v[f->pivot[0]].x, f->v[f->pivot[1]].y - f->v[f->pivot[0]].y);
}

// The panel's title: the case, then what the model did the next frame (gnuplot string, noenhanced).
static void write_title(FILE *vars, int panel, const panel_def *p, long frame, const floor_view *f,
                        const next_view *nx) {
	double th = f->theta * 180.0 / HS_PI, tu = nx->turned * 180.0 / HS_PI;
	fprintf(vars, "title%d = \"(%c) %s: %s, frame %ld\\n", panel, 'a' + panel - 1, p->figure, p->scenario, frame);
	switch (f->kase) {
	case CASE_STABLE:
		fprintf(vars, "%d floor vertices, G' inside their hull: stable\\nframe %ld: unmoved, resting\"\n", f->n,
		        frame + 1);
		break;
	case CASE_ONE:
		fprintf(vars, "1 floor vertex, (1): turn about V1, θ = %.3f°\\nframe %ld: V1 stays, turned %.3f°\"\n", th,
		        frame + 1, tu);
		break;
	case CASE_TWO_A:
		fprintf(vars,
		        "2 vertices, G' not between the perpendiculars:\\n(2)-a, by (1) about V1, θ = %.3f°; "
		        "frame %ld: V1 stays, V2 lifts, turned %.3f°\"\n",
		        th, frame + 1, tu);
		break;
	case CASE_TWO_B:
		fprintf(vars,
		        "2 vertices, G' between the perpendiculars: (2)-b,\\nabout V1V2, θ = %.3f°; frame %ld: V1, V2 stay, "
		        "turned %.3f°\"\n",
		        th, frame + 1, tu);
		break;
	case CASE_MANY:
		fprintf(vars,
		        "%d vertices, G' outside: (3), V1 V2 nearest G', then (2)-%s,\\nθ = %.3f°; frame %ld: V1%s stay, "
		        "the others lift, turned %.3f°\"\n",
		        f->n, f->pivot_n == 2 ? "b" : "a", th, frame + 1, f->pivot_n == 2 ? ", V2" : "", tu);
		break;
	}
}

// A square view around the outline now and next, and G'.
static void write_range(FILE *vars, int panel, const floor_view *f, const next_view *nx, const hs_shape *shape) {
	double lo[2] = {f->gp.x, f->gp.y}, hi[2] = {f->gp.x, f->gp.y};
	for (int i = 0; i < shape->vertex_count; ++i)
		for (int j = 0; j < 2; ++j) {
			hs_vec3 p = posed(shape, j ? nx->st : f->st, i);
			lo[0] = fmin(lo[0], p.x), hi[0] = fmax(hi[0], p.x);
			lo[1] = fmin(lo[1], p.y), hi[1] = fmax(hi[1], p.y);
		}
	double half = 0.5 * fmax(hi[0] - lo[0], hi[1] - lo[1]) * 1.2 + 0.01;
	double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
	fprintf(vars, "xmin%d = %.6g; xmax%d = %.6g; ymin%d = %.6g; ymax%d = %.6g\n", panel, cx - half, panel, cx + half,
	        panel, cy - half, panel, cy + half);
}

static void write_row(FILE *out, int panel, const panel_def *p, long frame, const floor_view *f, const next_view *nx) {
	fprintf(out, "%d,%s,%ld,%s,%d,%d,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%d,%.12g,%.12g,%.12g,%.12g,%d\n",
	        panel, p->scenario, frame, case_code[f->kase], f->n, f->hull_n, f->st.position.x, f->st.position.y,
	        f->st.position.z, f->gm.x, f->gm.y, f->gm.z, f->gp.x, f->gp.y, f->kase == CASE_STABLE,
	        f->kase == CASE_STABLE ? NAN : f->c.x, f->kase == CASE_STABLE ? NAN : f->c.y,
	        f->kase == CASE_STABLE ? 0.0 : f->theta * 180.0 / HS_PI, nx->turned * 180.0 / HS_PI, nx->floor_n);
}

typedef struct outputs {
	FILE *out, *shapes, *vars;
} outputs;

// One panel: the scenario up to its frame, the floor there, one step, the check, the rest of the run.
static int panel(int k, const outputs *o) {
	const panel_def *p = &panels[k];
	char path[512];
	snprintf(path, sizeof path, "scenarios/%s.yaml", p->scenario);
	hs_scenario *s = plot_run_load(path, 0.0, false, 0);
	if (!s)
		return 1;
	hs_world *w = hs_scenario_world(s);
	hs_object_id id = hs_world_object_at(w, 0);
	const hs_shape *shape = hs_world_shape(w, hs_world_object_shape(w, id));
	while (hs_world_frame(w) < p->frame && hs_scenario_step(s))
		;
	long frame = hs_world_frame(w);
	floor_view f = look(w, id, shape);
	next_view nx = step_once(s, id, shape, &f);
	int bad = frame != p->frame || check(p->scenario, frame, p, &f, &nx, shape);
	write_row(o->out, k + 1, p, frame, &f, &nx);
	write_shapes(o->shapes, k + 1, &f, &nx, shape);
	write_title(o->vars, k + 1, p, frame, &f, &nx);
	write_range(o->vars, k + 1, &f, &nx, shape);
	while (hs_scenario_step(s)) // the rest, so that the scenario's own expectations are judged whole
		;
	int failed = hs_scenario_check(s, NULL);
	if (failed)
		fprintf(stderr, "%s: %d expectation(s) failed\n", p->scenario, failed);
	hs_scenario_destroy(s);
	return bad || failed;
}

static int about(const char *dir) {
	return plot_run_about(
	               dir, "paper_hull",
	               "paper_hull.csv: the 1999 paper's Figs. 5-6 (an object on the floor, §4.2), one row per panel: a\n"
	               "catalog scenario (scenarios/SCENARIO.yaml) at one frame. rule: stable (G' inside the hull), 1,\n"
	               "2a, 2b or 3 (§4.2's cases); floor_vertices: vertices within 1e-6 m of z = 0; hull_vertices: their\n"
	               "convex hull's; gx, gy, gz: G, m; gmx..: Gm = v dt + g dt^2, m (eq. 4, docs/model.md §5); gpx, "
	               "gpy:\n"
	               "G', G projected onto the floor along Gm, m (eq. 5); inside: 1 when G' is inside the hull; cx, cy:\n"
	               "C, the pivot vertex or the foot of G on the line V1V2, m (nan when stable); theta_deg: eq. 7's\n"
	               "turn, deg; turned_deg: the turn the model made in the next frame, deg; next_floor_vertices:\n"
	               "floor vertices after it. The program checks the model's next frame against the case.\n") |
	       plot_run_about(
	               dir, "paper_hull_shapes",
	               "paper_hull_shapes.csv: what each panel of paper_hull.csv draws, seen from above; panel: its\n"
	               "row; kind: outline (the object's edges at the frame), next (at the next frame), hull (an edge of\n"
	               "the floor vertices' convex hull), vertex (floor vertex V_i, i its number: rule (2)'s V1, V2\n"
	               "first), perp (rule (2)'s perpendicular to V1V2 through V_i), pivot (the vertex, i = 1, or the\n"
	               "line V1V2, i = 2, the model turns about next); x, y: a point, m; dx, dy: to the segment's\n"
	               "other end, m (0 for a point)\n");
}

int main(int argc, char **argv) {
	if (argc != 2) {
		fprintf(stderr, "usage: paper_hull OUTDIR\n");
		return 2;
	}
	outputs o = {plot_run_file(argv[1], "paper_hull", "csv"), plot_run_file(argv[1], "paper_hull_shapes", "csv"),
	             plot_run_file(argv[1], "paper_hull", "vars")};
	if (!o.out || !o.shapes || !o.vars)
		return 1;
	fprintf(o.out, "panel,scenario,frame,rule,floor_vertices,hull_vertices,gx,gy,gz,gmx,gmy,gmz,gpx,gpy,inside,cx,cy,"
	               "theta_deg,turned_deg,next_floor_vertices\n");
	fprintf(o.shapes, "panel,kind,i,x,y,dx,dy\n");
	int bad = 0;
	for (int k = 0; k < PANELS; ++k)
		bad |= panel(k, &o);
	bad |= about(argv[1]);
	bad |= (fclose(o.out) != 0) | (fclose(o.shapes) != 0) | (fclose(o.vars) != 0);
	return bad;
}
