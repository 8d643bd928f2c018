// view_html.h — `handspring view --html` (view_html.c): the run as JSON in one self-contained page
// (tool/viewer/page.html and viewer.js, with three.js vendored in tool/viewer/vendor/three).
#ifndef HS_VIEW_HTML_H
#define HS_VIEW_HTML_H

#include <stdbool.h>
#include <stddef.h>

#include "hs_harness.h"

// The page's pieces, embedded by the build (tool/viewer/embed.sh writes them as C arrays).
typedef struct view_asset {
	const char *name; // the page's marker: @@NAME@@
	const unsigned char *bytes;
	size_t size;
} view_asset;
extern const view_asset hs_viewer_assets[];
extern const size_t hs_viewer_asset_count;

typedef struct view_html view_html;

// Starts a page for the scenario loaded from `file`: its objects' shapes, walls and hands.
// NULL (said on stderr) when out of memory.
view_html *view_html_begin(hs_scenario *s, const char *file);
// Adds the world's current frame: poses and contact states, check points, contacts, stylus.
void view_html_frame(view_html *h, hs_scenario *s);
// Writes the page to `path` through the tool's writer (output.h); the page opens at the frame
// nearest `start` s (< 0: the first). Frees h. 0 written, 2 failed (said on stderr).
int view_html_finish(view_html *h, const char *path, double start);

#endif
