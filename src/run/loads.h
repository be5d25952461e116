/* The control phase's loads of a load step (src/run/program.c). */
#ifndef GB_RUN_LOADS_H
#define GB_RUN_LOADS_H

#include "gem/sim.h"
#include "gembem/solver.h"

/* The loads of a sub-step of size h (a fraction of the step's increment) of stage sg: the host's
 * loads grow (grains and cavity held: f0 changes), or the walls move (strain control, and the
 * shear increment of shear_mean_stress), the grains following them affinely with the line
 * search's predictor. */
gb_status gb_run_apply_loads(gb_sim *sim, const gb_stage *sg, double h, gb_error *err);
/* GB_EINPUT, with what the stage needs, when servo walls cannot reach their target under the
 * grains' weight (frictionless walls); GB_OK otherwise. */
gb_status gb_run_weight_reachable(const gb_sim *sim, const gb_stage *sg, const gb_wall_control *wc, gb_error *err);

#endif
