/* The files of a step's measures in the run directory (docs/measures.md). */
#ifndef GB_MEASURE_OUTPUT_H
#define GB_MEASURE_OUTPUT_H

#include "measure/step_measures.h"

/* One row of localisation.csv (created at step 0) and, with m->fields, the files of fields/ for
 * the step. */
gb_status gb_measure_write_step(const char *dir, const gb_step_measures *m, gb_error *err);

#endif
