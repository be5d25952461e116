#define _POSIX_C_SOURCE 200809L /* fmemopen */
#include "scene/yaml_read.h"

#include "core/number.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Length of the UTF-8 sequence at s (n bytes left) and its code point *cp, 0 if it is not one. */
static int utf8_decode(const unsigned char *s, size_t n, unsigned long *cp)
{
    int len = s[0] < 0x80 ? 1 : s[0] >= 0xc2 && s[0] < 0xe0 ? 2 : s[0] >= 0xe0 && s[0] < 0xf0 ? 3
            : s[0] >= 0xf0 && s[0] < 0xf5 ? 4 : 0;
    if ((size_t)len > n) return 0;
    *cp = len == 1 ? s[0] : s[0] & (0x7f >> len);
    for (int k = 1; k < len; k++) {
        if ((s[k] & 0xc0) != 0x80) return 0;
        *cp = *cp << 6 | (s[k] & 0x3f);
    }
    /* no overlong forms, surrogates or code points above U+10FFFF (RFC 3629) */
    if ((s[0] == 0xe0 && s[1] < 0xa0) || (s[0] == 0xed && s[1] > 0x9f) || (s[0] == 0xf0 && s[1] < 0x90) ||
        (s[0] == 0xf4 && s[1] > 0x8f))
        return 0;
    return len;
}

/* YAML 1.2's character set (c-printable, section 5.1): tab, line feed, carriage return, the
 * printable ASCII, NEL and the rest of Unicode but for the surrogates, U+FFFE and U+FFFF. */
static int yaml_printable(unsigned long c)
{
    return c == 0x9 || c == 0xa || c == 0xd || (c >= 0x20 && c <= 0x7e) || c == 0x85 || (c >= 0xa0 && c <= 0xfffd) ||
           (c >= 0x10000 && c <= 0x10ffff);
}

/* YAML is UTF-8 text of YAML's characters here, checked before libfyaml sees it: libfyaml 0.7
 * loops forever on a directive line ('%') holding a byte that is not UTF-8, and writes through a
 * null pointer on some texts holding a NUL (both found by fuzzing, fuzz/regress/scene and state). */
static gb_status check_text(const char *path, FILE *f, gb_error *err)
{
    unsigned char buf[4096];
    size_t have = 0, n;
    int line = 1, col = 1;
    while ((n = fread(buf + have, 1, sizeof buf - have, f)) > 0 || have > 0) {
        size_t end = have + n, i = 0;
        int last = n == 0; /* no more bytes: what is left must be complete */
        while (i < end) {
            if (!last && end - i < 4) break; /* a sequence may continue in the next read */
            unsigned long c = 0;
            int len = utf8_decode(buf + i, end - i, &c);
            if (!len)
                return gb_fail(err, GB_EINPUT, "%s:%d:%d: byte 0x%02x is not UTF-8 text; expected a YAML file in UTF-8",
                               path, line, col, buf[i]);
            if (!yaml_printable(c))
                return gb_fail(err, GB_EINPUT,
                               "%s:%d:%d: character U+%04lX is not allowed in a YAML file (YAML 1.2, section 5.1: "
                               "no control characters but tab, line feed and carriage return, no U+FFFE or U+FFFF)",
                               path, line, col, c);
            if (buf[i] == '\n') line++, col = 1;
            else col++;
            i += (size_t)len;
        }
        memmove(buf, buf + i, end - i);
        have = end - i;
        if (last) break;
    }
    return GB_OK;
}

/* Parses the checked YAML of `text` (NULL: the file doc->path) into doc. */
static gb_status parse(gb_yaml_doc *doc, FILE *text, gb_error *err)
{
    const char *path = doc->path;
    /* A fresh diag per parse, collecting errors so that we can report line and column. */
    struct fy_diag_cfg dcfg;
    fy_diag_cfg_default(&dcfg);
    dcfg.fp = NULL;
    dcfg.colorize = false;
    struct fy_diag *diag = fy_diag_create(&dcfg);
    if (!diag) return gb_fail(err, GB_ENOMEM, "%s: cannot create the YAML diagnostics", path);
    fy_diag_set_collect_errors(diag, true);

    struct fy_parse_cfg cfg = {0};
    cfg.flags = FYPCF_QUIET | FYPCF_COLLECT_DIAG;
    cfg.diag = diag;
    doc->fyd = text ? fy_document_build_from_fp(&cfg, text) : fy_document_build_from_file(&cfg, path);
    gb_status st = GB_OK;
    if (!doc->fyd) {
        void *it = NULL;
        struct fy_diag_error *e = fy_diag_errors_iterate(diag, &it);
        /* the diag's line and column are 1-based already (its token's marks are 0-based): the
         * offending token's first character, a duplicate key's second occurrence */
        if (e)
            st = gb_fail(err, GB_EINPUT, "%s:%d:%d: YAML syntax error: %s", path, e->line, e->column, e->msg);
        else
            st = gb_fail(err, GB_EINPUT, "%s: not a valid YAML document", path);
    } else if (!fy_document_root(doc->fyd)) {
        st = gb_fail(err, GB_EINPUT, "%s: the %s is empty; expected a YAML mapping", path, text ? "text" : "file");
        fy_document_destroy(doc->fyd);
        doc->fyd = NULL;
    }
    fy_diag_destroy(diag);
    return st;
}

gb_status gb_yaml_load(const char *path, gb_yaml_doc *doc, gb_error *err)
{
    memset(doc, 0, sizeof *doc);
    snprintf(doc->path, sizeof doc->path, "%s", path);
    FILE *probe = fopen(path, "rb");
    if (!probe) return gb_fail(err, GB_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    gb_status text = check_text(path, probe, err);
    fclose(probe);
    return text ? text : parse(doc, NULL, err);
}

gb_status gb_yaml_load_text(const char *text, size_t len, const char *name, gb_yaml_doc *doc, gb_error *err)
{
    memset(doc, 0, sizeof *doc);
    snprintf(doc->path, sizeof doc->path, "%s", name);
    if (!len) return gb_fail(err, GB_EINPUT, "%s: the text is empty; expected a YAML mapping", name);
    FILE *f = fmemopen((void *)text, len, "rb");
    if (!f) return gb_fail(err, GB_ENOMEM, "%s: cannot read the text: %s", name, strerror(errno));
    gb_status st = check_text(name, f, err);
    if (!st) rewind(f), st = parse(doc, f, err);
    fclose(f);
    return st;
}

void gb_yaml_free(gb_yaml_doc *doc)
{
    if (doc && doc->fyd) fy_document_destroy(doc->fyd);
    if (doc) doc->fyd = NULL;
}

/* libfyaml 0.7 gives marks on tokens only: a scalar has one, a collection is located by its first
 * scalar (a key for a mapping, an item for a sequence). */
void gb_yaml_where(struct fy_node *node, int *line, int *col)
{
    *line = 0;
    *col = 0;
    for (int depth = 0; node && depth < 64; depth++) {
        if (fy_node_get_type(node) == FYNT_SCALAR) {
            struct fy_token *t = fy_node_get_scalar_token(node);
            const struct fy_mark *mk = t ? fy_token_start_mark(t) : NULL;
            if (mk) {
                *line = mk->line + 1;
                *col = mk->column + 1;
                /* a quoted scalar's mark is its text's, one past the opening quote on the same line */
                enum fy_node_style style = fy_node_get_style(node);
                if ((style == FYNS_SINGLE_QUOTED || style == FYNS_DOUBLE_QUOTED) && *col > 1) (*col)--;
            }
            return;
        }
        if (fy_node_get_type(node) == FYNT_MAPPING) {
            void *it = NULL;
            struct fy_node_pair *p = fy_node_mapping_iterate(node, &it);
            node = p ? fy_node_pair_key(p) : NULL;
        } else {
            node = fy_node_sequence_get_by_index(node, 0);
        }
    }
}

gb_status gb_yaml_fail(const gb_yaml_doc *doc, struct fy_node *at, gb_error *err, const char *fmt, ...)
{
    char what[GB_ERROR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    int line = 0, col = 0;
    if (at) gb_yaml_where(at, &line, &col);
    if (line > 0) return gb_fail(err, GB_EINPUT, "%s:%d:%d: %s", doc->path, line, col, what);
    return gb_fail(err, GB_EINPUT, "%s: %s", doc->path, what);
}

gb_status gb_yaml_number(const gb_yaml_doc *doc, struct fy_node *node, const char *what, double *out,
                         gb_error *err)
{
    if (!node || fy_node_get_type(node) != FYNT_SCALAR)
        return gb_yaml_fail(doc, node, err, "%s: expected a number, found a %s", what,
                            node && fy_node_get_type(node) == FYNT_MAPPING ? "mapping" : "sequence");
    size_t len = 0;
    const char *s = fy_node_get_scalar(node, &len);
    if (fy_node_get_style(node) != FYNS_PLAIN)
        return gb_yaml_fail(doc, node, err, "%s: expected a number, found a quoted string ('%.*s'): write it without "
                            "quotes", what, (int)(len < 40 ? len : 40), s ? s : "");
    char buf[64];
    if (!s || len == 0 || len >= sizeof buf)
        return gb_yaml_fail(doc, node, err, "%s: expected a number, found '%.*s'", what, (int)(len < 40 ? len : 40),
                            s ? s : "");
    memcpy(buf, s, len);
    buf[len] = '\0';
    switch (gb_parse_finite(buf, out)) {
    case GB_NUMBER_OK: return GB_OK;
    case GB_NUMBER_SYNTAX: return gb_yaml_fail(doc, node, err, "%s: expected a number, found '%s'", what, buf);
    default: return gb_yaml_fail(doc, node, err, "%s: expected a finite number, found '%s'", what, buf);
    }
}

gb_status gb_ymap_open(const gb_yaml_doc *doc, struct fy_node *node, const char *name, gb_ymap *m,
                       gb_error *err)
{
    memset(m, 0, sizeof *m);
    m->doc = doc;
    m->node = node;
    size_t len = strlen(name);
    if (len >= sizeof m->name) len = sizeof m->name - 1; /* a very deep path is cut, not overrun */
    memcpy(m->name, name, len);
    m->name[len] = '\0';
    if (node && fy_node_get_type(node) != FYNT_MAPPING)
        return gb_yaml_fail(doc, node, err, "%s: expected a mapping of keys to values", name);
    return GB_OK;
}

/* Optimal string alignment distance between a (length la) and b, letters compared without case:
 * a typo is one or two edits (a letter missed, doubled, swapped with its neighbour, mistyped). */
static int edit_distance(const char *a, size_t la, const char *b)
{
    enum { MAX = 64 };
    size_t lb = strlen(b);
    if (la >= MAX || lb >= MAX) return MAX;
    int d[MAX][MAX];
    for (size_t i = 0; i <= la; i++) d[i][0] = (int)i;
    for (size_t j = 0; j <= lb; j++) d[0][j] = (int)j;
    for (size_t i = 1; i <= la; i++)
        for (size_t j = 1; j <= lb; j++) {
            int same = tolower((unsigned char)a[i - 1]) == tolower((unsigned char)b[j - 1]);
            int v = d[i - 1][j - 1] + !same;
            if (d[i - 1][j] + 1 < v) v = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < v) v = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && tolower((unsigned char)a[i - 1]) == tolower((unsigned char)b[j - 2]) &&
                tolower((unsigned char)a[i - 2]) == tolower((unsigned char)b[j - 1]) && d[i - 2][j - 2] + 1 < v)
                v = d[i - 2][j - 2] + 1;
            d[i][j] = v;
        }
    return d[la][lb];
}

/* Whether `written` (length len) is a likely misspelling of the key `meant`: at most one edit in
 * a key of 4 to 7 letters, two from 8; short keys only by case (kn and kt, de1 and de2 are
 * different keys one letter apart). */
static int misspelt(const char *written, size_t len, const char *meant)
{
    int d = edit_distance(written, len, meant);
    return 4 * d <= (int)strlen(meant) && d <= 2;
}

int gb_yaml_closest(const char *written, size_t len, const char *const *names, int n)
{
    for (int i = 0; written && i < n; i++)
        if (misspelt(written, len, names[i])) return i;
    return -1;
}

enum { PATH_LEN = 256 }; /* a key's path in messages */

static void key_path(const gb_ymap *m, const char *key, char *out, size_t n)
{
    if (m->name[0]) snprintf(out, n, "%s.%s", m->name, key);
    else snprintf(out, n, "%s", key);
}

gb_status gb_ymap_find(gb_ymap *m, const char *key, int flags, struct fy_node **out, gb_error *err)
{
    int seen = 0; /* a key looked up twice is listed once among the expected ones */
    for (int i = 0; i < m->n_asked && !seen; i++) seen = !strcmp(m->asked[i], key);
    if (!seen && m->n_asked < GB_YMAP_MAX_KEYS) m->asked[m->n_asked++] = key;
    *out = m->node ? fy_node_mapping_lookup_by_string(m->node, key, FY_NT) : NULL;
    if (*out && fy_node_get_type(*out) == FYNT_SCALAR && fy_node_is_null(*out) &&
        fy_node_get_style(*out) == FYNS_PLAIN) {
        size_t len = 0;
        fy_node_get_scalar(*out, &len);
        if (len == 0) *out = NULL; /* "key:" with no value counts as absent */
    }
    if (!*out && (flags & GB_Y_REQUIRED)) {
        char path[PATH_LEN];
        key_path(m, key, path, sizeof path);
        /* a key of the mapping written for this one: named at its own line */
        void *it = NULL;
        struct fy_node_pair *p;
        while (m->node && (p = fy_node_mapping_iterate(m->node, &it))) {
            size_t len = 0;
            const char *s = fy_node_get_scalar(fy_node_pair_key(p), &len);
            if (s && misspelt(s, len, key))
                return gb_yaml_fail(m->doc, fy_node_pair_key(p), err, "missing key '%s' (found '%.*s': did you mean "
                                    "'%s'?)", path, (int)len, s, key);
        }
        return gb_yaml_fail(m->doc, m->node, err, "missing key '%s'", path);
    }
    return GB_OK;
}

/* A key's value as found: its node (NULL when it is absent and may be), its path for messages
 * ("host.mesh") and, for a scalar, its text. */
typedef struct {
    struct fy_node *node;
    char path[PATH_LEN];
    const char *text; /* NULL unless a scalar */
    size_t len;
} found_value;

static gb_status find_value(gb_ymap *m, const char *key, int flags, found_value *v, gb_error *err)
{
    key_path(m, key, v->path, sizeof v->path);
    v->text = NULL;
    v->len = 0;
    gb_status st = gb_ymap_find(m, key, flags, &v->node, err);
    if (!st && v->node && fy_node_get_type(v->node) == FYNT_SCALAR) v->text = fy_node_get_scalar(v->node, &v->len);
    return st;
}

/* The same, and the value read as a number when it is there. */
static gb_status find_number(gb_ymap *m, const char *key, int flags, found_value *v, double *x, gb_error *err)
{
    gb_status st = find_value(m, key, flags, v, err);
    return st || !v->node ? st : gb_yaml_number(m->doc, v->node, v->path, x, err);
}

/* A sequence of 1 to max numbers (exactly max when `exactly`) into out, their count in *n. */
static gb_status find_numbers(gb_ymap *m, const char *key, int flags, int max, int exactly, double *out, int *n,
                              gb_error *err)
{
    found_value v;
    gb_status st = find_value(m, key, flags, &v, err);
    if (st || !v.node) return st;
    int count = fy_node_get_type(v.node) == FYNT_SEQUENCE ? fy_node_sequence_item_count(v.node) : -1;
    if (exactly && count != max)
        return gb_yaml_fail(m->doc, v.node, err, "%s: expected a list of %d numbers", v.path, max);
    if (count < 1 || count > max)
        return gb_yaml_fail(m->doc, v.node, err, "%s: expected a list of 1 to %d numbers", v.path, max);
    for (int i = 0; i < count && !st; i++)
        st = gb_yaml_number(m->doc, fy_node_sequence_get_by_index(v.node, i), v.path, &out[i], err);
    if (!st) *n = count;
    return st;
}

gb_status gb_ymap_number(gb_ymap *m, const char *key, int flags, double *out, gb_error *err)
{
    found_value v;
    double x;
    gb_status st = find_number(m, key, flags, &v, &x, err);
    if (st || !v.node) return st;
    if ((flags & GB_Y_POSITIVE) && !(x > 0))
        return gb_yaml_fail(m->doc, v.node, err, "%s: expected a positive number, found %g", v.path, x);
    if ((flags & GB_Y_NONNEG) && !(x >= 0))
        return gb_yaml_fail(m->doc, v.node, err, "%s: expected a number >= 0, found %g", v.path, x);
    *out = x;
    return GB_OK;
}

gb_status gb_ymap_int(gb_ymap *m, const char *key, int flags, long lo, long hi, long *out, gb_error *err)
{
    found_value v;
    double x;
    gb_status st = find_number(m, key, flags, &v, &x, err);
    if (st || !v.node) return st;
    if (x != floor(x) || x < (double)lo || x > (double)hi)
        return gb_yaml_fail(m->doc, v.node, err, "%s: expected a whole number from %ld to %ld, found %g", v.path, lo,
                            hi, x);
    *out = (long)x;
    return GB_OK;
}

gb_status gb_ymap_bool(gb_ymap *m, const char *key, int flags, int *out, gb_error *err)
{
    found_value v;
    gb_status st = find_value(m, key, flags, &v, err);
    if (st || !v.node) return st;
    if (v.text && fy_node_get_style(v.node) == FYNS_PLAIN) {
        if (v.len == 4 && !strncmp(v.text, "true", 4)) return *out = 1, GB_OK;
        if (v.len == 5 && !strncmp(v.text, "false", 5)) return *out = 0, GB_OK;
    }
    return gb_yaml_fail(m->doc, v.node, err, "%s: expected true or false", v.path);
}

gb_status gb_ymap_string(gb_ymap *m, const char *key, int flags, char *buf, size_t n, gb_error *err)
{
    found_value v;
    gb_status st = find_value(m, key, flags, &v, err);
    if (st || !v.node) return st;
    if (!v.text) return gb_yaml_fail(m->doc, v.node, err, "%s: expected a string", v.path);
    if (v.len == 0 || v.len >= n)
        return gb_yaml_fail(m->doc, v.node, err, "%s: expected a non-empty string of at most %zu characters", v.path,
                            n - 1);
    memcpy(buf, v.text, v.len);
    buf[v.len] = '\0';
    return GB_OK;
}

gb_status gb_ymap_map(gb_ymap *m, const char *key, int flags, gb_ymap *sub, gb_error *err)
{
    found_value v;
    gb_status st = find_value(m, key, flags, &v, err);
    return st ? st : gb_ymap_open(m->doc, v.node, v.path, sub, err);
}

gb_status gb_ymap_vector(gb_ymap *m, const char *key, int flags, int n, double *out, gb_error *err)
{
    int got = 0;
    return find_numbers(m, key, flags, n, 1, out, &got, err);
}

gb_status gb_ymap_numbers(gb_ymap *m, const char *key, int flags, int max, double *out, int *n, gb_error *err)
{
    return find_numbers(m, key, flags, max, 0, out, n, err);
}

gb_status gb_ymap_units(gb_ymap *top, char *length, char *force, size_t n, gb_error *err)
{
    gb_ymap units;
    gb_status st;
    if ((st = gb_ymap_map(top, "units", GB_Y_REQUIRED, &units, err)) ||
        (st = gb_ymap_string(&units, "length", GB_Y_REQUIRED, length, n, err)) ||
        (st = gb_ymap_string(&units, "force", GB_Y_REQUIRED, force, n, err)))
        return st;
    return gb_ymap_close(&units, err);
}

gb_status gb_ymap_close(gb_ymap *m, gb_error *err)
{
    if (!m->node) return GB_OK;
    void *it = NULL;
    struct fy_node_pair *p;
    while ((p = fy_node_mapping_iterate(m->node, &it))) {
        struct fy_node *k = fy_node_pair_key(p);
        size_t len = 0;
        const char *s = fy_node_get_type(k) == FYNT_SCALAR ? fy_node_get_scalar(k, &len) : NULL;
        int known = 0;
        for (int i = 0; s && i < m->n_asked && !known; i++)
            known = strlen(m->asked[i]) == len && !strncmp(m->asked[i], s, len);
        if (known) continue;
        char expected[600] = "", hint[96] = "";
        size_t used = 0;
        for (int i = 0; i < m->n_asked && used < sizeof expected - 1; i++) {
            used += (size_t)snprintf(expected + used, sizeof expected - used, "%s%s", i ? ", " : "", m->asked[i]);
            if (s && !hint[0] && misspelt(s, len, m->asked[i]) &&
                !fy_node_mapping_lookup_by_string(m->node, m->asked[i], FY_NT)) /* not a key given as well */
                snprintf(hint, sizeof hint, " did you mean '%s'?", m->asked[i]);
        }
        return gb_yaml_fail(m->doc, k, err, "%s: unknown key '%.*s';%s expected one of: %s",
                            m->name[0] ? m->name : "(top level)", (int)(s ? len : 0), s ? s : "", hint, expected);
    }
    return GB_OK;
}

void gb_yaml_relative_path(const gb_yaml_doc *doc, const char *name, char *out, size_t n)
{
    const char *slash = strrchr(doc->path, '/');
    if (name[0] == '/' || !slash) {
        snprintf(out, n, "%s", name);
        return;
    }
    snprintf(out, n, "%.*s/%s", (int)(slash - doc->path), doc->path, name);
}
