// state_fields.c — the field tables' walker out of line (state_fields.h): the walk every mode but a
// frame's hash takes (size, save, check, load, and the self-check builds' hash walks).
#include "state_fields.h"

void hs_fields_io(hs_state_io *io, const hs_field *table, size_t n, void *root, const int64_t *ctx) {
	for (size_t i = 0; i < n; ++i) // not unrolled: one copy of the walker serves every table
		hs_field_walk(io, io->mode, &table[i], (unsigned char *)root, ctx);
}
