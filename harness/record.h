// record.h — recorded tracker files (glove and stylus CSV): one reader for both.
#ifndef HS_HARNESS_RECORD_H
#define HS_HARNESS_RECORD_H

#include <stdbool.h>

#include "error.h"
#include "file_read.h"

// A header, then rows of `columns` numbers with t strictly increasing (column 1), x y z within
// ±1000 m (2-4) and qw qx qy qz a unit quaternion (5-8, HS_QUAT_NORM_TOLERANCE); blank and '#'
// lines are skipped, before the header too. The caller checks the rest. Files and lines are
// bounded (file_read.h).
typedef struct hs_record_rows {
	long count;
	double *values; // count × columns
	long *lines;    // each row's line in the file
} hs_record_rows;

#define HS_RECORD_MAX_COLUMNS 192

// `what` names the file in messages ("recorded input"); `shown` is how messages write the header.
bool hs_record_read(const char *path, const char *what, const char *header, const char *shown, int columns,
                    long max_rows, hs_record_rows *rows, hs_error *err);
// The same with each column's kind in `layout` (one character per column, `columns` long): 't'
// time (column 1), 'p' a position (within ±1000 m), 'q' the first of a quaternion's four columns
// (w, x, y, z: unit norm), 'n' any finite number. hs_record_read is the layout "tpppqqqq" then 'n'.
bool hs_record_read_layout(const char *path, const char *what, const char *header, const char *shown, int columns,
                           const char *layout, long max_rows, hs_record_rows *rows, hs_error *err);
void hs_record_rows_free(hs_record_rows *rows);
// The message for a line reader that stopped before the end of the file (`status`: not OK or END)
// at `line`; `what` names the file ("recorded input"). Always false.
bool hs_record_reader_failure(hs_line_status status, const char *path, long line, const char *what, hs_error *err);

#endif
