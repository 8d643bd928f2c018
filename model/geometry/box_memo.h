// box_memo.h — an object's world box (hs_part_world_box of its single part) remembered at its last
// two poses, so that a held object's box is made once a frame, not once per neighbour it is tested
// against, and a resting neighbour's once (interfere.h). Keyed by the pose's bits, so never stale:
// a shape never changes.
#ifndef HS_BOX_MEMO_H
#define HS_BOX_MEMO_H

#include <stdint.h>
#include <string.h>

#include "collide.h"
#include "inline.h"

// The boxes at two poses, the older replaced first.
typedef struct hs_box_memo {
	hs_vec3 pos[2], centre[2], half[2];
	hs_quat rot[2];
	uint8_t filled, older; // entries made (0..2), and the one to replace next
} hs_box_memo;

// The entry of m holding the box of `shape` at (pos, rot), made now unless it was at those bits.
static HS_FORCE_INLINE int hs_box_memo_find(hs_box_memo *m, const hs_shape *shape, hs_vec3 pos, hs_quat rot) {
	for (int k = 0; k < m->filled; ++k)
		if (memcmp(&m->pos[k], &pos, sizeof pos) == 0 && memcmp(&m->rot[k], &rot, sizeof rot) == 0)
			return k;
	int k = m->filled < 2 ? m->filled++ : m->older;
	m->older = (uint8_t)(1 - k);
	m->pos[k] = pos;
	m->rot[k] = rot;
	hs_part_world_box(shape, 0, pos, rot, &m->centre[k], &m->half[k]);
	return k;
}

#endif
