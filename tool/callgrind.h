// callgrind.h — reads what `valgrind --tool=callgrind` writes (its profile format: the `fn=`,
// `cfn=` and `calls=` lines), for `handspring bench --instr` (bench_cmd.c).
#ifndef HS_CALLGRIND_H
#define HS_CALLGRIND_H

#include <stddef.h>
#include <stdint.h>

typedef struct hs_cg_profile hs_cg_profile;

/// Loads a callgrind output file; NULL with `why` filled when it cannot be read or parsed.
hs_cg_profile *hs_cg_load(const char *path, char *why, size_t why_size);
void hs_cg_free(hs_cg_profile *profile);
/// The first event's total (Ir: instructions) over what was collected.
uint64_t hs_cg_total(const hs_cg_profile *profile);
/// Inclusive cost of the calls `caller` made to `callee` (0 when none or either is unknown).
uint64_t hs_cg_call(const hs_cg_profile *profile, const char *caller, const char *callee);
/// Inclusive cost of `fn`: its calls from every other function (its calls to itself left out).
uint64_t hs_cg_inclusive(const hs_cg_profile *profile, const char *fn);

#endif
