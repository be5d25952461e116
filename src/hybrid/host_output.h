/* The host's outputs in a run directory (hybrid scenes). */
#ifndef GB_HOST_OUTPUT_H
#define GB_HOST_OUTPUT_H

#include <stdio.h>

#include "gembem/gem.h"

/* host_particles.csv (cavity elements: displacement, host force K u + f0, grains' force),
 * host_boundary.csv and .vtp (the whole boundary), host_field.vtu (interior displacement and
 * stress on a grid) for the simulation's current cavity displacements. */
gb_status gb_host_write_outputs(const char *dir, const gb_sim *sim, gb_error *err);

/* One row per group with a displacement condition: the step, the group, its prescribed
 * displacement and the force on it (the body's load-displacement curve). */
gb_status gb_host_write_step(FILE *f, int step, const gb_sim *sim, gb_error *err);

#endif
