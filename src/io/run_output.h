/* What a run (src/run/program.c) writes of each step into the run directory of gembem/output.h:
 * the step's rows and files, solver.history, checkpoints (also within a step), and a resume's
 * reopening. */
#ifndef GB_RUN_OUTPUT_H
#define GB_RUN_OUTPUT_H

#include "gembem/output.h"
#include "io/run_progress.h"
#include "measure/step_measures.h"

/* One row of steps.csv and micromechanics.csv (flushed at once), the step's measures
 * (localisation.csv, fields/), the snapshots the scene asks for at this step, and the checkpoint
 * of the simulation and the run's progress p when due (output.checkpoint_every,
 * output.checkpoint_minutes). */
gb_status gb_run_output_step(gb_run_output *o, const gb_sim *sim, const gb_run_progress *p, const gb_step_report *rep,
                             const gb_step_measures *m, gb_error *err);
/* Whether the step's fields/ files are due (output.measures_every). */
int gb_run_output_fields_due(const gb_run_output *o, int step);
/* One row of history.csv (solver.history), a gb_iteration_fn with o as user. A write error is
 * reported by the next gb_run_output_step or gb_run_output_close. */
void gb_run_output_iteration(void *o, const gb_iteration_report *rep);
/* Between two iterations of a relaxation: checkpoint.txt within the load step in progress when
 * output.checkpoint_minutes have passed since the last checkpoint (docs/run-directory.md,
 * "Checkpoints and resume"); a history.csv that could not be written stops the run here. */
gb_status gb_run_output_within_step(gb_run_output *o, const gb_sim *sim, const gb_run_progress *p, gb_error *err);
/* The run's time split so far, for run_info.yaml's `time` (at the end of each call of the run). */
void gb_run_output_phases(gb_run_output *o, const gb_run_profile *phases);
/* gb_run_resume (gembem/run.h): the checkpoint into sim and p. */
gb_status gb_run_output_resume(const char *dir, gb_sim *sim, gb_run_progress *p, const char *command,
                               gb_run_output **out, gb_error *err);

#endif
