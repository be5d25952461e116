#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"

#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Where the fixtures come from, relative to the source tree (GB_FUZZ_ROOT): this directory's own
 * and the meshes the project's scenes use, copied (not linked: the targets write into the
 * directory). Only names with these endings are copied. */
static const struct {
    const char *dir, *ending;
} sources[] = {{"fuzz/fixtures", ""}, {"meshes", ".geo"}, {"tests/bem/scenes", ".geo"}, {"tests/bem", ".msh"}};

static char dir[512];

static void die(const char *what, const char *path)
{
    fprintf(stderr, "fuzz: cannot %s %s\n", what, path);
    abort();
}

static void copy_file(const char *from, const char *to)
{
    FILE *in = fopen(from, "rb"), *out = fopen(to, "wb");
    if (!in || !out) die("copy", from);
    char buf[8192];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        if (fwrite(buf, 1, n, out) != n) die("write", to);
    fclose(in);
    if (fclose(out)) die("write", to);
}

static void remove_dir(void)
{
    DIR *d = opendir(dir);
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) unlink(gb_fuzz_path(e->d_name));
    closedir(d);
    rmdir(dir);
}

static void make_dir(void)
{
    const char *tmp = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/gembem_fuzz_XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    if (!mkdtemp(dir)) die("create", dir);
    atexit(remove_dir);
    for (size_t k = 0; k < sizeof sources / sizeof *sources; k++) {
        char from[1024];
        snprintf(from, sizeof from, "%s/%s", GB_FUZZ_ROOT, sources[k].dir);
        DIR *d = opendir(from);
        if (!d) die("read", from);
        struct dirent *e;
        size_t le = strlen(sources[k].ending);
        while ((e = readdir(d))) {
            size_t ln = strlen(e->d_name);
            if (e->d_name[0] == '.' || ln < le || strcmp(e->d_name + ln - le, sources[k].ending)) continue;
            char src[1536];
            snprintf(src, sizeof src, "%s/%s", from, e->d_name);
            copy_file(src, gb_fuzz_path(e->d_name));
        }
        closedir(d);
    }
}

const char *gb_fuzz_path(const char *name)
{
    static char path[1024];
    if (!dir[0]) make_dir();
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return path;
}

const char *gb_fuzz_write(const char *name, const uint8_t *data, size_t size)
{
    const char *path = gb_fuzz_path(name);
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0) die("create", path);
    for (size_t done = 0; done < size;) {
        ssize_t n = write(fd, data + done, size - done);
        if (n <= 0) die("write", path);
        done += (size_t)n;
    }
    close(fd);
    return path;
}

int gb_fuzz_contains(const uint8_t *data, size_t size, const char *word)
{
    size_t n = strlen(word);
    for (size_t i = 0; i + n <= size; i++)
        if (!memcmp(data + i, word, n)) return 1;
    return 0;
}

void gb_fuzz_show(gb_status st, const gb_error *err)
{
    static int show = -1;
    if (show < 0) show = getenv("GB_FUZZ_SHOW") != NULL;
    if (show) printf("%s\n", st ? err->msg : "accepted");
}
