// all_cmd.h — `handspring all` and `handspring golden` (all_cmd.c).
#ifndef HS_TOOL_ALL_CMD_H
#define HS_TOOL_ALL_CMD_H

int hs_cmd_all(int argc, char **argv);
int hs_cmd_golden(int argc, char **argv);

#endif
