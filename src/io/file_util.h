/* Files that appear whole or not at all: written to NAME.tmp, renamed on success. */
#ifndef GB_FILE_UTIL_H
#define GB_FILE_UTIL_H

#include <stdio.h>

#include "gembem/status.h"

typedef struct {
    FILE *f;
    char path[1024], tmp[1040];
} gb_atomic_file;

gb_status gb_atomic_open(gb_atomic_file *a, const char *path, gb_error *err);
/* Closes and renames; on a write error removes the temporary file. */
gb_status gb_atomic_commit(gb_atomic_file *a, gb_error *err);
void gb_atomic_abort(gb_atomic_file *a);

#endif
