/* The geometric admission of a scene: grains against their box or cavity and against each other. */
#ifndef GB_ADMIT_H
#define GB_ADMIT_H

#include "gembem/scene.h"

/* Refuses (GB_EINPUT, at the grain's file:line:column) a grain larger than its space, a grain whose
 * centre is outside it, a disc that crosses a wall or the cavity's boundary by more than
 * s->max_overlap of its radius, two grains that overlap by more than s->max_overlap of the smaller
 * radius; counts the overlaps it accepts in s->overlaps. mesh: the host's (NULL: the box). */
gb_status gb_scene_admit(gb_scene *s, const gb_bem_mesh *mesh, gb_error *err);

#endif
