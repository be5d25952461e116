/* The files a run appends to, at a checkpoint: their marks (length and last bytes) and, on a
 * resume, each cut back to its mark (io/checkpoint.h). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/checkpoint.h"

gb_status gb_checkpoint_file_mark(const char *dir, const char *name, gb_checkpoint_file *f, gb_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    snprintf(f->name, sizeof f->name, "%s", name);
    f->length = -1, f->n_tail = 0;
    FILE *in = fopen(path, "rb");
    if (!in) return errno == ENOENT ? GB_OK : gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno));
    /* on the disk before the checkpoint that counts on it (a power cut) */
    int ok = fsync(fileno(in)) == 0 && fseek(in, 0, SEEK_END) == 0;
    long end = ok ? ftell(in) : -1;
    f->n_tail = end < 0 ? 0 : end < GB_CHECKPOINT_TAIL ? (int)end : GB_CHECKPOINT_TAIL;
    ok = end >= 0 && fseek(in, end - f->n_tail, SEEK_SET) == 0 &&
         fread(f->tail, 1, (size_t)f->n_tail, in) == (size_t)f->n_tail;
    fclose(in);
    if (!ok) return gb_fail(err, GB_EIO, "%s: cannot read its end", path);
    f->length = end;
    return GB_OK;
}

gb_status gb_checkpoint_file_rewind(const char *dir, const gb_checkpoint_file *f, gb_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", dir, f->name);
    if (f->length < 0) return remove(path) == 0 || errno == ENOENT ? GB_OK : gb_fail(err, GB_EIO, "%s: %s", path,
                                                                                       strerror(errno));
    struct stat sb;
    if (stat(path, &sb) != 0 || (long long)sb.st_size < f->length)
        return gb_fail(err, GB_EINPUT, "%s: %s than the checkpoint records (%lld bytes); the run directory was "
                       "changed", path, stat(path, &sb) != 0 ? "missing, not longer" : "shorter", f->length);
    int fd = open(path, O_WRONLY);
    int ok = fd >= 0 && ftruncate(fd, (off_t)f->length) == 0 &&
             pwrite(fd, f->tail, (size_t)f->n_tail, (off_t)(f->length - f->n_tail)) == f->n_tail;
    if (fd >= 0 && close(fd) != 0) ok = 0;
    return ok ? GB_OK : gb_fail(err, GB_EIO, "%s: cannot cut back to %lld bytes: %s", path, f->length,
                                strerror(errno));
}
