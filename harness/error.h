// error.h — the harness's one error convention: "PATH:LINE: what is wrong", in an hs_error.
#ifndef HS_HARNESS_ERROR_H
#define HS_HARNESS_ERROR_H

#include <stdarg.h>
#include <stdbool.h>

#include "hs_harness.h"

#if defined(__GNUC__)
#define HS_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define HS_PRINTF(f, a)
#endif

// Room for a whole message (hs_error.message), for messages built in parts.
#define HS_ERROR_TEXT (sizeof ((hs_error *)0)->message)

// A path as error messages show it: at most HS_SHOWN_PATH bytes, longer ones as "..." and their
// end, so the line and the reason always fit in an hs_error. Returns path or buf.
#define HS_SHOWN_PATH 200
const char *hs_shown_path(const char *path, char buf[HS_SHOWN_PATH + 4]);

// Writes "PATH:LINE: " and the formatted reason into err. Always returns false, so a reader can
// `return hs_set_error(...)`.
bool hs_vset_error(hs_error *err, const char *path, unsigned long line, const char *fmt, va_list ap);
HS_PRINTF(4, 5) bool hs_set_error(hs_error *err, const char *path, unsigned long line, const char *fmt, ...);

#endif
