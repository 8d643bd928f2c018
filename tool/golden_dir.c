// golden_dir.c — where a folder's goldens go. A user's folder at the top of the repository once
// had the catalog's own golden/ "beside it", and a scenario of theirs named drop_cube rewrote
// golden/drop_cube.csv: goldens now go to DIR/golden, and no command writes into the goldens
// folder of a catalog (a folder 'golden' with 'scenarios' beside it) but for that catalog's own
// scenarios. Paths are compared resolved (symbolic links, '..'), also where a write would create
// the folders.
#define _XOPEN_SOURCE 700 // realpath
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "golden_dir.h"

char *hs_golden_beside(const char *dir) {
	size_t n = strlen(dir);
	while (n > 1 && dir[n - 1] == '/')
		--n;
	size_t cut = n;
	while (cut > 0 && dir[cut - 1] != '/')
		--cut;
	char *r = malloc(cut + 8);
	if (r) {
		memcpy(r, dir, cut);
		strcpy(r + cut, "golden");
	}
	return r;
}

char *hs_golden_default(const char *dir) {
	size_t n = strlen(dir);
	while (n > 1 && dir[n - 1] == '/')
		--n;
	size_t base = n;
	while (base > 0 && dir[base - 1] != '/')
		--base;
	if (n - base == 9 && strncmp(dir + base, "scenarios", 9) == 0)
		return hs_golden_beside(dir);
	char *r = malloc(n + 8);
	if (r)
		snprintf(r, n + 8, "%.*s/golden", (int)n, dir);
	return r;
}

// Appends the components of `tail` to the absolute path `out` as a write would meet them ('..'
// takes one off; these folders do not exist yet, so none is a link).
static void append_lexically(char *out, const char *tail) {
	while (*tail) {
		size_t len = strcspn(tail, "/");
		if (len == 2 && strncmp(tail, "..", 2) == 0) {
			char *slash = strrchr(out, '/');
			if (slash)
				slash[slash == out] = '\0'; // "/a" -> "/", "/a/b" -> "/a"
		} else if (len > 0 && !(len == 1 && tail[0] == '.')) {
			size_t n = strlen(out);
			if (n > 0 && out[n - 1] != '/')
				out[n++] = '/';
			memcpy(out + n, tail, len);
			out[n + len] = '\0';
		}
		tail += len + (tail[len] == '/');
	}
}

// The absolute path `path` names: its longest existing head resolved by realpath, the rest added
// lexically. NULL when out of memory or nothing resolves.
static char *resolve(const char *path) {
	size_t n = strlen(path), cut = n;
	char *head = malloc(n + 2);
	if (!head)
		return NULL;
	char *real = NULL;
	for (;;) {
		memcpy(head, path, cut);
		head[cut] = '\0';
		real = realpath(cut > 0 ? head : ".", NULL);
		if (real || cut == 0)
			break;
		while (cut > 1 && path[cut - 1] == '/')
			--cut;
		while (cut > 0 && path[cut - 1] != '/')
			--cut;
	}
	free(head);
	char *out = real ? malloc(strlen(real) + n + 2) : NULL;
	if (out) {
		strcpy(out, real);
		append_lexically(out, path + cut);
	}
	free(real);
	return out;
}

static bool is_dir(const char *path) {
	struct stat st;
	return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

// The catalog (resolved) whose goldens folder is `p` or holds it: the folder 'scenarios' beside
// the nearest 'golden' among p and its parents that has one; NULL when there is none.
static char *catalog_of(const char *p) {
	char *q = malloc(strlen(p) + 12);
	if (!q)
		return NULL;
	strcpy(q, p);
	for (char *slash; (slash = strrchr(q, '/')) != NULL; *slash = '\0') {
		if (strcmp(slash + 1, "golden") != 0)
			continue;
		strcpy(slash + 1, "scenarios");
		char *catalog = is_dir(q) ? resolve(q) : NULL;
		if (catalog) {
			free(q);
			return catalog;
		}
		strcpy(slash + 1, "golden");
	}
	free(q);
	return NULL;
}

static bool inside(const char *path, const char *folder) {
	size_t n = strlen(folder);
	return strncmp(path, folder, n) == 0 && (path[n] == '\0' || path[n] == '/' || (n == 1 && folder[0] == '/'));
}

bool hs_golden_dir_allowed(const char *dir, const char *gdir, char *why, size_t size) {
	char *g = resolve(gdir), *d = resolve(dir);
	char *catalog = g ? catalog_of(g) : NULL;
	bool ok = g && d && (!catalog || inside(d, catalog));
	if (!g || !d)
		snprintf(why, size, "cannot resolve %s: out of memory", g ? dir : gdir);
	else if (!ok)
		snprintf(why, size,
		         "%s holds the goldens of the catalog %s: goldens of %s never go there (by default they go to "
		         "%s/golden; choose another folder with --golden)",
		         gdir, catalog, dir, dir);
	free(g);
	free(d);
	free(catalog);
	return ok;
}

bool hs_golden_is_make_golden(const char *dir, const char *gdir) {
	char *d = resolve(dir), *g = resolve(gdir), *ds = resolve("scenarios"), *gs = resolve("golden");
	bool same = d && g && ds && gs && strcmp(d, ds) == 0 && strcmp(g, gs) == 0;
	free(d);
	free(g);
	free(ds);
	free(gs);
	return same;
}
