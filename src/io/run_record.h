/* What run_info.yaml records of a run beyond how it was started (docs/run-directory.md#run_infoyaml):
 * every setting as the run used it, the machine, where the time went. */
#ifndef GB_RUN_RECORD_H
#define GB_RUN_RECORD_H

#include <stdio.h>

#include "gembem/gem.h"

/* The record's first keys, how the directory was made: gembem_version, command, scene, and the
 * time `when` (NULL: now, UTC) as `when_key` ("started" in run_info.yaml, "made" in pack_info.yaml). */
void gb_run_record_origin(FILE *f, const char *command, const char *scene, const char *when_key, const char *when);

/* settings: the scene's every setting, defaults spelled out. */
void gb_run_record_settings(FILE *f, const gb_scene *sc);
/* machine: CPU model and cores, memory, the BLAS's and OpenMP's threads. */
void gb_run_record_machine(FILE *f);
/* time: the split of this process's time (total seconds since it opened the run directory) by the
 * loop's phases (p: the run's, gb_run_phases) and the solver's parts (sim may be NULL: none);
 * close: the final state's writing. */
void gb_run_record_times(FILE *f, const gb_sim *sim, gb_run_profile p, double total, double close);

#endif
