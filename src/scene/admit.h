/* The geometric admission of a scene: grains against their box or cavity and against each other. */
#ifndef GB_ADMIT_H
#define GB_ADMIT_H

#include "gembem/scene.h"

/* gb_scene_admit: gembem/scene.h. */

/* Appends a warning to s->warning (said before the run, kept in run_info.yaml). */
void gb_scene_warn(gb_scene *s, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* The fixing force that doubles resolve for the scene's stiffest spring *kn and its largest
 * coordinate *x: kn eps x (eps = DBL_EPSILON). Iterations stall between 1/8 of it and it; an
 * accuracy below 1/8 of it cannot be reached (src/scene/admit.c). */
double gb_scene_force_resolution(const gb_scene *s, double *kn, double *x);
#define GB_RESOLUTION_REFUSED 0.125
/* The accuracy to suggest against a resolution: 10 times it, rounded up to a power of ten. */
double gb_scene_suggested_accuracy(double resolution);

#endif
