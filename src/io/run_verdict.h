/* A run's verdict and its warnings, read back from its steps.csv and localisation.csv at its end
 * (so that a resumed run judges all its steps): run_info.yaml and stderr (docs/run-directory.md#warnings). */
#ifndef GB_RUN_VERDICT_H
#define GB_RUN_VERDICT_H

#include <stdio.h>

#include "gembem/scene.h"

/* The accuracy is not small against the contact forces above this share of the mean normal
 * contact force at a converged step: a contact force is then known to a percent at best. */
#define GB_WARN_ACCURACY 1e-2
/* Not jammed: fewer contacts per load-carrying grain than a frictional packing needs (3 in 2D,
 * infinite friction; 4 frictionless), from GB_WARN_JAM_GRAINS grains (fewer make a structure, not
 * a packing: the three discs). */
#define GB_WARN_COORDINATION 3.0
#define GB_WARN_JAM_GRAINS 20
/* The contact count swings: it changes by more than this share of the larger count between two
 * consecutive converged steps. */
#define GB_WARN_SWING 0.25
/* The linear host leaves its range: the largest principal strain of the affine map that fits its
 * cavity's displacements at the end (host_boundary.csv) above this; its geometry at rest is then
 * no longer the body's (docs/hybrid.md). */
#define GB_WARN_HOST_STRAIN 0.02

enum { GB_VERDICT_WARNINGS = 8 };

typedef struct {
    int steps;               /* converged load steps (step 0 aside) */
    double residual;         /* the largest of relative_residual, relative_wall_residual, host_balance */
    int residual_step;
    double residual_allowed; /* accuracy / force_scale at that step */
    double coulomb;          /* the largest coulomb_excess */
    int coulomb_step;
    int n_warnings;
    char warning[GB_VERDICT_WARNINGS][640];
} gb_run_verdict;

/* Reads dir/steps.csv and dir/localisation.csv (steps >= 1). */
gb_status gb_run_verdict_read(const char *dir, const gb_scene *sc, gb_run_verdict *v, gb_error *err);
/* verdict: and warnings: of run_info.yaml. */
void gb_run_verdict_write(FILE *f, const gb_run_verdict *v);

#endif
