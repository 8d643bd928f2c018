// contact_swept.h — swept detection (contact_swept.c): where a check point's or line's path through
// the frame first met a part (the 1999 paper §3.2 (A)-(B); docs/model.md §3). Private to contact_*.c.
#ifndef HS_CONTACT_SWEPT_H
#define HS_CONTACT_SWEPT_H

#include "contact_part.h"
#include "contact_pass.h"

// The first piece of check point i's path (body frame, from a) that crosses into the part.
bool hs_contact_path_enters(const hs_world_model *model, const hs_shape *shape, const hs_part *part, const hs_hand *hand, int i,
                            int steps, const hs_frame *body, hs_vec3 a, bool inside, hs_clip *hit, hs_vec3 *from,
                            hs_vec3 *to, double *when);
// All four ends (q, p) lie beyond one face plane of the part: the swept surface misses it.
bool hs_contact_sweep_beyond_a_face(const hs_world_model *model, const hs_shape *shape, const hs_part *part,
                                    const hs_vec3 q[2], const hs_vec3 p[2]);
// Check line j, missing the part now (p), touches where its path through the frame swept across it.
void hs_contact_swept_path(const hs_contact_pass *cp, int object, int h, int j, const hs_part *part, const hs_frame *body,
                           int steps, const hs_vec3 start[2], const hs_vec3 p[2]);

#endif
