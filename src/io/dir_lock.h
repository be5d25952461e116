/* One writer per output directory: DIR/.lock, locked by the process that writes DIR for as long as
 * it lives (an open-file-description lock, which the kernel drops when the process dies, however it
 * dies), holding who holds it (pid, host, start) and the writer's last status. The file keeps a fixed
 * size and is rewritten in place, so that a status can be recorded on a disk too full for any other
 * write (docs/run-directory.md, "One writer"). */
#ifndef GB_DIR_LOCK_H
#define GB_DIR_LOCK_H

#include <stddef.h>

#include "gembem/status.h"
#include "io/file_util.h"

#define GB_LOCK_NAME ".lock"
enum { GB_LOCK_SIZE = 512 };

typedef struct {
    int fd; /* -1: not held */
    char holder[GB_LOCK_SIZE]; /* the record as written (pid, host, started), without its status */
    char prev[GB_LOCK_SIZE];   /* the lock file as it was before this process took it */
    int prev_len;              /* its length; -1: this process created it */
    char path[GB_DIR_MAX + 16];
} gb_dir_lock;

/* Takes dir for this process. create: dir is made if absent and, unless overwrite, must be empty
 * (.lock aside) once locked; else dir must exist (a resume). Refused with GB_EINPUT if another
 * process holds it (naming it: pid, host, start) and if dir's path is too long (GB_DIR_MAX). what
 * names the directory in messages ("run directory"). */
gb_status gb_dir_lock_take(gb_dir_lock *l, const char *dir, int create, int overwrite, const char *what,
                           gb_error *err);
/* Records the writer's status ("running", "completed", "interrupted", "i/o error", ...) in the lock
 * file, in place; 0 if written. */
int gb_dir_lock_status(gb_dir_lock *l, const char *status);
/* Lets go of dir, its lock file put back as it was (a refused resume leaves the directory as it
 * found it). */
void gb_dir_lock_undo(gb_dir_lock *l);
/* Lets go of dir (the lock file stays, with the last status). */
void gb_dir_lock_release(gb_dir_lock *l);

/* Whether a live process holds dir's lock (1) or not (0: no lock file, or a free one); holder
 * (may be NULL): who holds or last held it, on one line; status (may be NULL): the status it
 * recorded ("" without a lock file). */
int gb_dir_lock_probe(const char *dir, char *holder, size_t holder_cap, char *status, size_t status_cap);

/* A refusal because dir is held by another process, naming it: GB_EINPUT. */
gb_status gb_dir_lock_refuse(const char *dir, const char *what, const char *holder, gb_error *err);

#endif
