/* Shared by the fuzz targets (libFuzzer, and tests/fuzz's replay of their corpora): each target
 * writes the input to a file in a per-process directory that holds copies of the fixtures (the
 * meshes, grains, contacts and state files that scenes name by relative path) and reads it
 * through the entry point the command line uses. */
#ifndef GB_FUZZ_H
#define GB_FUZZ_H

#include <stddef.h>
#include <stdint.h>

#include "gembem/status.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Writes data to `name` in the fixture directory (made and filled on the first call, removed at
 * exit) and returns the file's path. */
const char *gb_fuzz_write(const char *name, const uint8_t *data, size_t size);
/* The path of a fixture (or of any name) in that directory. */
const char *gb_fuzz_path(const char *name);
/* With GB_FUZZ_SHOW set (replaying by hand), prints the reader's verdict on the input. */
void gb_fuzz_show(gb_status st, const gb_error *err);
/* 1 if the input contains the string (picks a fixture scene from the input, reproducibly). */
int gb_fuzz_contains(const uint8_t *data, size_t size, const char *word);

#endif
