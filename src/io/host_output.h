/* The host's outputs in a run directory (hybrid scenes). */
#ifndef GB_HOST_OUTPUT_H
#define GB_HOST_OUTPUT_H

#include <stdio.h>

#include "gembem/gem.h"
#include "gembem/scene.h"

/* host_particles.csv (cavity elements: displacement, host force K u + f0, grains' force),
 * host_boundary.csv and .vtp (the whole boundary), host_field.vtu (interior displacement and
 * stress on a grid) for the simulation's current cavity displacements. */
gb_status gb_host_write_outputs(const char *dir, const gb_sim *sim, gb_error *err);

/* host_steps.csv, the body's load-displacement curve: one row per step and boundary group (the
 * cavity included): its condition, mean displacement (length-weighted; the prescribed one on a
 * displaced group), the total force the outside puts on it (tension-positive tractions x length;
 * on the cavity: the grains' force), and for an unbounded host the remote stress. */
void gb_host_write_steps_header(FILE *f, const gb_scene *scene);
gb_status gb_host_write_step(FILE *f, int step, const gb_sim *sim, gb_error *err);

#endif
