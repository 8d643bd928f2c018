// hand_cmd.h — `handspring hand` (hand_cmd.c): a posture's check points in the wrist frame.
#ifndef HS_HAND_CMD_H
#define HS_HAND_CMD_H

#include "handspring.h"

extern const char *const hs_hand_usage;
int hs_hand_main(int argc, char **argv);

#endif
