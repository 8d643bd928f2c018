// near_list.h — the broad phase's neighbour lists (broadphase.c, hs_grid_near): the resting objects
// near a few boxes, listed from the grid with a skin, so that the queries of a hand that stays in a
// place read a short list instead of the grid's cells. A CACHE of the world: a list is stale once
// the epoch moved on (an object came to rest, or moved while resting).
#ifndef HS_NEAR_LIST_H
#define HS_NEAR_LIST_H

#define HS_NEAR_BOXES 4      // lists kept at once (a hand and the objects it holds: one)
#define HS_NEAR_LISTED 64    // objects a list holds at most (more: the grid answers alone)
#define HS_NEAR_AWAKE_MAX 32 // lists are read only while this few objects are awake

// The resting objects near one box.
typedef struct hs_near_list {
	double lo[2], hi[2]; // m: the box (x, y)
	long epoch;          // hs_near_lists.epoch when listed (0: never; the epoch starts at 1)
	long used;           // hs_near_lists.clock when it last answered
	int count;
	int index[HS_NEAR_LISTED]; // ascending
} hs_near_list;

// The lists kept at once, with the epoch that makes them stale and the clock that picks the
// least recently used one to replace.
typedef struct hs_near_lists {
	hs_near_list list[HS_NEAR_BOXES];
	long epoch, clock;
	long hits; // queries a list answered (tests: the lists are used)
} hs_near_lists;

#endif
