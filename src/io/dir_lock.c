/* DIR/.lock: one writer per output directory (io/dir_lock.h). An open-file-description lock
 * (F_OFD_SETLK) rather than a classic fcntl lock: closing any other descriptor of the file in the
 * same process does not drop it, and a classic lock (Python's fcntl.lockf) still sees it. */
#define _GNU_SOURCE
#include "io/dir_lock.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "io/file_util.h"

#ifndef F_OFD_SETLK /* a kernel or libc before Linux 3.15: classic locks, which the writer never closes */
#define F_OFD_SETLK F_SETLK
#define F_OFD_GETLK F_GETLK
#endif

/* The value of "key: " in the lock file's text, to the end of its line, trailing blanks dropped. */
static void field(const char *text, const char *key, char *out, size_t cap)
{
    out[0] = '\0';
    size_t n = strlen(key);
    for (const char *l = text; l && *l; l = strchr(l, '\n') ? strchr(l, '\n') + 1 : NULL) {
        if (strncmp(l, key, n) || l[n] != ':' || l[n + 1] != ' ') continue;
        const char *v = l + n + 2;
        size_t len = strcspn(v, "\n");
        while (len && v[len - 1] == ' ') len--;
        if (len >= cap) len = cap - 1;
        memcpy(out, v, len), out[len] = '\0';
        return;
    }
}

/* Who holds (or last held) the lock whose text is given, on one line. */
static void describe(const char *text, char *out, size_t cap)
{
    char pid[32], host[256], started[64];
    field(text, "pid", pid, sizeof pid);
    field(text, "host", host, sizeof host);
    field(text, "started", started, sizeof started);
    snprintf(out, cap, "pid %s on %s, started %s", pid[0] ? pid : "?", host[0] ? host : "?",
             started[0] ? started : "?");
}

static void read_text(int fd, char *text, size_t cap)
{
    ssize_t k = pread(fd, text, cap - 1, 0);
    text[k > 0 ? k : 0] = '\0';
}

int gb_dir_lock_probe(const char *dir, char *holder, size_t holder_cap, char *status, size_t status_cap)
{
    char path[GB_DIR_MAX + 16], text[GB_LOCK_SIZE + 1];
    snprintf(path, sizeof path, "%s/%s", dir, GB_LOCK_NAME);
    if (holder && holder_cap) holder[0] = '\0';
    if (status && status_cap) status[0] = '\0';
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return 0;
    struct flock fl = {.l_type = F_WRLCK, .l_whence = SEEK_SET};
    int held = fcntl(fd, F_OFD_GETLK, &fl) == 0 && fl.l_type != F_UNLCK;
    read_text(fd, text, sizeof text);
    close(fd);
    if (holder) describe(text, holder, holder_cap);
    if (status) field(text, "status", status, status_cap);
    return held;
}

gb_status gb_dir_lock_refuse(const char *dir, const char *what, const char *holder, gb_error *err)
{
    return gb_fail(err, GB_EINPUT, "%s %s is in use: a gembem process writes it (%s; its %s/%s). One process "
                   "writes a directory at a time: wait for it to end, stop it (it then records where it stopped), "
                   "or choose another directory", what, dir, holder, dir, GB_LOCK_NAME);
}

/* The lock file's text: the holder's record and status, padded to its fixed size. */
static int write_record(gb_dir_lock *l, const char *status)
{
    char text[GB_LOCK_SIZE];
    int n = snprintf(text, sizeof text, "%sstatus: %.80s\n", l->holder, status);
    if (n < 0 || n >= GB_LOCK_SIZE) n = GB_LOCK_SIZE - 1;
    memset(text + n, ' ', GB_LOCK_SIZE - 1 - (size_t)n);
    text[GB_LOCK_SIZE - 1] = '\n';
    return pwrite(l->fd, text, GB_LOCK_SIZE, 0) == GB_LOCK_SIZE ? 0 : -1;
}

gb_status gb_dir_lock_take(gb_dir_lock *l, const char *dir, int create, int overwrite, const char *what,
                           gb_error *err)
{
    l->fd = -1;
    l->holder[0] = '\0';
    char path[GB_DIR_MAX + 16], holder[384];
    struct stat sb;
    if (!create && stat(dir, &sb) != 0) return gb_fail(err, GB_EINPUT, "%s: no such %s", dir, what);
    /* checked before anything is made: a refused directory is left as it was */
    gb_status st = gb_output_dir_check(dir, !create || overwrite, what, err);
    if (st || (st = gb_make_dirs(dir, err))) return st;
    snprintf(path, sizeof path, "%s/%s", dir, GB_LOCK_NAME);
    int fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0) return gb_fail(err, GB_EIO, "%s: cannot create: %s", path, strerror(errno));
    struct flock fl = {.l_type = F_WRLCK, .l_whence = SEEK_SET};
    if (fcntl(fd, F_OFD_SETLK, &fl) != 0) {
        int e = errno;
        char text[GB_LOCK_SIZE + 1];
        read_text(fd, text, sizeof text);
        close(fd);
        if (e != EAGAIN && e != EACCES)
            return gb_fail(err, GB_EIO, "%s: cannot lock: %s (a file system without locks?)", path, strerror(e));
        describe(text, holder, sizeof holder);
        return gb_dir_lock_refuse(dir, what, holder, err);
    }
    l->fd = fd;
    snprintf(l->path, sizeof l->path, "%s", path);
    ssize_t k = pread(fd, l->prev, sizeof l->prev, 0);
    l->prev_len = k > 0 ? (int)k : -1; /* an empty one, as one just made, goes again */
    /* a writer that took the directory between the checks above and the lock has finished by now */
    if (create && (st = gb_dir_empty_check(dir, overwrite, what, err))) {
        gb_dir_lock_release(l);
        return st;
    }
    char host[256] = "?", started[64];
    gethostname(host, sizeof host);
    host[sizeof host - 1] = '\0';
    time_t now = time(NULL);
    strftime(started, sizeof started, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
    snprintf(l->holder, sizeof l->holder,
             "# gembem: the process that writes this directory, locked (fcntl) while it lives\n"
             "pid: %ld\nhost: %.200s\nstarted: %s\n", (long)getpid(), host, started);
    if (write_record(l, "running") != 0 || ftruncate(fd, GB_LOCK_SIZE) != 0) {
        int e = errno;
        gb_dir_lock_release(l);
        return gb_fail(err, GB_EIO, "%s: cannot write: %s", path, strerror(e));
    }
    return GB_OK;
}

int gb_dir_lock_status(gb_dir_lock *l, const char *status)
{
    if (l->fd < 0) return -1;
    return write_record(l, status);
}

void gb_dir_lock_undo(gb_dir_lock *l)
{
    if (l->fd < 0) return;
    if (l->prev_len < 0) unlink(l->path);
    /* should this fail, the file names this process: a holder gone, which readers take as such */
    int ok = l->prev_len < 0 || (pwrite(l->fd, l->prev, (size_t)l->prev_len, 0) == l->prev_len &&
                                 ftruncate(l->fd, l->prev_len) == 0);
    (void)ok;
    gb_dir_lock_release(l);
}

void gb_dir_lock_release(gb_dir_lock *l)
{
    if (l->fd >= 0) close(l->fd);
    l->fd = -1;
}
