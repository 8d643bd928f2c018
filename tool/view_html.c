// view_html.c — `handspring view FILE --html OUT.html`: the run as JSON, put with three.js into the
// page template (tool/viewer/page.html, viewer.js; docs/viewer.md says what the page does).
// The objects' shapes, the walls and the number of hands once; then per frame drawn each object's
// pose and contact state, each hand's 20 check points and which touch, the contacts with their
// object, and in a spring world the stylus, the spring's anchor, the attached object and the
// selection candidate. Only the public API is used.
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output.h"
#include "view_html.h"

struct view_html {
	FILE *json;    // the frames, an array written as they come (open_memstream)
	char *frames;  // its buffer
	size_t size;
	long count;
	char *head;    // the run's fixed part: file, model, objects, walls
	size_t head_size;
	char *title;   // the scenario file as given
};

// A JSON string; '<', '>' and '&' escaped too, so no name can end the page's <script>.
static void json_string(FILE *f, const char *s) {
	fputc('"', f);
	for (const unsigned char *p = (const unsigned char *)s; *p; ++p) {
		if (*p < 0x20 || *p == '"' || *p == '\\' || *p == '<' || *p == '>' || *p == '&')
			fprintf(f, "\\u%04x", *p);
		else
			fputc(*p, f);
	}
	fputc('"', f);
}

// 10 µm is far below a pixel; a non-finite value (never expected: the world freezes an object
// before one spreads) as null, which the page shows as missing rather than as 0.
static void num(FILE *f, double x, const char *sep) {
	if (isfinite(x))
		fprintf(f, "%.5f%s", x, sep);
	else
		fprintf(f, "null%s", sep);
}

static void vec(FILE *f, hs_vec3 p, const char *sep) {
	num(f, p.x, ",");
	num(f, p.y, ",");
	num(f, p.z, sep);
}

static int object_index(const hs_world *w, hs_object_id id) {
	for (int i = 0; i < hs_world_object_count(w); ++i)
		if (hs_world_object_at(w, i).index1 == id.index1)
			return i;
	return -1;
}

// Each object's name and shape in its own frame (origin at G): vertices, faces as vertex lists.
static void shapes(FILE *f, hs_scenario *s, hs_world *w) {
	fputs("\"objects\":[", f);
	for (int i = 0; i < hs_world_object_count(w); ++i) {
		const hs_shape *sh = hs_world_shape(w, hs_world_object_shape(w, hs_world_object_at(w, i)));
		fputs(i ? ",{\"name\":" : "{\"name\":", f);
		json_string(f, hs_scenario_object_name(s, i));
		fputs(",\"v\":[", f);
		for (int k = 0; sh && k < sh->vertex_count; ++k)
			vec(f, sh->vertices[k], k + 1 < sh->vertex_count ? "," : "");
		fputs("],\"f\":[", f);
		for (int k = 0; sh && k < sh->face_count; ++k) {
			fputc(k ? ',' : '[', f);
			if (k)
				fputc('[', f);
			for (int j = 0; j < sh->faces[k].index_count; ++j)
				fprintf(f, j ? ",%d" : "%d", sh->face_vertices[sh->faces[k].first_index + j]);
			fputc(']', f);
		}
		fputs("]}", f);
	}
	fputs("],", f);
}

static bool head(view_html *h, hs_scenario *s, const char *file) {
	hs_world *w = hs_scenario_world(s);
	FILE *f = open_memstream(&h->head, &h->head_size);
	if (!f)
		return false;
	fputs("{\"file\":", f);
	json_string(f, file);
	fputs(",\"name\":", f);
	json_string(f, hs_scenario_name(s));
	fprintf(f, ",\"model\":\"%s\",\"dt\":%.17g,", hs_world_springs_enabled(w) ? "spring" : "hand", hs_world_dt(w));
	shapes(f, s, w);
	int hands = 0;
	while (hs_world_hand_at(w, hands).index1 != 0)
		++hands;
	fprintf(f, "\"hands\":%d,\"walls\":", hands);
	hs_spring_def sd;
	if (hs_world_spring_def(w, &sd) == HS_OK && sd.walls.enabled) { // drawn 0.3 m high, as the gnuplot views
		fputc('[', f);
		num(f, sd.walls.x_min, ",");
		num(f, sd.walls.x_max, ",");
		num(f, sd.walls.y_min, ",");
		num(f, sd.walls.y_max, ",0.3]");
	} else {
		fputs("null", f);
	}
	return fclose(f) == 0;
}

view_html *view_html_begin(hs_scenario *s, const char *file) {
	view_html *h = calloc(1, sizeof *h);
	if (h && (h->title = strdup(file)) != NULL && head(h, s, file) &&
	    (h->json = open_memstream(&h->frames, &h->size)) != NULL)
		return h;
	fprintf(stderr, "handspring view: out of memory\n");
	if (h) {
		free(h->head);
		free(h->title);
	}
	free(h);
	return NULL;
}

static void frame_hands(FILE *f, hs_world *w) {
	fputs(",\"h\":[", f);
	for (int n = 0;; ++n) {
		hs_hand_id id = hs_world_hand_at(w, n);
		hs_vec3 p[HS_HAND_POINTS], r[HS_HAND_POINTS];
		uint32_t touching = 0;
		if (id.index1 == 0)
			break;
		if (hs_world_hand_points(w, id, p) != HS_OK || hs_world_hand_rectified_points(w, id, r, &touching) != HS_OK) {
			fputs(n ? ",null" : "null", f);
			continue;
		}
		fputs(n ? ",{\"p\":[" : "{\"p\":[", f);
		for (int k = 0; k < HS_HAND_POINTS; ++k)
			vec(f, p[k], k + 1 < HS_HAND_POINTS ? "," : "");
		fprintf(f, "],\"touch\":%lu}", (unsigned long)touching);
	}
	fputs("],\"c\":[", f);
	hs_contact few[64], *cs = few;
	int n = hs_world_contacts(w, few, 64);
	if (n > 64 && (cs = malloc((size_t)n * sizeof *cs)) != NULL) // a crowded frame
		hs_world_contacts(w, cs, n);
	if (!cs) {
		cs = few;
		n = 64;
	}
	for (int k = 0; k < n; ++k) {
		vec(f, cs[k].point, ",");
		fprintf(f, k + 1 < n ? "%d," : "%d", object_index(w, cs[k].object));
	}
	if (cs != few)
		free(cs);
	fputc(']', f);
}

static void frame_stylus(FILE *f, hs_world *w) {
	hs_spring_state ss;
	fputs(",\"s\":", f);
	if (!hs_world_springs_enabled(w) || hs_world_spring_state(w, &ss) != HS_OK) {
		fputs("null", f);
		return;
	}
	fputs("{\"p\":[", f);
	vec(f, ss.stylus, "],\"d\":[");
	vec(f, hs_quat_rotate(ss.stylus_orientation, hs_v3(1.0, 0.0, 0.0)), "],\"a\":["); // the pointing ray
	vec(f, ss.anchor, "],\"e\":");
	num(f, ss.extension, "");
	fprintf(f, ",\"b\":%d,\"k\":%d,\"n\":%d}", ss.button ? 1 : 0, ss.attached.index1 ? object_index(w, ss.attached) : -1,
	        ss.candidate.index1 ? object_index(w, ss.candidate) : -1);
}

void view_html_frame(view_html *h, hs_scenario *s) {
	hs_world *w = hs_scenario_world(s);
	FILE *f = h->json;
	long frame = hs_world_frame(w);
	fprintf(f, "%s{\"f\":%ld,\"t\":%.6f,\"o\":[", h->count ? ",\n" : "", frame, (double)frame * hs_world_dt(w));
	for (int i = 0; i < hs_world_object_count(w); ++i) {
		hs_object_state st;
		if (hs_world_object_state(w, hs_world_object_at(w, i), &st) != HS_OK)
			memset(&st, 0, sizeof st);
		vec(f, st.position, ",");
		fprintf(f, "%.6f,%.6f,%.6f,%.6f,%d", st.orientation.w, st.orientation.x, st.orientation.y, st.orientation.z,
		        (int)st.contact);
		fputs(i + 1 < hs_world_object_count(w) ? "," : "]", f);
	}
	if (hs_world_object_count(w) == 0)
		fputc(']', f);
	frame_hands(f, w);
	frame_stylus(f, w);
	fputc('}', f);
	h->count++;
}

// The first "@@" at or after p, NULL when none before end.
static const char *marker(const char *p, const char *end) {
	for (; p + 1 < end; ++p)
		if (p[0] == '@' && p[1] == '@')
			return p;
	return NULL;
}

static const view_asset *asset(const char *name, size_t len) {
	for (size_t k = 0; k < hs_viewer_asset_count; ++k)
		if (strlen(hs_viewer_assets[k].name) == len && memcmp(hs_viewer_assets[k].name, name, len) == 0)
			return &hs_viewer_assets[k];
	return NULL;
}

static void html_text(FILE *f, const char *s) {
	for (; *s; ++s) {
		if (*s == '<')
			fputs("&lt;", f);
		else if (*s == '>')
			fputs("&gt;", f);
		else if (*s == '&')
			fputs("&amp;", f);
		else if (*s == '"')
			fputs("&quot;", f);
		else
			fputc(*s, f);
	}
}

// The template with each @@NAME@@ replaced: TITLE and DATA from the run, the rest embedded files.
static void page(FILE *out, const view_html *h, const char *title, double start) {
	const view_asset *tpl = asset("PAGE", 4);
	const char *p = (const char *)tpl->bytes, *end = p + tpl->size;
	while (p < end) {
		const char *m = marker(p, end), *close = m ? marker(m + 2, end) : NULL;
		if (!m || !close) {
			fwrite(p, 1, (size_t)(end - p), out);
			break;
		}
		fwrite(p, 1, (size_t)(m - p), out);
		const char *name = m + 2;
		size_t len = (size_t)(close - name);
		const view_asset *a = asset(name, len);
		if (len == 5 && memcmp(name, "TITLE", 5) == 0) {
			html_text(out, title);
		} else if (len == 4 && memcmp(name, "DATA", 4) == 0) {
			fwrite(h->head, 1, h->head_size, out);
			fprintf(out, ",\"start\":%.17g,\"frames\":[\n", start);
			fwrite(h->frames, 1, h->size, out);
			fputs("]}", out);
		} else if (a) {
			fwrite(a->bytes, 1, a->size, out);
		} else {
			fwrite(m, 1, (size_t)(close + 2 - m), out); // not a marker: as it is
		}
		p = close + 2;
	}
}

int view_html_finish(view_html *h, const char *path, double start) {
	int status = 2;
	if (fclose(h->json) != 0) {
		fprintf(stderr, "handspring view: out of memory\n");
	} else {
		output o;
		memset(&o, 0, sizeof o);
		if (!output_open(&o, path)) {
			fprintf(stderr, "handspring: %s\n", o.error);
		} else {
			page(o.file, h, h->title, start);
			if (output_close(&o, true))
				status = 0;
			else
				fprintf(stderr, "handspring: %s\n", o.error);
		}
		output_free(&o);
	}
	free(h->frames);
	free(h->head);
	free(h->title);
	free(h);
	return status;
}
