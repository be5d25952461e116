#define _POSIX_C_SOURCE 200809L
#include "io/file_util.h"
#include "io/dir_lock.h"

#include <dirent.h>
#include <sys/stat.h>

#include <errno.h>
#include <math.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void gb_test_kill_point(FILE *torn)
{
    static long at = -1, count = 0;
    if (at < 0) {
        const char *s = getenv("GB_TEST_KILL_AT");
        at = s ? strtol(s, NULL, 10) : 0;
    }
    if (at <= 0 || ++count != at) return;
    if (torn) {
        fputs("torn wri", torn);
        fflush(torn);
    }
    raise(SIGKILL);
}

int gb_test_checkpoint_due(void)
{
    static long every = -1, count = 0;
    if (every < 0) {
        const char *s = getenv("GB_TEST_CHECKPOINT_ITERATIONS");
        every = s ? strtol(s, NULL, 10) : 0;
    }
    return every > 0 && ++count % every == 0;
}

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
    gb_test_kill_point(a->f);
    int bad = ferror(a->f);
    bad |= fclose(a->f) != 0;
    a->f = NULL;
    if (bad || rename(a->tmp, a->path) != 0) {
        remove(a->tmp);
        return gb_fail(err, GB_EIO, "%s: write failed: %s", a->path, strerror(errno));
    }
    return GB_OK;
}

gb_status gb_atomic_write(const char *path, void (*write)(FILE *f, const void *data), const void *data, gb_error *err)
{
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    write(a.f, data);
    return gb_atomic_commit(&a, err);
}

void gb_atomic_abort(gb_atomic_file *a)
{
    if (a->f) fclose(a->f);
    a->f = NULL;
    remove(a->tmp);
}

gb_status gb_atomic_commit_durable(gb_atomic_file *a, gb_error *err)
{
    if (fflush(a->f) != 0 || fsync(fileno(a->f)) != 0) {
        int e = errno;
        gb_atomic_abort(a);
        return gb_fail(err, GB_EIO, "%s: write failed: %s", a->path, strerror(e));
    }
    gb_status st = gb_atomic_commit(a, err);
    if (st) return st;
    /* the rename itself: sync the directory */
    char dir[sizeof a->path];
    snprintf(dir, sizeof dir, "%s", a->path);
    char *slash = strrchr(dir, '/');
    if (slash) *slash = '\0';
    int fd = open(slash ? dir : ".", O_RDONLY);
    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
    return GB_OK;
}

/* Nothing in it but a lock file (a missing directory counts as empty). */
static int dir_is_empty(const char *path)
{
    DIR *d = opendir(path);
    if (!d) return errno == ENOENT;
    struct dirent *e;
    int empty = 1;
    while (empty && (e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && strcmp(e->d_name, GB_LOCK_NAME)) empty = 0;
    closedir(d);
    return empty;
}

/* A name too long for the file system is the user's choice (bad input); the others, the disk's. */
static gb_status mkdir_failed(const char *path, gb_error *err)
{
    int e = errno;
    return gb_fail(err, e == ENAMETOOLONG ? GB_EINPUT : GB_EIO, "%s: cannot make the directory: %s", path, strerror(e));
}

gb_status gb_dir_length_check(const char *dir, const char *what, gb_error *err)
{
    size_t n = strlen(dir);
    if (n <= GB_DIR_MAX) return GB_OK;
    return gb_fail(err, GB_EINPUT, "%s %.200s...: a path of %zu characters; gembem writes into directories of at "
                   "most %d (its files' names are added to it): choose a shorter path, or a relative one",
                   what, dir, n, GB_DIR_MAX);
}

/* mkdir -p */
gb_status gb_make_dirs(const char *path, gb_error *err)
{
    char buf[1024];
    if (strlen(path) >= sizeof buf)
        return gb_fail(err, GB_EINPUT, "%.200s...: a path of %zu characters, longer than gembem's %zu", path,
                       strlen(path), sizeof buf - 1);
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) return mkdir_failed(buf, err);
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) return mkdir_failed(buf, err);
    return GB_OK;
}

gb_status gb_copy_file(const char *from, const char *to, gb_error *err)
{
    FILE *in = fopen(from, "rb");
    if (!in) return gb_fail(err, GB_EIO, "%s: %s", from, strerror(errno));
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, to, err);
    if (st) {
        fclose(in);
        return st;
    }
    char buf[65536];
    size_t k;
    while ((k = fread(buf, 1, sizeof buf, in)) > 0) fwrite(buf, 1, k, a.f);
    fclose(in);
    return gb_atomic_commit(&a, err);
}

gb_status gb_output_dir_check(const char *dir, int overwrite, const char *what, gb_error *err)
{
    struct stat sb;
    char holder[384];
    gb_status st = gb_dir_length_check(dir, what, err);
    if (st) return st;
    if (stat(dir, &sb) != 0) return GB_OK;
    if (!S_ISDIR(sb.st_mode)) return gb_fail(err, GB_EINPUT, "%s exists and is not a directory", dir);
    if (gb_dir_lock_probe(dir, holder, sizeof holder, NULL, 0)) return gb_dir_lock_refuse(dir, what, holder, err);
    return gb_dir_empty_check(dir, overwrite, what, err);
}

gb_status gb_dir_empty_check(const char *dir, int overwrite, const char *what, gb_error *err)
{
    if (!overwrite && !dir_is_empty(dir))
        return gb_fail(err, GB_EINPUT, "%s %s exists and is not empty; choose another or pass --overwrite", what, dir);
    return GB_OK;
}

void gb_csv_put(FILE *f, const char *fmt, double v)
{
    if (isfinite(v)) {
        fprintf(f, fmt, v);
        return;
    }
    /* the format with "nan" for its conversion */
    const char *c = strchr(fmt, '%'), *e = c ? c + strcspn(c + 1, "aAeEfFgG") + 1 : NULL;
    if (!c || !*e) return;
    fprintf(f, "%.*snan%s", (int)(c - fmt), fmt, e + 1);
}

void gb_write_rows(FILE *f, int m, int threads, gb_row_fn row, const void *ctx)
{
    enum { BLOCK = 2048, MAX_THREADS = 64 };
    int T = threads < 1 ? 1 : threads > MAX_THREADS ? MAX_THREADS : threads, rows = BLOCK;
    size_t len[MAX_THREADS];
    char one[GB_ROW_MAX], *buf = malloc((size_t)T * BLOCK * GB_ROW_MAX);
    if (!buf) buf = one, T = 1, rows = 1; /* without the memory: row by row */
    for (int k0 = 0; k0 < m; k0 += T * rows) {
#pragma omp parallel for schedule(static) num_threads(T) if (T > 1 && m - k0 > rows)
        for (int t = 0; t < T; t++) {
            char *b = buf + (size_t)t * rows * GB_ROW_MAX;
            size_t at = 0;
            for (int k = k0 + t * rows, e = k + rows < m ? k + rows : m; k < e; k++) {
                /* snprintf's length: negative on an encoding error (nothing kept), at least
                 * GB_ROW_MAX when cut (the rows' formats are bounded well below it) */
                int n = row(b + at, GB_ROW_MAX, k, ctx);
                at += n < 0 ? 0 : n < GB_ROW_MAX ? (size_t)n : GB_ROW_MAX - 1;
            }
            len[t] = at;
        }
        for (int t = 0; t < T; t++) fwrite(buf + (size_t)t * rows * GB_ROW_MAX, 1, len[t], f);
    }
    if (buf != one) free(buf);
}
