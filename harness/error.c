// error.c — formatting of "PATH:LINE: what is wrong" messages, shared by every reader.
#include <stdio.h>
#include <string.h>

#include "error.h"

const char *hs_shown_path(const char *path, char buf[HS_SHOWN_PATH + 4]) {
	size_t n = strlen(path);
	if (n <= HS_SHOWN_PATH)
		return path;
	memcpy(buf, "...", 3);
	memcpy(buf + 3, path + n - HS_SHOWN_PATH, HS_SHOWN_PATH + 1);
	return buf;
}

bool hs_vset_error(hs_error *err, const char *path, unsigned long line, const char *fmt, va_list ap) {
	char shown[HS_SHOWN_PATH + 4];
	int n = snprintf(err->message, sizeof err->message, "%s:%lu: ", hs_shown_path(path, shown), line);
	if (n >= 0 && (size_t)n < sizeof err->message)
		vsnprintf(err->message + n, sizeof err->message - (size_t)n, fmt, ap);
	return false;
}

bool hs_set_error(hs_error *err, const char *path, unsigned long line, const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	hs_vset_error(err, path, line, fmt, ap);
	va_end(ap);
	return false;
}
