// output.h — every file the tool writes goes through here (output.c): written whole or not at all,
// never through a planted link, never over one of the command's inputs, every error reported.
#ifndef HS_TOOL_OUTPUT_H
#define HS_TOOL_OUTPUT_H

#include <stdbool.h>
#include <stdio.h>

// An output file. A path that names a regular file, or nothing yet, is written to a temporary
// beside it, made with an unpredictable name by exclusive creation (mkstemp: a link planted at
// that name is never followed, and two runs writing the same path never share a temporary); every
// write, the flush, fsync and close are checked, and only then is the temporary renamed over the
// path; on any failure it is removed and the path is left as it was. A symbolic link at the path
// is followed, as a shell's `>` does: the file it names is replaced whole (the link stays a link);
// a link to nothing is refused. `-`, and a path that names something other than a regular file
// (/dev/null, /dev/full, a pipe, /dev/stdout), are written in place: renaming over them would
// replace the device or the link with a regular file. A path that is the same file (device and
// inode) as one of the command's inputs (output_input), or as another output of the command, is
// refused before anything is written.
typedef struct output {
	char *path;   // as given
	char *target; // the file that will hold the output (a link's target)
	char *temp;   // NULL: written in place
	FILE *file;
	bool in_place, is_stdout;
	char error[512]; // one line: what failed (output_open or output_close returned false)
} output;

// Records an input of the command (a file it read or will read): no output may overwrite it.
// A path that does not exist is ignored.
void output_input(const char *path);
// The checks of output_open without opening or claiming the path: false with the reason in
// `error` (an input, a folder, a link to nothing). For an output written later in the run.
bool output_check(const char *path, char *error, size_t size);
// Opens `path` for writing (its folders made as mkdir -p does); false with o->error set.
bool output_open(output *o, const char *path);
// Finishes the file: with `keep`, renames the temporary over the path once every byte is written
// and synced; without, removes it. False with o->error set when any write failed (the temporary
// removed, the path untouched). Closing an output that was never opened succeeds.
bool output_close(output *o, bool keep);
void output_free(output *o);
// Like mkdir -p for the folder that will hold `file`.
bool make_parent_dirs(const char *file);
// Standard output flushed and checked at the tool's end: false (said in one line on stderr) when
// any of it could not be written (a full disk, /dev/full).
bool output_stdout_ok(void);

#endif
