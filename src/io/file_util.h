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
/* The same, the data synced to the disk first and the directory after the rename, so that the file
 * survives a power cut whole (checkpoints). */
gb_status gb_atomic_commit_durable(gb_atomic_file *a, gb_error *err);
void gb_atomic_abort(gb_atomic_file *a);
/* The whole of it: open, the content printed by write(f, data), commit. */
gb_status gb_atomic_write(const char *path, void (*write)(FILE *f, const void *data), const void *data, gb_error *err);

/* Rows 0 .. m of a table into f in their order, each printed by row(buf, cap, k, ctx) into a
 * buffer of cap >= GB_ROW_MAX bytes (its length returned, as snprintf's), in blocks formatted on
 * `threads` OpenMP threads: printing doubles exactly (%.17g) is most of the time of writing a large
 * state (1e6 discs: some 9 s on one thread for its 421 MB). The same bytes on any thread count. */
enum { GB_ROW_MAX = 1024 };
typedef int (*gb_row_fn)(char *buf, size_t cap, int k, const void *ctx);
void gb_write_rows(FILE *f, int m, int threads, gb_row_fn row, const void *ctx);

/* The longest output directory path gembem writes into: its files' paths (the directory, a
 * subfolder, a numbered name and ".tmp") then fit the 1 024 bytes of its path buffers. */
enum { GB_DIR_MAX = 900 };
/* GB_EINPUT, naming dir as `what`, if its path is longer than GB_DIR_MAX. */
gb_status gb_dir_length_check(const char *dir, const char *what, gb_error *err);

/* mkdir -p */
gb_status gb_make_dirs(const char *path, gb_error *err);
/* Copies a file (atomically). */
gb_status gb_copy_file(const char *from, const char *to, gb_error *err);
/* An output directory may be made: absent, or an empty directory (its lock file aside), or
 * (overwrite) any directory that no other process writes (io/dir_lock.h); its path not too long
 * (GB_DIR_MAX); else GB_EINPUT, the message naming it as `what` ("run directory"). */
gb_status gb_output_dir_check(const char *dir, int overwrite, const char *what, gb_error *err);
/* Its last part: unless overwrite, dir must be empty (its lock file aside). */
gb_status gb_dir_empty_check(const char *dir, int overwrite, const char *what, gb_error *err);

/* A CSV value, or "nan" where it is undefined (any non-finite value): Python's float(), numpy and
 * pandas read it as NaN. fmt holds one printf conversion of a double, with text around it, e.g.
 * ",%.10e" or "%.10e\n". */
void gb_csv_put(FILE *f, const char *fmt, double v);

/* For tests of interrupted runs (tests/cli/run_resume.sh): with GB_TEST_KILL_AT=N in the
 * environment, the N-th call in the process writes a few bytes to `torn` (may be NULL), as a write
 * cut short would leave, and raises SIGKILL. Called before each appended row and each atomic rename. */
void gb_test_kill_point(FILE *torn);
/* For the same tests: with GB_TEST_CHECKPOINT_ITERATIONS=N in the environment, true at every N-th
 * call in the process (a checkpoint within a load step every N iterations, whatever the clock). */
int gb_test_checkpoint_due(void);

#endif
