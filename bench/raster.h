// raster.h — a small software rasteriser, so that the Fig. 13 section can time a frame that is
// drawn as well as checked (the 1999 paper's 17 frames/s were frames drawn on screen).
//
// What it does, all in plain C on one core: a fixed perspective camera over the seed row, a
// 640 x 480 colour buffer (32-bit) and depth buffer (float, 1/depth) cleared every frame, and
// flat-shaded triangles (one Lambert shade per triangle) filled pixel by pixel with edge functions
// and a depth test. Back faces are culled; a triangle with a corner nearer than 5 cm to the eye,
// or behind it, is dropped whole (no clipping). No textures, no anti-aliasing, no display: the
// image stays in memory and a sample of its pixels feeds the bench's checksum.
#ifndef HS_BENCH_RASTER_H
#define HS_BENCH_RASTER_H

#include <stdint.h>

#include "handspring.h"

#define BENCH_RASTER_W 640
#define BENCH_RASTER_H 480

typedef struct bench_raster bench_raster;

/// The buffers and the camera; exits with a message when out of memory.
bench_raster *bench_raster_create(void);
void bench_raster_destroy(bench_raster *r); ///< NULL is fine
/// Clears colour to the background and depth to infinitely far.
void bench_raster_clear(bench_raster *r);
/// One flat-shaded triangle (world coordinates, m); `normal` is its outward unit normal (the
/// triangle is culled when it faces away from the eye); rgb 0xRRGGBB its lit colour.
void bench_raster_triangle(bench_raster *r, hs_vec3 a, hs_vec3 b, hs_vec3 c, hs_vec3 normal, uint32_t rgb);
/// Pixels written since the last clear (each depth-test pass counts).
long bench_raster_pixels(const bench_raster *r);
/// FNV-1a over every 61st pixel of the colour buffer.
uint64_t bench_raster_checksum(const bench_raster *r);
/// Writes the colour buffer as a binary PPM (to look at what is drawn); false when it cannot.
int bench_raster_write_ppm(const bench_raster *r, const char *path);

/// One frame of a world drawn (bench/raster_world.c): clear, the floor (2 m x 2 m in front of the
/// eye), every object's faces (fan-triangulated; grasped ones red, pushed ones orange, the rest
/// blue) and every hand (each finger segment a square tube of finger_radius around the line between
/// its two check points, the palm the polygon of the five finger bases). Returns its checksum.
uint64_t bench_draw_world(bench_raster *r, const hs_world *world);

#endif
