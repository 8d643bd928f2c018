// view.c — `handspring view FILE`: a scenario drawn in 3-D by gnuplot (splot with polygons), as an
// animated GIF and a filmstrip PNG of chosen times; the replay page (--html) is view_html.c's.
//
// The scenario runs once; the frames to draw are written to a data file in a temporary folder as
// gnuplot blocks, then one gnuplot script draws every output from it. Per frame: each object's
// faces as polygons shaded by the angle to a light (gnuplot 5.4 cannot colour polygons from a
// column, so the faces go to VIEW_SHADES blocks per contact-state colour, each drawn in its
// colour), the hand's 15 finger segments as thick lines and its palm as a polygon, the contact
// points coloured by their object's contact state, the stylus and the spring as a coil; the floor
// and the walls once. A label at the top left gives the time and the contact states.
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hs_harness.h"
#include "output.h"
#include "view.h"
#include "view_html.h"

const char *const hs_view_usage =
    "usage: handspring view FILE [--gif OUT.gif] [--every N] [--strip OUT.png --at T1,T2,...]\n"
    "                            [--html OUT.html] [--html-at T] [--size WxH]\n"
    "Runs the scenario FILE and draws it in 3-D: the objects coloured by contact state (blue none,\n"
    "orange push, green grasp or on the spring, purple push at several points), the hand's finger\n"
    "segments and palm, the contact points, the stylus and the spring as a coil, the walls, the floor.\n"
    "Progress goes to stderr.\n"
    "  --gif OUT.gif     (gnuplot) an animated GIF of the run, every frame or every Nth (--every N);\n"
    "                    the scenario, the time and the contact states at the top left\n"
    "  --strip OUT.png   (gnuplot) a filmstrip: the frames nearest the times --at T1,T2,... (s) side\n"
    "                    by side, each with its time and contact states\n"
    "  --size WxH        pixels per GIF frame or filmstrip panel (default 1024x768)\n"
    "  --html OUT.html   a replay page for a browser, one self-contained file (three.js and the run\n"
    "                    inside; it loads nothing else): drag to turn the view, right-drag to pan,\n"
    "                    the wheel to zoom; play, pause, step back and on, speed and a time slider;\n"
    "                    a contact-state timeline per object under the view, its marker at the\n"
    "                    frame shown; a legend (docs/viewer.md). Every frame or every Nth (--every N)\n"
    "                    and the last; it opens at the frame nearest --html-at T (default the\n"
    "                    first). Needs no gnuplot.\n"
    "Exit status: 0 written, 2 bad input or gnuplot failed (one error line on stderr).\n";

#define VIEW_SHADES 6
#define VIEW_COLOURS 4 // objects by contact state: none, push, grasp, push at several points
#define VIEW_MAX_TIMES 16

static const char *const state_rgb[VIEW_COLOURS][2] = { // [state] = {dark, light}
    {"#2b4a6f", "#9cc3ea"}, {"#8a4b12", "#f3b072"}, {"#1f6b2c", "#8fdc98"}, {"#7a2a6b", "#e59fd6"}};
static const char *const state_name[VIEW_COLOURS] = {"none", "push", "grasp", "push at several points"};

typedef struct view_opts {
	const char *file, *gif, *strip, *html;
	int every;             // GIF: every Nth frame
	double at[VIEW_MAX_TIMES];
	int at_count;          // filmstrip times (s)
	double html_at;        // s: the page opens at the frame nearest it; < 0: the first
	int width, height;
} view_opts;

typedef struct view_run {
	char dir[64];          // the temporary folder: one data file per frame drawn (gnuplot reads a
	                       // file from its start for an `index`: one file for all would be quadratic)
	FILE *data;            // the frame being written
	long records;          // frames written
	hs_vec3 lo, hi;        // bounds of everything drawn
	char (*titles)[160];
	long *frames;          // frame of each record
	long capacity;
} view_run;

static void grow(view_run *v, hs_vec3 p) {
	v->lo = hs_v3(fmin(v->lo.x, p.x), fmin(v->lo.y, p.y), fmin(v->lo.z, p.z));
	v->hi = hs_v3(fmax(v->hi.x, p.x), fmax(v->hi.y, p.y), fmax(v->hi.z, p.z));
}

static void point(view_run *v, hs_vec3 p) {
	fprintf(v->data, "%.9g %.9g %.9g\n", p.x, p.y, p.z);
	grow(v, p);
}

// A line segment as one row `x y z dx dy dz`, drawn `with vectors nohead`: segments apart in
// rows, never in scans that splot would join with lines across them.
static void segment(view_run *v, hs_vec3 a, hs_vec3 b) {
	fprintf(v->data, "%.9g %.9g %.9g %.9g %.9g %.9g\n", a.x, a.y, a.z, b.x - a.x, b.y - a.y, b.z - a.z);
	grow(v, a);
	grow(v, b);
}

static void end_block(FILE *f, bool empty) {
	if (empty)
		fputs("NaN NaN NaN\n", f);
	fputs("\n\n", f);
}

// The faces of every object, into VIEW_COLOURS × VIEW_SHADES blocks.
static void objects(view_run *v, hs_world *w) {
	hs_vec3 light = hs_normalize(hs_v3(-0.4, -0.6, 1.0));
	for (int c = 0; c < VIEW_COLOURS; ++c)
		for (int s = 0; s < VIEW_SHADES; ++s) {
			bool empty = true;
			for (int i = 0; i < hs_world_object_count(w); ++i) {
				hs_object_id id = hs_world_object_at(w, i);
				hs_object_state st;
				hs_world_object_state(w, id, &st);
				const hs_shape *shape = hs_world_shape(w, hs_world_object_shape(w, id));
				if (!shape || (int)st.contact != c)
					continue;
				for (int f = 0; f < shape->face_count; ++f) {
					const hs_face *face = &shape->faces[f];
					double lit = fmax(0.0, hs_dot(hs_quat_rotate(st.orientation, face->normal), light));
					int shade = (int)(lit * (VIEW_SHADES - 1) + 0.5);
					if (shade != s)
						continue;
					for (int k = 0; k < face->index_count; ++k) {
						hs_vec3 p = shape->vertices[shape->face_vertices[face->first_index + k]];
						point(v, hs_add(st.position, hs_quat_rotate(st.orientation, p)));
					}
					fputc('\n', v->data);
					empty = false;
				}
			}
			end_block(v->data, empty);
		}
}

// The hands: 15 segments, the palm through the fingers' bases, the contacts.
static void hands(view_run *v, hs_world *w) {
	bool empty = true;
	for (int h = 0;; ++h) {
		hs_hand_id id = hs_world_hand_at(w, h);
		hs_vec3 p[HS_HAND_POINTS];
		if (id.index1 == 0 || hs_world_hand_points(w, id, p) != HS_OK)
			break;
		for (int f = 0; f < 5; ++f)
			for (int j = 0; j < 3; ++j)
				segment(v, p[f * 4 + j], p[f * 4 + j + 1]);
		empty = false;
	}
	end_block(v->data, empty);
	empty = true;
	for (int h = 0;; ++h) {
		hs_hand_id id = hs_world_hand_at(w, h);
		hs_vec3 p[HS_HAND_POINTS];
		if (id.index1 == 0 || hs_world_hand_points(w, id, p) != HS_OK)
			break;
		for (int f = 0; f < 5; ++f)
			point(v, p[f * 4]);
		fputc('\n', v->data);
		empty = false;
	}
	end_block(v->data, empty);
	hs_contact cs[256];
	int n = hs_world_contacts(w, cs, 256);
	for (int k = 0; k < n && k < 256; ++k) {
		hs_object_state st;
		hs_world_object_state(w, cs[k].object, &st);
		fprintf(v->data, "%.9g %.9g %.9g %d\n", cs[k].point.x, cs[k].point.y, cs[k].point.z, (int)st.contact);
	}
	end_block(v->data, n == 0);
}

// The stylus (its pointing ray, 10 cm) and the spring as a coil from its anchor to G.
static void stylus(view_run *v, hs_world *w, hs_spring_state *ss, bool *attached) {
	*attached = false;
	if (!hs_world_springs_enabled(w) || hs_world_spring_state(w, ss) != HS_OK) {
		end_block(v->data, true);
		return;
	}
	segment(v, ss->stylus, hs_add(ss->stylus, hs_scale(hs_quat_rotate(ss->stylus_orientation, hs_v3(1, 0, 0)), 0.1)));
	hs_object_state st;
	if (ss->attached.index1 && hs_world_object_state(w, ss->attached, &st) == HS_OK) {
		*attached = true;
		hs_vec3 a = ss->anchor, d = hs_sub(st.position, a);
		double len = hs_length(d);
		hs_vec3 u = len > 0.0 ? hs_scale(d, 1.0 / len) : hs_v3(0, 0, -1);
		hs_vec3 e1 = hs_normalize(hs_cross(u, fabs(u.x) < 0.9 ? hs_v3(1, 0, 0) : hs_v3(0, 1, 0))), e2 = hs_cross(u, e1);
		double r = 0.01;
		hs_vec3 last = a;
		for (int k = 0; k <= 96; ++k) { // 8 turns
			double s = (double)k / 96.0, phi = 2.0 * HS_PI * 8.0 * s;
			hs_vec3 q = hs_add(hs_add(a, hs_scale(d, s)), hs_add(hs_scale(e1, r * cos(phi)), hs_scale(e2, r * sin(phi))));
			if (k > 0)
				segment(v, last, q);
			last = q;
		}
	}
	end_block(v->data, false);
}

// One frame: its blocks and its title.
static void record(view_run *v, hs_scenario *s) {
	hs_world *w = hs_scenario_world(s);
	if (v->records == v->capacity) {
		long cap = v->capacity ? 2 * v->capacity : 256;
		void *t = realloc(v->titles, (size_t)cap * sizeof *v->titles), *f = realloc(v->frames, (size_t)cap * sizeof *v->frames);
		if (!t || !f) {
			fprintf(stderr, "handspring view: out of memory\n");
			exit(2);
		}
		v->titles = t;
		v->frames = f;
		v->capacity = cap;
	}
	char path[96];
	snprintf(path, sizeof path, "%s/r%06ld.dat", v->dir, v->records);
	if (!(v->data = fopen(path, "w"))) {
		fprintf(stderr, "handspring view: cannot write %s: %s\n", path, strerror(errno));
		exit(2);
	}
	objects(v, w);
	hands(v, w);
	hs_spring_state ss;
	bool attached;
	stylus(v, w, &ss, &attached);
	if (fclose(v->data) != 0) {
		fprintf(stderr, "handspring view: cannot write %s: %s\n", path, strerror(errno));
		exit(2);
	}
	v->data = NULL;
	long frame = hs_world_frame(w);
	char *title = v->titles[v->records];
	int len = snprintf(title, 160, "t = %.3f s", (double)frame * hs_world_dt(w));
	for (int i = 0; i < hs_world_object_count(w) && len < 150; ++i) {
		hs_object_state st;
		hs_world_object_state(w, hs_world_object_at(w, i), &st);
		if (st.contact != HS_CONTACT_NONE)
			len += snprintf(title + len, (size_t)(160 - len), "  %s: %s", hs_scenario_object_name(s, i),
			                attached ? "spring" : state_name[st.contact]);
	}
	if (attached && len < 150)
		snprintf(title + len, (size_t)(160 - len), "  ext %.3f m", ss.extension);
	v->frames[v->records++] = frame;
}

static void splot(FILE *g, const char *dir, long r) {
	char data[96];
	snprintf(data, sizeof data, "%s/r%06ld.dat", dir, r);
	fputs("splot ", g);
	for (int c = 0; c < VIEW_COLOURS; ++c)
		for (int s = 0; s < VIEW_SHADES; ++s) {
			int b = c * VIEW_SHADES + s;
			fprintf(g, "'%s' index %d with polygons fs solid 1.0 noborder fc rgb mix(%d) notitle, ", data, b, b);
		}
	int h = VIEW_COLOURS * VIEW_SHADES; // then the hand, the palm, the contacts, the stylus
	fprintf(g, "'%s' index %d using 1:2:3:4:5:6 with vectors nohead lw 5 lc rgb '#c98e6b' notitle, ", data, h);
	fprintf(g, "'%s' index %d with polygons fs solid 1.0 noborder fc rgb '#e0b392' notitle, ", data, h + 1);
	fprintf(g, "'%s' index %d using 1:2:3:(col($4)) with points pt 7 ps 1.2 lc rgb variable notitle, ", data, h + 2);
	fprintf(g, "'%s' index %d using 1:2:3:4:5:6 with vectors nohead lw 2 lc rgb '#333333' notitle, ", data, h + 3);
	fprintf(g, "floor using 1:2:3:4:5:6 with vectors nohead lw 0.5 lc rgb '#b0b0b0' notitle, walls using 1:2:3:4:5:6 with "
	           "vectors nohead lw 1.5 lc rgb '#808080' notitle\n");
}

// The floor as a grid of lines (drawn over nothing: a filled floor would hide what rests on it in
// the depth sort), about 10 lines each way at a round spacing, and the walls of a spring world
// (§4.5) as their outlines 0.3 m high; one segment per row (`with vectors`), so splot joins none.
static void floor_and_walls(FILE *g, hs_vec3 lo, hs_vec3 hi, const hs_world *w) {
	double side = fmax(hi.x - lo.x, hi.y - lo.y), step = pow(10.0, floor(log10(side / 10.0)));
	while (side / step > 12.0)
		step *= 2.0;
	double x0 = step * ceil(lo.x / step), y0 = step * ceil(lo.y / step);
	fputs("$floor << EOD\n", g);
	for (double x = x0; x <= hi.x + 1e-9; x += step)
		fprintf(g, "%.9g %.9g 0 0 %.9g 0\n", x, lo.y, hi.y - lo.y);
	for (double y = y0; y <= hi.y + 1e-9; y += step)
		fprintf(g, "%.9g %.9g 0 %.9g 0 0\n", lo.x, y, hi.x - lo.x);
	fputs("EOD\nfloor = '$floor'\n", g);
	hs_spring_def sd;
	fputs("$walls << EOD\n", g);
	if (hs_world_spring_def(w, &sd) == HS_OK && sd.walls.enabled) {
		double xs[5] = {sd.walls.x_min, sd.walls.x_max, sd.walls.x_max, sd.walls.x_min, sd.walls.x_min};
		double ys[5] = {sd.walls.y_min, sd.walls.y_min, sd.walls.y_max, sd.walls.y_max, sd.walls.y_min};
		for (int k = 0; k < 4; ++k) // the bottom, the top and the upright at each corner
			for (int z = 0; z < 3; ++z)
				fprintf(g, "%.9g %.9g %g %.9g %.9g %g\n", xs[k], ys[k], z == 1 ? 0.3 : 0.0, z == 2 ? 0.0 : xs[k + 1] - xs[k],
				        z == 2 ? 0.0 : ys[k + 1] - ys[k], z == 2 ? 0.3 : 0.0);
	} else {
		fputs("NaN NaN NaN\n", g);
	}
	fputs("EOD\nwalls = '$walls'\n", g);
}

// A title as a gnuplot string: quotes and backslashes out, the parts (split at two spaces) wrapped
// into lines of at most `width` characters, so a narrow picture shows the whole of it.
static void gp_title(FILE *g, const char *title, int width) {
	fputc('"', g);
	int line = 0;
	for (const char *p = title; *p;) {
		const char *next = strstr(p, "  ");
		int len = next ? (int)(next - p) : (int)strlen(p);
		if (p != title)
			fputs(line > 0 && line + 2 + len > width ? (line = 0, "\\n") : (line += 2, "  "), g);
		for (int k = 0; k < len; ++k)
			fputc(p[k] == '"' || p[k] == '\\' ? '_' : p[k], g);
		line += len;
		p += len;
		while (*p == ' ')
			++p;
	}
	fputs("\"\n", g);
}

// Framed on everything drawn (objects, hands, stylus, walls) and the floor under it: the scene's
// box (a tenth of its width more on each side, down to the floor) centred in a cube of ranges,
// the view's scale raised from 1.45 (where the whole cube fits) by as much as the box's projected
// half-width and half-height let it, at this view (62° from the vertical, turned 28° about z).
// The floor patch is lo..hi in x and y.
static void set_view(FILE *g, const view_run *v, double width, double height, hs_vec3 *lo, hs_vec3 *hi) {
	hs_vec3 e = hs_sub(v->hi, v->lo), c = hs_scale(hs_add(v->lo, v->hi), 0.5);
	double m = 0.1 * fmax(fmax(e.x, e.y), 0.1), z0 = fmin(0.0, v->lo.z);
	hs_vec3 b = hs_v3(0.5 * e.x + m, 0.5 * e.y + m, 0.5 * (v->hi.z - z0) + 0.02 * m); // half-extents
	double half = fmax(fmax(b.x, b.y), b.z), zc = z0 + b.z;
	double cz = cos(28.0 * HS_PI / 180.0), sz = sin(28.0 * HS_PI / 180.0), cx = cos(62.0 * HS_PI / 180.0), sx = sin(62.0 * HS_PI / 180.0);
	double w_box = b.x * cz + b.y * sz, h_box = (b.x * sz + b.y * cz) * cx + b.z * sx;
	// gnuplot draws a unit of the cube's half-side 0.144 × scale × the picture's width long, across and
	// up (measured): the box's half-width within 0.42 of the width, its half-height within 0.4 of
	// the plot's height (0.9 of the picture's: a tenth for the title)
	double k = 0.144 / half, scale = fmin(0.42 / (k * w_box), 0.4 * 0.9 * height / width / (k * h_box));
	*lo = hs_v3(c.x - b.x, c.y - b.y, z0);
	*hi = hs_v3(c.x + b.x, c.y + b.y, z0 + 2.0 * b.z);
	fprintf(g, "set encoding utf8\nset view 62, 28, %.4f\nset view equal xyz\nunset border\nunset tics\nunset key\n", scale);
	fprintf(g, "set xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\nset zrange [%.9g:%.9g]\nset xyplane at 0\n", c.x - half,
	        c.x + half, c.y - half, c.y + half, zc - half, zc + half);
}

static void script(FILE *g, const view_run *v, const char *name, const hs_world *w, int width, int height) {
	hs_vec3 lo, hi;
	set_view(g, v, width, height, &lo, &hi);
	fprintf(g, "set pm3d depthorder\narray col[4] = [%s, %s, %s, %s]\n", "0x3b6ea5", "0xe07b22", "0x2e9e44", "0xb03a9a");
	fprintf(g, "array shade[%d]\n", VIEW_COLOURS * VIEW_SHADES);
	for (int k = 0; k < VIEW_COLOURS; ++k) { // dark to light per contact state
		unsigned dark = (unsigned)strtoul(state_rgb[k][0] + 1, NULL, 16), light = (unsigned)strtoul(state_rgb[k][1] + 1, NULL, 16);
		for (int s = 0; s < VIEW_SHADES; ++s) {
			double t = (double)s / (VIEW_SHADES - 1);
			unsigned rgb = 0;
			for (int ch = 16; ch >= 0; ch -= 8) {
				double a = (double)(dark >> ch & 255u), b = (double)(light >> ch & 255u);
				rgb |= (unsigned)(a + t * (b - a) + 0.5) << ch;
			}
			fprintf(g, "shade[%d] = %u\n", k * VIEW_SHADES + s + 1, rgb);
		}
	}
	fputs("mix(i) = shade[i + 1]\ncol(s) = col[int(s) + 1]\n", g);
	floor_and_walls(g, lo, hi, w);
	int chars = width / 7; // at 10 points
	fputs("name = ", g);
	gp_title(g, name, chars);
	fprintf(g, "array title[%ld]\n", v->records);
	for (long r = 0; r < v->records; ++r) {
		fprintf(g, "title[%ld] = ", r + 1);
		gp_title(g, v->titles[r], chars);
	}
}

// The record nearest time t.
static long nearest(const view_run *v, double t, double dt) {
	long best = 0;
	for (long r = 1; r < v->records; ++r)
		if (fabs((double)v->frames[r] * dt - t) < fabs((double)v->frames[best] * dt - t))
			best = r;
	return best;
}

static bool wanted(const view_opts *o, long frame, long frames, double dt) {
	if (o->gif && frame % o->every == 0)
		return true;
	for (int k = 0; k < o->at_count; ++k)
		if (llround(o->at[k] / dt) == frame || (frame == frames && llround(o->at[k] / dt) > frames))
			return true;
	return false;
}

static int draw(const view_opts *o, const view_run *v, const char *data, hs_world *w, const char *name) {
	FILE *g = popen("gnuplot", "w");
	if (!g) {
		fprintf(stderr, "handspring view: cannot start gnuplot: %s\n", strerror(errno));
		return 2;
	}
	script(g, v, name, w, o->width, o->height);
	double dt = hs_world_dt(w);
	if (o->gif) {
		int delay = (int)fmax(2.0, 100.0 * dt * o->every + 0.5);
		fprintf(g, "set terminal gif animate delay %d size %d,%d\nset output '%s'\n", delay, o->width, o->height, o->gif);
		fputs("set size 1, 0.9\n", g); // the top tenth for the title
		long n = 0;
		for (long r = 0; r < v->records; ++r)
			if (v->frames[r] % o->every == 0) {
				fprintf(g, "set label 1 name.\"\\n\".title[%ld] at screen 0.01, screen 0.98 left front noenhanced\n", r + 1);
				splot(g, data, r);
				if (++n % 25 == 0)
					fprintf(g, "print 'handspring view: %ld GIF frames drawn'\n", n);
			}
		fputs("set output\n", g);
	}
	if (o->strip) {
		fprintf(g, "set terminal pngcairo size %d,%d font 'sans,10'\nset output '%s'\nset multiplot\n", o->width * o->at_count,
		        o->height, o->strip);
		for (int k = 0; k < o->at_count; ++k) { // each panel's title left-aligned in its own top tenth
			long r = nearest(v, o->at[k], dt);
			double x = (double)k / o->at_count;
			fprintf(g, "set origin %.9g, 0\nset size %.9g, 0.9\n", x, 1.0 / o->at_count);
			fprintf(g, "set label 1 title[%ld] at screen %.9g, screen 0.98 left front noenhanced\n", r + 1, x + 0.01 / o->at_count);
			splot(g, data, r);
		}
		fputs("unset multiplot\nset output\n", g);
	}
	int rc = pclose(g);
	if (rc != 0) {
		fprintf(stderr, "handspring view: gnuplot failed (status %d)\n", rc);
		return 2;
	}
	return 0;
}

// gnuplot draws into the temporary folder; each picture is then checked whole (a GIF ends with its
// trailer byte, a PNG with its IEND chunk: gnuplot does not report a short
// write) and copied to its path through the tool's writer (output.h), which checks every write.
static bool complete(const char *path, const char *ext) {
	FILE *f = fopen(path, "rb");
	unsigned char end[16] = {0};
	long size = -1;
	if (f && fseek(f, 0, SEEK_END) == 0 && (size = ftell(f)) >= 16 && fseek(f, -16, SEEK_END) == 0 &&
	    fread(end, 1, 16, f) != 16)
		size = -1;
	if (f)
		fclose(f);
	if (size < 16)
		return false;
	if (strcmp(ext, "gif") == 0)
		return end[15] == 0x3B;
	return memcmp(end + 8, "IEND\xae\x42\x60\x82", 8) == 0;
}

static bool deliver(const char *dir, const char *ext, const char *to) {
	char from[96];
	snprintf(from, sizeof from, "%s/out.%s", dir, ext);
	if (!complete(from, ext)) {
		fprintf(stderr, "handspring view: gnuplot did not finish %s (is the temporary folder's disk full?)\n", to);
		remove(from);
		return false;
	}
	FILE *in = fopen(from, "rb");
	output o;
	memset(&o, 0, sizeof o);
	bool ok = in && output_open(&o, to);
	if (!in)
		fprintf(stderr, "handspring view: cannot read back %s: %s\n", from, strerror(errno));
	else if (!ok)
		fprintf(stderr, "handspring: %s\n", o.error);
	char buf[1 << 16];
	size_t n;
	while (ok && (n = fread(buf, 1, sizeof buf, in)) > 0)
		fwrite(buf, 1, n, o.file); // a failed write sets the stream's error: output_close reports it
	if (ok && ferror(in)) {
		fprintf(stderr, "handspring view: cannot read back %s\n", from);
		output_close(&o, false);
		ok = false;
	} else if (ok && !output_close(&o, true)) {
		fprintf(stderr, "handspring: %s\n", o.error);
		ok = false;
	}
	if (in)
		fclose(in);
	output_free(&o);
	remove(from);
	return ok;
}

// The scenario's files are inputs: no picture may overwrite one (checked before the run).
static bool outputs_allowed(const view_opts *o, const hs_scenario *s) {
	const char *outs[3] = {o->gif, o->strip, o->html};
	for (int i = 0; i < hs_scenario_input_count(s); ++i)
		output_input(hs_scenario_input_path(s, i));
	for (int k = 0; k < 3; ++k) {
		char why[512];
		if (outs[k] && !output_check(outs[k], why, sizeof why)) {
			fprintf(stderr, "handspring: %s\n", why);
			return false;
		}
	}
	return true;
}

// gnuplot draws every picture into the temporary folder; each is then delivered to its path.
static int draw_and_deliver(const view_opts *o, const view_run *v, const char *dir, hs_world *w, const char *name) {
	view_opts drawn = *o;
	char temp[2][96];
	static const char *const ext[2] = {"gif", "png"};
	for (int k = 0; k < 2; ++k)
		snprintf(temp[k], sizeof temp[k], "%s/out.%s", dir, ext[k]);
	drawn.gif = o->gif ? temp[0] : NULL;
	drawn.strip = o->strip ? temp[1] : NULL;
	int status = draw(&drawn, v, dir, w, name);
	const char *outs[2] = {o->gif, o->strip};
	for (int k = 0; k < 2; ++k)
		if (outs[k] && (status != 0 || !deliver(dir, ext[k], outs[k]))) {
			remove(temp[k]);
			status = 2;
		}
	return status;
}

// Runs the scenario, keeping the frames each output wants: gnuplot's data files, the page's JSON
// (every --every-th frame and the last).
static void run_and_record(const view_opts *o, view_run *v, view_html *page, hs_scenario *s) {
	hs_world *w = hs_scenario_world(s);
	long frames = hs_scenario_frame_count(s);
	double dt = hs_world_dt(w);
	fprintf(stderr, "handspring view: running %s, %ld frames\n", o->file, frames);
	for (bool more = true; more; more = hs_scenario_step(s)) {
		long frame = hs_world_frame(w);
		if (wanted(o, frame, frames, dt))
			record(v, s);
		if (page && (frame % o->every == 0 || frame == frames))
			view_html_frame(page, s);
	}
}

static int view_usage(const char *fmt, const char *arg) {
	fprintf(stderr, "handspring view: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\n%s", hs_view_usage);
	return 2;
}

static bool parse_times(const char *text, view_opts *o) {
	o->at_count = 0;
	const char *p = text;
	while (*p && o->at_count < VIEW_MAX_TIMES) {
		char *end;
		double t = strtod(p, &end);
		if (end == p || !(t >= 0.0))
			return false;
		o->at[o->at_count++] = t;
		p = *end == ',' ? end + 1 : end;
		if (*end && *end != ',')
			return false;
	}
	return o->at_count > 0 && !*p;
}

static int parse(int argc, char **argv, view_opts *o) {
	memset(o, 0, sizeof *o);
	o->every = 1;
	o->html_at = -1.0;
	o->width = 1024;
	o->height = 768;
	for (int i = 0; i < argc; ++i) {
		const char *a = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
		if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
			fputs(hs_view_usage, stdout);
			return 0;
		}
		if (a[0] != '-') {
			if (o->file)
				return view_usage("unexpected argument '%s'", a);
			o->file = a;
			continue;
		}
		if (!val)
			return view_usage("%s needs a value", a);
		++i;
		if (strcmp(a, "--gif") == 0)
			o->gif = val;
		else if (strcmp(a, "--strip") == 0)
			o->strip = val;
		else if (strcmp(a, "--html") == 0)
			o->html = val;
		else if (strcmp(a, "--every") == 0) {
			char *end;
			long n = strtol(val, &end, 10);
			if (*end || n < 1 || n > 100000)
				return view_usage("--every needs a whole number of frames within [1, 100000], got '%s'", val);
			o->every = (int)n;
		} else if (strcmp(a, "--at") == 0) {
			if (!parse_times(val, o))
				return view_usage("--at needs times in s, comma-separated (at most 16, each >= 0), got '%s'", val);
		} else if (strcmp(a, "--html-at") == 0) {
			char *end;
			o->html_at = strtod(val, &end);
			if (*end || !(o->html_at >= 0.0))
				return view_usage("--html-at needs a time >= 0 s, got '%s'", val);
		} else if (strcmp(a, "--size") == 0) {
			if (sscanf(val, "%dx%d", &o->width, &o->height) != 2 || o->width < 64 || o->height < 64 ||
			    o->width > 4096 || o->height > 4096)
				return view_usage("--size needs WIDTHxHEIGHT in pixels, each within [64, 4096], got '%s'", val);
		} else {
			return view_usage("unknown option '%s'", a);
		}
	}
	if (!o->file)
		return view_usage("%s", "missing the scenario FILE");
	if (!o->gif && !o->strip && !o->html)
		return view_usage("%s", "give at least one of --gif, --strip, --html");
	if (o->strip && o->at_count == 0)
		return view_usage("%s", "--strip needs --at T1,T2,... (the times to show)");
	return -1;
}

int hs_view_main(int argc, char **argv) {
	view_opts o;
	int status = parse(argc, argv, &o);
	if (status >= 0)
		return status;
	hs_error err;
	hs_scenario *s = hs_scenario_load(o.file, &err);
	if (!s) {
		fprintf(stderr, "%s\n", err.message);
		return 2;
	}
	if (!outputs_allowed(&o, s)) {
		hs_scenario_destroy(s);
		return 2;
	}
	char dir[] = "/tmp/handspring-view-XXXXXX";
	if (!mkdtemp(dir)) {
		fprintf(stderr, "handspring view: cannot make a temporary folder: %s\n", strerror(errno));
		hs_scenario_destroy(s);
		return 2;
	}
	view_run v;
	memset(&v, 0, sizeof v);
	snprintf(v.dir, sizeof v.dir, "%s", dir);
	v.lo = hs_v3(INFINITY, INFINITY, INFINITY);
	v.hi = hs_v3(-INFINITY, -INFINITY, -INFINITY);
	hs_world *w = hs_scenario_world(s);
	hs_spring_def sd;
	if (hs_world_spring_def(w, &sd) == HS_OK && sd.walls.enabled) { // the walls in view
		grow(&v, hs_v3(sd.walls.x_min, sd.walls.y_min, 0.0));
		grow(&v, hs_v3(sd.walls.x_max, sd.walls.y_max, 0.3));
	}
	view_html *page = o.html ? view_html_begin(s, o.file) : NULL;
	status = o.html && !page ? 2 : 0;
	if (status == 0)
		run_and_record(&o, &v, page, s);
	if (status == 0 && (o.gif || o.strip)) {
		fprintf(stderr, "handspring view: drawing %ld frames with gnuplot\n", v.records);
		status = draw_and_deliver(&o, &v, dir, w, hs_scenario_name(s));
	}
	if (page) {
		int page_status = view_html_finish(page, o.html, o.html_at);
		status = status ? status : page_status;
	}
	for (long r = 0; r < v.records; ++r) {
		char path[96];
		snprintf(path, sizeof path, "%s/r%06ld.dat", dir, r);
		remove(path);
	}
	rmdir(dir);
	free(v.titles);
	free(v.frames);
	hs_scenario_destroy(s);
	if (status == 0)
		fprintf(stderr, "handspring view: wrote%s%s%s%s%s%s\n", o.gif ? " " : "", o.gif ? o.gif : "", o.strip ? " " : "",
		        o.strip ? o.strip : "", o.html ? " " : "", o.html ? o.html : "");
	return status;
}
