// bench_cmd.h — `handspring bench` (bench_cmd.c): how fast a scenario's frames step.
#ifndef HS_BENCH_CMD_H
#define HS_BENCH_CMD_H

extern const char *const hs_bench_usage;
int hs_bench_main(int argc, char **argv);

#endif
