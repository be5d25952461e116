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

/* The largest force a scene or state may give, and the largest force a stiffness may make over a
 * radius (kn, kt times the largest radius). A run squares forces and sums the squares: the springs'
 * energies pn^2 / 2 kn and pt^2 / 2 kt (K 22), the solvers' residual norms over 3 N components (N <
 * 2^31: 6.5e9 terms); with every force below 1e145 such a sum stays below 6.5e9 x 1e290 < 1e300,
 * eight decades under the doubles' largest (1.8e308) for the products of these sums with the ratios
 * of stiffnesses, accuracies and step lengths that the solvers take. A value above it makes the run
 * go non-finite (a tangential force of 1e308: its energy is inf at the first step), and no unit
 * system of a laboratory comes near it (1e145 N). */
#define GB_FORCE_MAX 1e145

/* The fixing force that doubles resolve for the scene's stiffest spring *kn and its largest
 * coordinate *x: kn eps x (eps = DBL_EPSILON). Iterations stall between 1/8 of it and it; an
 * accuracy below 1/8 of it cannot be reached (src/scene/admit.c). */
double gb_scene_force_resolution(const gb_scene *s, double *kn, double *x);
#define GB_RESOLUTION_REFUSED 0.125
/* The accuracy to suggest against a resolution: 10 times it, rounded up to a power of ten. */
double gb_scene_suggested_accuracy(double resolution);

#endif
