// spring_contact.h — the floor and the walls of the spring model: normal force, static and sliding
// friction (§4.2), hard constraints (§4.5, Fig. 4).
#ifndef HS_SPRING_CONTACT_H
#define HS_SPRING_CONTACT_H

#include "spring_geom.h"
#include "spring_integrate.h"

// What the floor sees of one object's frame.
typedef struct hs_spring_support {
	hs_integrator integrator;
	double dt;                  // s
	double tol;                 // m: the world's floor tolerance
	hs_vec3 gravity;            // m/s²
	const hs_spring_def *def;   // friction and walls
	const hs_spring_params *sp; // the object's spring
	const hs_spring_geom *g;    // its reach
	bool attached;              // on the spring
	hs_vec3 axis;               // the spring's direction when G and the stylus coincide
	hs_vec3 stylus_start;       // m: the stylus at the frame start,
	hs_vec3 stylus_end;         // at its end,
	hs_vec3 stylus_velocity;    // m/s: and in between
	const hs_vec3 *load;        // N: the force of the objects it touches (spring_rest.c), NULL when none
} hs_spring_support;

// Wall k (x_min, x_max, y_min, y_max): its normal into the room.
hs_vec3 hs_spring_wall_normal(int k);
// The walls the object (G at p) touches within tol: bit k for wall k (0 when walls are off).
unsigned hs_spring_walls_near(const hs_spring_walls *walls, const hs_spring_geom *g, hs_vec3 p, double tol);
// Removes the components of `vec` that push into a wall the object (G at p) touches within tol.
void hs_spring_wall_block(const hs_spring_walls *walls, const hs_spring_geom *g, hs_vec3 p, double tol,
                          hs_vec3 *vec);
// Projects the object inside the walls; with `vel`, removes the velocity into a wall it was stopped at.
void hs_spring_wall_project(const hs_spring_walls *walls, const hs_spring_geom *g, hs_vec3 *p, hs_vec3 *vel);
// A whole frame on the floor when the object lies on it and is pressed onto it: false (p, v untouched)
// when it is not; otherwise friction holds it or it slides (*sliding), and it ends on the floor.
bool hs_spring_floor_step(const hs_spring_support *su, hs_spring_segment *sg, hs_vec3 *p, hs_vec3 *v,
                          bool *sliding);
// After a frame in the air: an object below the floor lands on it (true).
bool hs_spring_land(const hs_spring_geom *g, hs_vec3 *p, hs_vec3 *v);

#endif
