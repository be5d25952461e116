/* Checkpoints of a run directory (docs/run-directory.md, "Checkpoints and resume"): everything a
 * completed load step leaves that the next one reads, or, within a load step, everything its next
 * iteration and the rest of the step read, exactly (hex floats), so that `gembem run --resume` goes
 * on as if the run had never stopped; and the lengths of the files the run appends to, so that what
 * an interrupted run wrote after its last checkpoint is cut off before the resumed run appends. */
#ifndef GB_CHECKPOINT_H
#define GB_CHECKPOINT_H

#include <limits.h>
#include <stdint.h>

#include "io/run_progress.h"

/* realpath() writes up to PATH_MAX bytes into its buffer */
#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

#define GB_CHECKPOINT_NAME "checkpoint.txt"
#define GB_CHECKPOINT_TAIL 64
#define GB_CHECKPOINT_MAX_FILES 8

/* A file the run appends to, as it was at the checkpoint. Its last bytes are kept too: a writer
 * may rewrite them in place (fields/triangles.pvd seeks back over its closing tags). */
typedef struct {
    char name[64];     /* relative to the run directory */
    long long length;  /* bytes; -1: the file did not exist */
    int n_tail;
    unsigned char tail[GB_CHECKPOINT_TAIL];
} gb_checkpoint_file;

typedef struct {
    uint64_t scene_hash;
    char scene_path[PATH_MAX]; /* absolute, by realpath() */
    int n_files;
    gb_checkpoint_file file[GB_CHECKPOINT_MAX_FILES];
} gb_checkpoint_meta;

/* FNV-1a 64 of the scene file's bytes and of what the simulation made of it and of the files it
 * reads (grains, contacts, initial state, the host's mesh and values): call it before the run. */
gb_status gb_checkpoint_scene_hash(const gb_sim *sim, uint64_t *hash, gb_error *err);

/* The length and last bytes of dir/name now, the file synced to the disk. */
gb_status gb_checkpoint_file_mark(const char *dir, const char *name, gb_checkpoint_file *f, gb_error *err);
/* dir/name back to its mark: cut to its length and its last bytes rewritten, or removed if it did
 * not exist. Fails if the file is shorter than its mark (it lost data the checkpoint counts on). */
gb_status gb_checkpoint_file_rewind(const char *dir, const gb_checkpoint_file *f, gb_error *err);

/* dir/checkpoint.txt, replaced atomically (written, synced, renamed), for the simulation's current
 * state and the run's progress p (its place, and the step in progress within one). */
gb_status gb_checkpoint_write(const char *dir, const gb_sim *sim, const gb_run_progress *p, const gb_checkpoint_meta *m,
                              gb_error *err);
/* Its header alone: the scene, its hash and the files. GB_EINPUT if there is none or it is not one. */
gb_status gb_checkpoint_read_meta(const char *dir, gb_checkpoint_meta *m, gb_error *err);
/* The whole checkpoint into a simulation just created from the same scene (scene_hash: its hash,
 * refused if the checkpoint's differs) and a new run's progress p; the run then continues after the
 * checkpoint's step, or within the step in progress.
 * Neither is changed if the checkpoint is refused (only running out of memory fails later). */
gb_status gb_checkpoint_read(const char *dir, gb_sim *sim, gb_run_progress *p, uint64_t scene_hash,
                             gb_checkpoint_meta *m, gb_error *err);

#endif
