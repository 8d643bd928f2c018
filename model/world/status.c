// status.c — the names of the API's status codes (one error convention: misuse and bad data
// return a status; numeric trouble is counted on the world, see hs_world_first_fault).
#include "handspring.h"

const char *hs_status_string(hs_status status) {
	switch (status) {
	case HS_OK:
		return "ok";
	case HS_ERR_INVALID_ARGUMENT:
		return "invalid argument";
	case HS_ERR_DEGENERATE:
		return "degenerate shape";
	case HS_ERR_CAPACITY:
		return "capacity exceeded";
	case HS_ERR_NO_MEMORY:
		return "out of memory";
	case HS_ERR_STATE_MISMATCH:
		return "saved state does not match this world";
	}
	return "unknown status";
}
