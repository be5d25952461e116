/* The elastic host of a hybrid simulation (docs/method.md sections 9-10), as a run leaves it: the
 * cavity's displacements, the host's forces on it, the boundary particles' balance, the resultants
 * of its boundary groups. Every function is for a simulation with a host. Functions of the
 * simulation (src/gem/sim.c), which holds the host (src/hybrid) and its state. */
#ifndef GEMBEM_HYBRID_H
#define GEMBEM_HYBRID_H

#include "gembem/gem.h"

/* The cavity's degrees of freedom: 2 per cavity element (0 without a host). */
int gb_sim_host_dofs(const gb_sim *sim);
/* Into each array that is not NULL (gb_sim_host_dofs values, 2 per cavity element in the mesh's
 * order): the elements' displacements u, the host's forces F = K u + f0 (what the grains must put
 * on each element) and the boundary particles' fixing forces (F less the grains' contact forces:
 * zero at equilibrium to the accuracy). */
void gb_sim_host_cavity(const gb_sim *sim, double *u, double *force, double *fixing);
/* A boundary group's total force (traction times length over its elements: what the outside puts
 * on the body) and its mean displacement, for the current cavity displacements and loads (one
 * solve of the host); GB_EINPUT for a group the mesh does not have. */
gb_status gb_sim_host_group_force(const gb_sim *sim, const char *group, double force[2], double disp[2],
                                  gb_error *err);

#endif
