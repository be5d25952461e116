/* Running a scene's loading program (src/run): a simulation made from a scene, and the loop that
 * takes it through its load steps, each in four phases (docs/architecture.md): control (the
 * step's loads, cut-backs), solve (relaxation to equilibrium, src/solver), measure (the step's
 * report and measures, src/measure) and output (the run directory's files, src/io); and `gembem
 * bem`'s solve of an elastic body alone (gb_bem_run). */
#ifndef GEMBEM_RUN_H
#define GEMBEM_RUN_H

#include <stddef.h>

#include "gembem/gem.h"
#include "gembem/measure.h"
#include "gembem/output.h"


/* A simulation of a scene: its problem and state, with the solver its settings name. The scene
 * must outlive the simulation. */
gb_status gb_sim_create(const gb_scene *scene, gb_sim **out, gb_error *err);
void gb_sim_free(gb_sim *sim);

/* A run: a simulation taken through its scene's loading program. It holds where the program
 * stands, the state a failed step goes back to, the external work done, the time split and the
 * hooks; the simulation (which must outlive it) holds the state. A new run starts the program from
 * its start, from the simulation's current state. */
typedef struct gb_run gb_run;
gb_status gb_run_create(gb_sim *sim, gb_run **out, gb_error *err);
void gb_run_free(gb_run *run);
gb_sim *gb_run_sim(const gb_run *run);

/* Runs the whole loading program (the rest of it, resumed): for the initial state (step 0, unless
 * resumed) and each load step, control -> solve -> measure -> output. With `out`
 * (gb_run_output_open or gb_run_resume; NULL: none) the loop writes the step's files, checkpoints
 * (also within a step) and solver.history; then on_step (NULL: none), e.g. to print progress, sees
 * the step's report. A step that reaches the iteration cap returns GB_ENOCONV with a message naming
 * the step and its distance from convergence; the simulation then holds the state of the last
 * converged step. */
gb_status gb_run_program(gb_run *run, gb_run_output *out, gb_step_fn on_step, void *user, gb_error *err);
/* The whole loading program of sim in a run of its own (gb_run_create, gb_run_program, gb_run_free):
 * each call runs the program from its start, from sim's current state. */
gb_status gb_sim_run(gb_sim *sim, gb_run_output *out, gb_step_fn on_step, void *user, gb_error *err);

/* The loading program one step at a time, for a caller that looks at the simulation between steps
 * (the Python binding): the first call takes the initial state (step 0: its report, no solve) of a
 * new run, or, on a resumed one, the step after its checkpoint's; each later call the next load
 * step, with its control, solve, measure and (with `out`) output phases as gb_run_program takes
 * them, so that a run by steps and one by gb_run_program give the same states and files. *rep: the
 * step's report. A step that fails returns its error (as gb_run_program's) and leaves the state of
 * the last completed step; the next call takes the failed step again. Past the last step:
 * GB_EINPUT. */
gb_status gb_run_advance(gb_run *run, gb_run_output *out, gb_step_report *rep, gb_error *err);
/* Whether every step of the loading program is taken (by gb_run_advance or gb_run_program). */
int gb_run_finished(const gb_run *run);

/* Reopens the run directory of an interrupted run (docs/run-directory.md, "Checkpoints and
 * resume") for run, new, of a simulation just created from the same scene: the checkpoint's state
 * into the simulation and its place into run (refused, GB_EINPUT, if the scene changed), the
 * appended files cut back to the checkpoint, run_info.yaml told of the resume. gb_run_program then
 * continues after the checkpoint's step, or within the step it was taken in. Nothing is changed if
 * the checkpoint cannot be used. */
gb_status gb_run_resume(gb_run *run, const char *dir, const char *command, gb_run_output **out, gb_error *err);

/* Where a run's loading program stands: the last step taken and the program's size. */
typedef struct {
    int step;         /* the last step taken: 0 the initial state, -1 none yet */
    int stage;        /* its stage, 0-based; -1 for step 0 or none */
    int stage_step;   /* its number in its stage, 1-based; 0 for step 0 or none */
    int stage_steps;  /* the steps of its stage; 0 for step 0 or none */
    int total_steps;  /* of the whole program (step 0 not counted) */
    int n_stages;
} gb_run_place;
gb_run_place gb_run_where(const gb_run *run);

/* Calls fn after every iteration that did not converge; NULL: none. With an output whose scene
 * asks for solver.history, gb_run_program and gb_run_advance write history.csv instead. */
void gb_run_on_iteration(gb_run *run, gb_iteration_fn fn, void *user);
/* Calls fn every few seconds while a load step runs for longer than ten times the median of the
 * run's earlier steps (and at least ten seconds); NULL: none. The CLI prints it. */
void gb_run_on_progress(gb_run *run, gb_progress_fn fn, void *user);
/* The external work the run has done on its simulation, and the elastic energy at its start, for
 * gb_micro_measure (gembem/measure.h). */
gb_work_accounts gb_run_work(const gb_run *run);
/* The time split of the run so far (zero before its first call). */
gb_run_profile gb_run_phases(const gb_run *run);

/* `gembem bem`: the elastic body of a BEM scene solved alone, its files written to dir (new or
 * empty, or any with overwrite; refused before any solve otherwise): scene.yaml, boundary and
 * interior fields as the scene asks, the condensed stiffness, run_info.yaml (how it was made, with
 * `command` as given, and the solve's numbers). A few lines of those numbers go into summary (cap
 * bytes; NULL: not). */
gb_status gb_bem_run(const char *scene, const char *dir, int overwrite, const char *command, char *summary, size_t cap,
                     gb_error *err);

#endif
