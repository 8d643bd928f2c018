// spring_geom.h — where an object of the spring model reaches, and point and ray queries on it.
#ifndef HS_SPRING_GEOM_H
#define HS_SPRING_GEOM_H

#include <stdbool.h>

#include "body.h"

// How object–object collisions see a shape (spring_collide.c): exact sphere, a box whose faces
// lie on its world-axis bounding box, a turned (oriented) box, or any other convex part set (libccd).
typedef enum hs_spring_form { HS_FORM_SPHERE, HS_FORM_AXIS_BOX, HS_FORM_BOX, HS_FORM_CONVEX } hs_spring_form;

// Where an object reaches, relative to G: its world-axis bounding box (floor, walls, picking, the
// broad phase) and its true shape (collisions). Objects keep their orientation in the spring
// model (no torque, §4.2), so both are fixed per object.
typedef struct hs_spring_geom {
	hs_vec3 lo, hi; // m: offsets of the bounding box's corners from G
	double radius;  // m, spheres only
	bool sphere;
	hs_spring_form form;
	int shape;      // index into world->model.shapes
	hs_quat rot;    // body → world
	hs_vec3 half;   // m: half extents of a box in its body frame
	double inner;   // m: the largest ball about G inside it (a sphere's radius, a box's smallest half
	                // extent; other shapes an eighth of the bounding box's): the swept collisions' step
} hs_spring_geom;

// The reach of `body`, made of `shape`, in its present orientation.
hs_spring_geom hs_spring_geom_of(const hs_shape *shape, const hs_body *body);
// True when the point s lies in the object whose G is at p.
bool hs_spring_geom_inside(const hs_spring_geom *g, hs_vec3 p, hs_vec3 s);
// m from s to the surface of the object whose G is at p (≤ 0 inside).
double hs_spring_geom_distance(const hs_spring_geom *g, hs_vec3 p, hs_vec3 s);
// The ray o + t d (d unit) against the object whose G is at p: the entry t in [0, range], or -1.
double hs_spring_geom_ray(const hs_spring_geom *g, hs_vec3 p, hs_vec3 o, hs_vec3 d, double range);

#endif
