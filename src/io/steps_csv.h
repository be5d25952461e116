/* steps.csv: a row per load step (docs/run-directory.md#stepscsv). */
#ifndef GB_STEPS_CSV_H
#define GB_STEPS_CSV_H

#include <stdio.h>

#include "gembem/gem.h"

void gb_steps_csv_header(FILE *f);
void gb_steps_csv_row(FILE *f, const gb_step_report *r);

#endif
