/* Running a scene's loading program (src/run): a simulation made from a scene, and the loop that
 * takes it through its load steps, each in four phases (docs/architecture.md): control (the
 * step's loads, cut-backs), solve (relaxation to equilibrium, src/solver), measure (the step's
 * report and measures, src/measure) and output (the run directory's files, src/io); and `gembem
 * bem`'s solve of an elastic body alone (gb_bem_run). */
#ifndef GEMBEM_RUN_H
#define GEMBEM_RUN_H

#include <stddef.h>

#include "gembem/gem.h"
#include "gembem/output.h"


/* The scene must outlive the simulation. */
gb_status gb_sim_create(const gb_scene *scene, gb_sim **out, gb_error *err);
void gb_sim_free(gb_sim *sim);

/* Runs the whole loading program from its start: for the initial state (step 0, unless resumed)
 * and each load step, control -> solve -> measure -> output. With `out` (gb_run_output_open or
 * _resume; NULL: none) the loop writes the step's files, checkpoints (also within a step) and solver.history;
 * then on_step (NULL: none), e.g. to print progress, sees the step's report. A step that reaches
 * the iteration cap returns GB_ENOCONV with a message naming the step and its distance from
 * convergence; the simulation then holds the state of the last converged step. */
gb_status gb_sim_run(gb_sim *sim, gb_run_output *out, gb_step_fn on_step, void *user, gb_error *err);

/* The loading program one step at a time, for a caller that looks at the simulation between steps
 * (the Python binding): the first call takes the initial state (step 0: its report, no solve) of a
 * new run, or, on a resumed one, the step after its checkpoint's; each later call the next load
 * step, with its control, solve, measure and (with `out`) output phases as gb_sim_run takes them,
 * so that a run by steps and one by gb_sim_run give the same states and files. *rep: the step's
 * report. A step that fails returns its error (as gb_sim_run's) and leaves the state of the last
 * completed step; the next call takes the failed step again. Past the last step: GB_EINPUT. */
gb_status gb_sim_advance(gb_sim *sim, gb_run_output *out, gb_step_report *rep, gb_error *err);
/* Whether every step of the loading program is taken (by gb_sim_advance or gb_sim_run). */
int gb_sim_finished(const gb_sim *sim);

/* Where a simulation's loading program stands: the last step taken and the program's size. */
typedef struct {
    int step;         /* the last step taken: 0 the initial state, -1 none yet */
    int stage;        /* its stage, 0-based; -1 for step 0 or none */
    int stage_step;   /* its number in its stage, 1-based; 0 for step 0 or none */
    int stage_steps;  /* the steps of its stage; 0 for step 0 or none */
    int total_steps;  /* of the whole program (step 0 not counted) */
    int n_stages;
} gb_run_place;
gb_run_place gb_sim_place(const gb_sim *sim);

/* Calls fn after every iteration that did not converge (for solver.history); NULL: none. gb_sim_run
 * with an output sets its own. */
void gb_sim_on_iteration(gb_sim *sim, gb_iteration_fn fn, void *user);
/* Calls fn between the iterations of every relaxation; NULL: none. gb_sim_run with an output sets
 * its own (checkpoints within a step). */
void gb_sim_on_within_step(gb_sim *sim, gb_within_step_fn fn, void *user);

/* `gembem bem`: the elastic body of a BEM scene solved alone, its files written to dir (new or
 * empty, or any with overwrite; refused before any solve otherwise): scene.yaml, boundary and
 * interior fields as the scene asks, the condensed stiffness, run_info.yaml (how it was made, with
 * `command` as given, and the solve's numbers). A few lines of those numbers go into summary (cap
 * bytes; NULL: not). */
gb_status gb_bem_run(const char *scene, const char *dir, int overwrite, const char *command, char *summary, size_t cap,
                     gb_error *err);

/* The time split of the runs of sim so far (zero before one). */
gb_run_profile gb_sim_profile(const gb_sim *sim);

#endif
