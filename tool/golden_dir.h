// golden_dir.h — where the goldens of a folder of scenarios go (golden_dir.c): DIR/golden, or the
// folder 'golden' beside a folder named 'scenarios'; never the goldens folder of another catalog.
#ifndef HS_TOOL_GOLDEN_DIR_H
#define HS_TOOL_GOLDEN_DIR_H

#include <stdbool.h>
#include <stddef.h>

// The folder 'golden' beside `dir` ("scenarios" -> "golden", "a/b/scenarios" -> "a/b/golden"; malloc'd,
// NULL when out of memory).
char *hs_golden_beside(const char *dir);
// The default goldens folder of `dir` (malloc'd; NULL when out of memory): for a folder named
// 'scenarios' the folder 'golden' beside it (the catalog's layout: scenarios/ and golden/), for
// any other DIR/golden.
char *hs_golden_default(const char *dir);

// False, with the reason in `why`, when `gdir` is (or lies below) the goldens folder of a catalog
// (a folder 'golden' with a folder 'scenarios' beside it) and `dir` is not that catalog or inside
// it: a user's scenario named like a catalog one must not overwrite the catalog's golden.
bool hs_golden_dir_allowed(const char *dir, const char *gdir, char *why, size_t size);

// True when `dir` and `gdir` are the folders 'scenarios' and 'golden' of the current folder: what
// `make golden` writes (the goldens' header then says so).
bool hs_golden_is_make_golden(const char *dir, const char *gdir);

#endif
