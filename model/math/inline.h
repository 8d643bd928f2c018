// inline.h — the compiler hints of the speed work: a function forced inline where a call cost
// more than its body (vectors passed by value through the stack, a walk whose mode is a constant
// only once inlined), or kept out of line where inlining grew a hot caller past what it saved.
// Each use says why; none changes an operation, so none changes a result.
#ifndef HS_INLINE_H
#define HS_INLINE_H

#if defined(__GNUC__)
#define HS_FORCE_INLINE inline __attribute__((always_inline))
#define HS_NOINLINE __attribute__((noinline))
#else
#define HS_FORCE_INLINE inline
#define HS_NOINLINE
#endif

#endif
