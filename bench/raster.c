// raster.c — the software rasteriser of raster.h: a perspective camera, edge-function filling
// with a depth test, one Lambert shade per triangle.
#include "raster.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define RASTER_NEAR 0.05 // m: a triangle with a corner nearer than this to the eye is dropped
#define RASTER_FOV_DEG 60.0 // vertical field of view
#define RASTER_BACKGROUND 0x202830u

struct bench_raster {
	uint32_t *colour;
	float *depth; // 1 / distance along the view axis; 0: nothing drawn
	hs_vec3 eye, right, up, forward; // the camera's frame
	double focal;                    // pixels: the image plane's distance
	hs_vec3 light;                   // unit: toward the light
	long pixels;
};

bench_raster *bench_raster_create(void) {
	bench_raster *r = calloc(1, sizeof *r);
	size_t n = (size_t)BENCH_RASTER_W * BENCH_RASTER_H;
	if (r) {
		r->colour = malloc(n * sizeof *r->colour);
		r->depth = malloc(n * sizeof *r->depth);
	}
	if (!r || !r->colour || !r->depth) {
		fprintf(stderr, "bench: no memory for a %dx%d image\n", BENCH_RASTER_W, BENCH_RASTER_H);
		exit(2);
	}
	// the seed row (y = 0.3 m) from the front and above, the hands' whole loop in view (up to
	// 0.2 m above a grasp, 0.5 m for a hand that grasps nothing)
	hs_vec3 target = hs_v3(0.0, 0.3, 0.2);
	r->eye = hs_v3(0.0, -0.6, 0.6);
	r->forward = hs_normalize(hs_sub(target, r->eye));
	r->right = hs_normalize(hs_cross(r->forward, hs_v3(0.0, 0.0, 1.0)));
	r->up = hs_cross(r->right, r->forward);
	r->focal = 0.5 * BENCH_RASTER_H / tan(0.5 * RASTER_FOV_DEG * HS_PI / 180.0);
	r->light = hs_normalize(hs_v3(0.3, -0.5, 0.8));
	return r;
}

void bench_raster_destroy(bench_raster *r) {
	if (!r)
		return;
	free(r->colour);
	free(r->depth);
	free(r);
}

void bench_raster_clear(bench_raster *r) {
	size_t n = (size_t)BENCH_RASTER_W * BENCH_RASTER_H;
	for (size_t i = 0; i < n; ++i) {
		r->colour[i] = RASTER_BACKGROUND;
		r->depth[i] = 0.0f;
	}
	r->pixels = 0;
}

// A corner on screen: pixel coordinates and 1 / depth (affine in screen space).
typedef struct corner {
	double x, y, inv;
} corner;

static int project(const bench_raster *r, hs_vec3 p, corner *out) {
	hs_vec3 d = hs_sub(p, r->eye);
	double z = hs_dot(d, r->forward);
	if (!(z >= RASTER_NEAR))
		return 0;
	out->x = 0.5 * BENCH_RASTER_W + r->focal * hs_dot(d, r->right) / z;
	out->y = 0.5 * BENCH_RASTER_H - r->focal * hs_dot(d, r->up) / z;
	out->inv = 1.0 / z;
	return 1;
}

static uint32_t shade(const bench_raster *r, hs_vec3 normal, uint32_t rgb) {
	double lit = hs_dot(normal, r->light);
	double k = 0.25 + 0.75 * (lit > 0.0 ? lit : 0.0);
	uint32_t out = 0;
	for (int shift = 0; shift <= 16; shift += 8)
		out |= (uint32_t)(k * (double)((rgb >> shift) & 0xffu)) << shift;
	return out;
}

// Fills the triangle (a, b, c), counter-clockwise on screen, pixel centres inside or on an edge:
// the three edge functions and 1 / depth stepped by their constant increments along each row.
static void fill(bench_raster *r, corner a, corner b, corner c, uint32_t colour) {
	double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
	if (!(area > 0.0))
		return;
	int x0 = (int)floor(fmin(a.x, fmin(b.x, c.x))), x1 = (int)ceil(fmax(a.x, fmax(b.x, c.x)));
	int y0 = (int)floor(fmin(a.y, fmin(b.y, c.y))), y1 = (int)ceil(fmax(a.y, fmax(b.y, c.y)));
	x0 = x0 < 0 ? 0 : x0;
	y0 = y0 < 0 ? 0 : y0;
	x1 = x1 > BENCH_RASTER_W - 1 ? BENCH_RASTER_W - 1 : x1;
	y1 = y1 > BENCH_RASTER_H - 1 ? BENCH_RASTER_H - 1 : y1;
	// edge e(p) = A x + B y + C, one per corner (zero on the opposite edge), over the area
	double ea[3] = {-(c.y - b.y), -(a.y - c.y), -(b.y - a.y)}, eb[3] = {c.x - b.x, a.x - c.x, b.x - a.x};
	double ec[3] = {-(ea[0] * b.x + eb[0] * b.y), -(ea[1] * c.x + eb[1] * c.y), -(ea[2] * a.x + eb[2] * a.y)};
	double inv_dx = (ea[0] * a.inv + ea[1] * b.inv + ea[2] * c.inv) / area;
	for (int y = y0; y <= y1; ++y) {
		double px = x0 + 0.5, py = y + 0.5;
		double w0 = ea[0] * px + eb[0] * py + ec[0], w1 = ea[1] * px + eb[1] * py + ec[1];
		double w2 = ea[2] * px + eb[2] * py + ec[2];
		double inv = (w0 * a.inv + w1 * b.inv + w2 * c.inv) / area;
		size_t i = (size_t)y * BENCH_RASTER_W + (size_t)x0;
		for (int x = x0; x <= x1; ++x, ++i, w0 += ea[0], w1 += ea[1], w2 += ea[2], inv += inv_dx) {
			if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0 || !((float)inv > r->depth[i]))
				continue;
			r->depth[i] = (float)inv;
			r->colour[i] = colour;
			r->pixels++;
		}
	}
}

void bench_raster_triangle(bench_raster *r, hs_vec3 a, hs_vec3 b, hs_vec3 c, hs_vec3 normal, uint32_t rgb) {
	if (hs_dot(normal, hs_sub(a, r->eye)) >= 0.0) // faces away from the eye
		return;
	corner pa, pb, pc;
	if (!project(r, a, &pa) || !project(r, b, &pb) || !project(r, c, &pc))
		return;
	// screen y grows downward: a front face is clockwise there; make it counter-clockwise for fill
	double area = (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
	if (area < 0.0)
		fill(r, pa, pc, pb, shade(r, normal, rgb));
	else
		fill(r, pa, pb, pc, shade(r, normal, rgb));
}

long bench_raster_pixels(const bench_raster *r) { return r->pixels; }

uint64_t bench_raster_checksum(const bench_raster *r) {
	uint64_t h = 14695981039346656037ull;
	size_t n = (size_t)BENCH_RASTER_W * BENCH_RASTER_H;
	for (size_t i = 0; i < n; i += 61) {
		h ^= r->colour[i];
		h *= 1099511628211ull;
	}
	return h;
}

int bench_raster_write_ppm(const bench_raster *r, const char *path) {
	FILE *f = fopen(path, "wb");
	if (!f)
		return 0;
	fprintf(f, "P6\n%d %d\n255\n", BENCH_RASTER_W, BENCH_RASTER_H);
	size_t n = (size_t)BENCH_RASTER_W * BENCH_RASTER_H;
	for (size_t i = 0; i < n; ++i) {
		unsigned char px[3] = {(unsigned char)(r->colour[i] >> 16), (unsigned char)(r->colour[i] >> 8),
		                       (unsigned char)r->colour[i]};
		fwrite(px, 1, 3, f);
	}
	return fclose(f) == 0;
}
