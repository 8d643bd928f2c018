// view.h — `handspring view` (view.c): a scenario drawn by gnuplot in 3-D.
#ifndef HS_VIEW_H
#define HS_VIEW_H

// The usage text of `handspring view`.
extern const char *const hs_view_usage;

// `handspring view` with the arguments after `view`; the exit status.
int hs_view_main(int argc, char **argv);

#endif
