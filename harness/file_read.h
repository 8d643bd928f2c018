// file_read.h — reading input files with limits: a scenario file whole, a recorded file line by
// line. Every limit is checked while reading, so /dev/zero, a FIFO or a runaway file ends at once.
#ifndef HS_HARNESS_FILE_READ_H
#define HS_HARNESS_FILE_READ_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "error.h"

// Bytes of any one input file: text written by hand or by a tracker; this is a runaway guard.
#define HS_MAX_INPUT_BYTES ((size_t)256 << 20)
// Bytes of one line of a recorded file: 26 numbers of at most 200 characters fit many times over;
// /dev/zero (no line breaks) stops here.
#define HS_MAX_LINE_BYTES ((size_t)16 << 20)

// Opens a file for reading without blocking on a FIFO that has no writer (it then reads as empty).
// NULL with errno set (EISDIR for a folder) on failure.
FILE *hs_open_input(const char *path);

// Reads a whole file (at most HS_MAX_INPUT_BYTES). Stops early after the first NUL byte, which
// the caller reports: a binary file or a device need not be read to its end. Errors:
// "PATH:1: cannot read: ...". *text is malloc'ed.
bool hs_read_file(const char *path, char **text, size_t *size, hs_error *err);

// A file named by a scenario: relative to the scenario's folder. NULL when out of memory.
char *hs_sibling_path(const char *scenario_path, const char *file);

// A file read line by line with HS_MAX_LINE_BYTES and HS_MAX_INPUT_BYTES as limits.
typedef struct hs_line_reader {
	FILE *file;
	char *buf;          // the unread part of the file, grown up to HS_MAX_LINE_BYTES + 2 bytes
	size_t cap;
	size_t start, len;  // unread bytes are buf[start, len)
	size_t total;       // bytes read so far
	long number;        // lines returned so far
	bool eof;
	size_t max_line, max_total; // the limits (hs_line_reader_limit): 0 means HS_MAX_LINE_BYTES, HS_MAX_INPUT_BYTES
} hs_line_reader;

typedef enum hs_line_status {
	HS_LINE_OK,       // *line (NUL-terminated, without its '\n') and *length are the next line
	HS_LINE_END,      // no more lines
	HS_LINE_TOO_LONG, // line number + 1 is longer than HS_MAX_LINE_BYTES (or the reader's limit)
	HS_LINE_TOO_BIG,  // the file is larger than HS_MAX_INPUT_BYTES (or the reader's limit)
	HS_LINE_NO_MEMORY,
	HS_LINE_READ_ERROR,
} hs_line_status;

// Takes ownership of `file` (closed by hs_line_reader_close).
void hs_line_reader_open(hs_line_reader *r, FILE *file);
// Other limits for a file of short lines (a trajectory's rows, a campaign's trials), so a file of
// no line breaks is refused after line_cap bytes (at most HS_MAX_LINE_BYTES). total_cap may be
// larger than HS_MAX_INPUT_BYTES for a reader that bounds its row count itself (0: the default).
void hs_line_reader_limit(hs_line_reader *r, size_t line_cap, size_t total_cap);
// What a status other than HS_LINE_OK and HS_LINE_END means, with the limits in it, into buf.
const char *hs_line_status_text(const hs_line_reader *r, hs_line_status status, char *buf, size_t size);
hs_line_status hs_line_next(hs_line_reader *r, char **line, size_t *length);
void hs_line_reader_close(hs_line_reader *r);

#endif
