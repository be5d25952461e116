/* Reading numeric CSV tables (grains, contacts): a header row names the columns; '#' lines and
 * blank lines are skipped; every bad field is reported as file:line:column. */
#ifndef GB_CSV_READ_H
#define GB_CSV_READ_H

#include <stdio.h>

#include "gembem/status.h"

#define GB_CSV_MAX_FIELDS 32

typedef struct {
    char path[512];
    FILE *f;
    int line;                       /* 1-based line of the current row */
    char *buf;
    size_t cap;
    int n_header;
    char header[GB_CSV_MAX_FIELDS][32];
    int n_fields;                   /* of the current row */
    char *field[GB_CSV_MAX_FIELDS];
    int column[GB_CSV_MAX_FIELDS];  /* 1-based column where each field starts */
} gb_csv;

gb_status gb_csv_open(const char *path, gb_csv *c, gb_error *err);
void gb_csv_close(gb_csv *c);
/* Index of a header column, or -1. */
int gb_csv_column(const gb_csv *c, const char *name);
/* Advances to the next row (*has_row = 0 at the end); a row must have as many fields as the header. */
gb_status gb_csv_next(gb_csv *c, int *has_row, gb_error *err);
/* Field k of the current row as a finite number. */
gb_status gb_csv_number(const gb_csv *c, int k, double *out, gb_error *err);
/* Reports an error at field k of the current row. */
gb_status gb_csv_fail(const gb_csv *c, int k, gb_error *err, const char *what);

#endif
