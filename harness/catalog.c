// catalog.c — the scenario catalog: every *.yaml below a folder, recursively (hidden entries
// skipped), sorted by name so every machine lists and runs them in the same order.
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hs_harness.h"

enum { MAX_CATALOG_DEPTH = 16 }; // folder nesting under the catalog root

typedef struct catalog_entry {
	char *name, *path;
} catalog_entry;

typedef struct catalog_builder {
	catalog_entry *entries;
	int count, capacity;
	hs_error *err;
} catalog_builder;

static char *join(const char *a, const char *b) {
	size_t na = strlen(a), nb = strlen(b);
	size_t slash = na > 0 && a[na - 1] != '/';
	char *r = malloc(na + slash + nb + 1);
	if (r) {
		memcpy(r, a, na);
		if (slash)
			r[na] = '/';
		memcpy(r + na + slash, b, nb + 1);
	}
	return r;
}

static bool catalog_add(catalog_builder *b, const char *rel, const char *path) {
	if (b->count == b->capacity) {
		int cap = b->capacity ? b->capacity * 2 : 16;
		catalog_entry *bigger = realloc(b->entries, (size_t)cap * sizeof *bigger);
		if (!bigger)
			return false;
		b->entries = bigger;
		b->capacity = cap;
	}
	size_t n = strlen(rel) - 5; // without ".yaml"
	char *name = malloc(n + 1), *copy = malloc(strlen(path) + 1);
	if (!name || !copy) {
		free(name);
		free(copy);
		return false;
	}
	memcpy(name, rel, n);
	name[n] = '\0';
	strcpy(copy, path);
	b->entries[b->count++] = (catalog_entry){name, copy};
	return true;
}

static bool catalog_walk(catalog_builder *b, const char *dir, const char *rel, int depth) {
	DIR *d = opendir(dir);
	if (!d) {
		snprintf(b->err->message, sizeof b->err->message, "%s: cannot read: %s", dir, strerror(errno));
		return false;
	}
	bool ok = true;
	struct dirent *e;
	while (ok && (e = readdir(d)) != NULL) {
		if (e->d_name[0] == '.') // hidden files, editors' files, "." and ".."
			continue;
		char *path = join(dir, e->d_name);
		char *sub = join(rel, e->d_name);
		struct stat st;
		if (!path || !sub) {
			snprintf(b->err->message, sizeof b->err->message, "%s: out of memory", dir);
			ok = false;
		} else if (stat(path, &st) != 0) {
			snprintf(b->err->message, sizeof b->err->message, "%s: cannot read: %s", path, strerror(errno));
			ok = false;
		} else if (S_ISDIR(st.st_mode)) {
			if (depth >= MAX_CATALOG_DEPTH) { // also stops a symbolic link loop
				snprintf(b->err->message, sizeof b->err->message, "%s: folders nested deeper than %d", path,
				         MAX_CATALOG_DEPTH);
				ok = false;
			} else {
				ok = catalog_walk(b, path, sub, depth + 1);
			}
		} else if (S_ISREG(st.st_mode)) {
			size_t n = strlen(e->d_name);
			if (n > 5 && strcmp(e->d_name + n - 5, ".yaml") == 0 && !catalog_add(b, sub, path)) {
				snprintf(b->err->message, sizeof b->err->message, "%s: out of memory", dir);
				ok = false;
			}
		}
		free(path);
		free(sub);
	}
	closedir(d);
	return ok;
}

static int compare_entries(const void *a, const void *b) {
	return strcmp(((const catalog_entry *)a)->name, ((const catalog_entry *)b)->name);
}

bool hs_catalog_load(const char *dir, hs_catalog *out, hs_error *err) {
	hs_error scratch;
	if (!err)
		err = &scratch;
	err->message[0] = '\0';
	if (!out)
		return false;
	memset(out, 0, sizeof *out);
	if (!dir) {
		snprintf(err->message, sizeof err->message, "(null): cannot read: no folder given");
		return false;
	}
	catalog_builder b = {NULL, 0, 0, err};
	bool ok = catalog_walk(&b, dir, "", 0);
	// readdir's order is the file system's: sort by name
	if (ok && b.count > 0) {
		qsort(b.entries, (size_t)b.count, sizeof *b.entries, compare_entries);
		out->names = malloc((size_t)b.count * sizeof *out->names);
		out->paths = malloc((size_t)b.count * sizeof *out->paths);
		ok = out->names && out->paths;
		if (!ok)
			snprintf(err->message, sizeof err->message, "%s: out of memory", dir);
	}
	for (int i = 0; i < b.count; ++i) {
		if (ok) {
			out->names[i] = b.entries[i].name;
			out->paths[i] = b.entries[i].path;
		} else {
			free(b.entries[i].name);
			free(b.entries[i].path);
		}
	}
	free(b.entries);
	if (!ok) {
		free(out->names);
		free(out->paths);
		memset(out, 0, sizeof *out);
		return false;
	}
	out->count = b.count;
	return true;
}

void hs_catalog_free(hs_catalog *catalog) {
	if (!catalog)
		return;
	for (int i = 0; i < catalog->count; ++i) {
		free(catalog->names[i]);
		free(catalog->paths[i]);
	}
	free(catalog->names);
	free(catalog->paths);
	memset(catalog, 0, sizeof *catalog);
}
