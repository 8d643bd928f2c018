// suggest.h — "did you mean 'X'?" for a misspelt word (a key, an object name, a shape), and the
// list of what is valid when it is short (suggest.c; scenarios/README.md, "Errors and warnings").
#ifndef HS_HARNESS_SUGGEST_H
#define HS_HARNESS_SUGGEST_H

#include <stddef.h>

// Lists of at most this many valid words are named in full in a message.
#define HS_SUGGEST_LIST_MAX 12

// The optimal string alignment distance between a[0..na) and b[0..nb) (insertions, deletions,
// substitutions and swaps of two neighbours, each 1); words longer than 64 bytes count as far.
int hs_edit_distance(const char *a, size_t na, const char *b, size_t nb);

// The valid word nearest to typed[0..n): its index in names, or -1 when none is near enough
// (distance at most 2, or at most a third of the typed length, and less than both lengths).
int hs_suggest(const char *typed, size_t n, const char *const *names, int count);

// Appends to buf (a NUL-terminated message of `size` bytes) ": did you mean 'X'?" when a word is
// near, then " (expected a, b or c)" when `list` and count <= HS_SUGGEST_LIST_MAX.
void hs_suggest_append(char *buf, size_t size, const char *typed, size_t n, const char *const *names, int count,
                       int list);

#endif
