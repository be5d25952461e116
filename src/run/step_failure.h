/* The error of a load step that failed (src/run/program.c). */
#ifndef GB_RUN_STEP_FAILURE_H
#define GB_RUN_STEP_FAILURE_H

#include "gembem/solver.h"
#include "io/run_progress.h"

/* The error of the step c of stage sg, ended by st with the last relaxation's
 * result *res: GB_ENOCONV names the step, why it stopped (iterations, stall, time limit), its
 * largest fixing force and what to change; another error is prefixed with the step. */
gb_status gb_run_step_failed(const gb_sim *sim, const gb_run_step *c, const gb_stage *sg, gb_status st,
                             const gb_solve_result *res, gb_error *err);

#endif
