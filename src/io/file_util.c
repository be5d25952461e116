#include "io/file_util.h"

#include <errno.h>
#include <string.h>

gb_status gb_atomic_open(gb_atomic_file *a, const char *path, gb_error *err)
{
    snprintf(a->path, sizeof a->path, "%s", path);
    snprintf(a->tmp, sizeof a->tmp, "%s.tmp", path);
    a->f = fopen(a->tmp, "w");
    if (!a->f) return gb_fail(err, GB_EIO, "%s: cannot write: %s", a->tmp, strerror(errno));
    return GB_OK;
}

gb_status gb_atomic_commit(gb_atomic_file *a, gb_error *err)
{
    int bad = ferror(a->f);
    bad |= fclose(a->f) != 0;
    a->f = NULL;
    if (bad || rename(a->tmp, a->path) != 0) {
        remove(a->tmp);
        return gb_fail(err, GB_EIO, "%s: write failed: %s", a->path, strerror(errno));
    }
    return GB_OK;
}

void gb_atomic_abort(gb_atomic_file *a)
{
    if (a->f) fclose(a->f);
    a->f = NULL;
    remove(a->tmp);
}
