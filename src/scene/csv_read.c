#define _POSIX_C_SOURCE 200809L
#include "scene/csv_read.h"

#include "core/number.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t') s++;
    char *e = s + strlen(s);
    while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r' || e[-1] == '\n')) *--e = '\0';
    return s;
}

/* Reads the next line that is not blank and not a comment; splits it at commas. */
static gb_status read_row(gb_csv *c, int *has_row, gb_error *err)
{
    for (;;) {
        ssize_t n = getline(&c->buf, &c->cap, c->f);
        if (n < 0) {
            *has_row = 0;
            return GB_OK;
        }
        c->line++;
        char *s = c->buf;
        while (*s == ' ' || *s == '\t') s++;
        if (*s == '#' || *s == '\n' || *s == '\r' || *s == '\0') continue;
        c->n_fields = 0;
        char *p = c->buf;
        for (;;) {
            if (c->n_fields == GB_CSV_MAX_FIELDS)
                return gb_fail(err, GB_EINPUT, "%s:%d: more than %d columns", c->path, c->line, GB_CSV_MAX_FIELDS);
            char *comma = strchr(p, ',');
            if (comma) *comma = '\0';
            c->column[c->n_fields] = (int)(p - c->buf) + 1;
            c->field[c->n_fields++] = trim(p);
            if (!comma) break;
            p = comma + 1;
        }
        *has_row = 1;
        return GB_OK;
    }
}

gb_status gb_csv_open(const char *path, gb_csv *c, gb_error *err)
{
    memset(c, 0, sizeof *c);
    snprintf(c->path, sizeof c->path, "%s", path);
    c->f = fopen(path, "r");
    if (!c->f) return gb_fail(err, GB_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    int has = 0;
    gb_status st = read_row(c, &has, err);
    if (!st && !has) st = gb_fail(err, GB_EINPUT, "%s: empty file; expected a header row naming the columns", path);
    for (int k = 0; !st && k < c->n_fields; k++) {
        size_t len = strlen(c->field[k]);
        if (len == 0 || len >= sizeof c->header[k])
            st = gb_csv_fail(c, k, err, "a column name of 1 to 31 characters");
        else
            memcpy(c->header[k], c->field[k], len + 1);
        for (int j = 0; !st && j < k; j++)
            if (!strcmp(c->header[j], c->header[k])) st = gb_csv_fail(c, k, err, "a column name not used twice");
    }
    if (st) {
        gb_csv_close(c);
        return st;
    }
    c->n_header = c->n_fields;
    return GB_OK;
}

void gb_csv_close(gb_csv *c)
{
    if (c->f) fclose(c->f);
    free(c->buf);
    c->f = NULL;
    c->buf = NULL;
}

int gb_csv_column(const gb_csv *c, const char *name)
{
    for (int k = 0; k < c->n_header; k++)
        if (!strcmp(c->header[k], name)) return k;
    return -1;
}

gb_status gb_csv_next(gb_csv *c, int *has_row, gb_error *err)
{
    gb_status st = read_row(c, has_row, err);
    if (st || !*has_row) return st;
    if (c->n_fields != c->n_header)
        return gb_fail(err, GB_EINPUT, "%s:%d: %d fields, expected %d (%s...)", c->path, c->line, c->n_fields,
                       c->n_header, c->header[0]);
    return GB_OK;
}

gb_status gb_csv_fail(const gb_csv *c, int k, gb_error *err, const char *what)
{
    return gb_fail(err, GB_EINPUT, "%s:%d:%d: %s: expected %s, found '%s'", c->path, c->line, c->column[k],
                   k < c->n_header ? c->header[k] : "header", what, c->field[k]);
}

gb_status gb_csv_number(const gb_csv *c, int k, double *out, gb_error *err)
{
    switch (gb_parse_finite(c->field[k], out)) {
    case GB_NUMBER_OK: return GB_OK;
    case GB_NUMBER_SYNTAX: return gb_csv_fail(c, k, err, "a number");
    default: return gb_csv_fail(c, k, err, "a finite number");
    }
}
