// output.h — the tool's output files (output.c): an interrupted run never leaves half a file.
#ifndef HS_TOOL_OUTPUT_H
#define HS_TOOL_OUTPUT_H

#include <stdbool.h>
#include <stdio.h>

// An output file written under a temporary name and renamed when complete, so that an
// interrupted run never leaves a half-written golden behind. A path that exists and is not a
// regular file (/dev/null, a pipe) is written in place: renaming over it replaced /dev/null with
// a regular file when run as root (tests/resume_catalog.sh's --out /dev/null did, and apt then
// failed on the machine). A symbolic link is written through, in place: renaming over
// /dev/stdout (a link to /proc/self/fd/1) replaced the link itself with a regular file.
typedef struct output {
	char *path, *temp; // temp NULL: written in place
	FILE *file;
} output;

// Opens `path` for writing (its folders made as mkdir -p does); false when it cannot.
bool output_open(output *o, const char *path);
// Closes, then renames to the final name when `keep`; false (and errno) on any write error.
bool output_close(output *o, bool keep);
void output_free(output *o);
// Like mkdir -p for the folder that will hold `file`.
bool make_parent_dirs(const char *file);

#endif
