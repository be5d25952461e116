/* The run directory: steps.csv, VTK snapshots, the final state, a copy of the scene, run_info.yaml.
 * A run directory documents itself: the scene and the gembem version are in it. */
#ifndef GEMBEM_OUTPUT_H
#define GEMBEM_OUTPUT_H

#include <stddef.h>

#include "gembem/gem.h"

typedef struct gb_run_output gb_run_output;

/* Creates (or, with overwrite, reuses) the run directory for a simulation not yet run, for a run
 * (gb_run_program, gembem/run.h) to write its steps into (the scene's hash, for resuming, is taken
 * from its initial state). `command` is recorded in run_info.yaml. A run directory interrupted
 * is reopened by gb_run_resume (gembem/run.h). */
gb_status gb_run_output_open(const char *dir, const gb_sim *sim, int overwrite, const char *command,
                             gb_run_output **out, gb_error *err);
/* Reads the scene's path from dir's checkpoint, into path. */
gb_status gb_run_output_resume_scene(const char *dir, char *path, size_t cap, gb_error *err);
/* Writes the final state (state.yaml, state_grains.csv, state_contacts.csv), records the run's
 * status and time split in run_info.yaml and frees o. */
gb_status gb_run_output_close(gb_run_output *o, const gb_sim *sim, gb_status run_status, const char *message,
                              gb_error *err);

/* The state files alone: a scene can start from dir/state.yaml with `initial_state:`. */
gb_status gb_state_write(const char *dir, const gb_sim *sim, gb_error *err);
/* The force-carrying contacts as CSV (i, j, pn, pt, nx, ny, overlap, elastic energy (K 22), the
 * step's dissipation, end points), readable as a scene's contacts file (it reads i, j, pt). */
gb_status gb_contacts_csv_write(const char *path, const gb_sim *sim, gb_error *err);
/* The grains (x, y, r, rotation) as CSV, readable as a scene's grains file. */
gb_status gb_grains_csv_write(const char *path, const gb_sim *sim, gb_error *err);
/* VTK XML PolyData that ParaView opens: grains as points with radius, rotation and |F|; contacts
 * (and the box) as lines with pn, pt. */
gb_status gb_vtk_write_grains(const char *path, const gb_sim *sim, gb_error *err);
gb_status gb_vtk_write_contacts(const char *path, const gb_sim *sim, gb_error *err);

#endif
