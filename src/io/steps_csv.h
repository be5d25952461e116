/* steps.csv: a row per load step (docs/run-directory.md#stepscsv). */
#ifndef GB_STEPS_CSV_H
#define GB_STEPS_CSV_H

#include <stdio.h>

#include "gembem/gem.h"

/* The value, or "nan" where it is undefined (any non-finite value): Python's float(), numpy and
 * pandas read it as NaN. fmt is a printf conversion of one double, e.g. "%.10e" or ",%.10e" (a separator first). */
void gb_csv_put(FILE *f, const char *fmt, double v);

void gb_steps_csv_header(FILE *f);
void gb_steps_csv_row(FILE *f, const gb_step_report *r);

#endif
