/* Reading YAML scenes with libfyaml: every value is checked for presence, type and range, every
 * unknown key is refused, and every error names file:line:column and what was expected.
 * Shared by all scene readers (granular scenes, elastic hosts). */
#ifndef GB_YAML_READ_H
#define GB_YAML_READ_H

#include <libfyaml.h>
#include <stddef.h>

#include "gembem/status.h"

typedef struct {
    struct fy_document *fyd;
    char path[512];
} gb_yaml_doc;

/* Parses the whole file; a syntax error is reported with its line and column. */
gb_status gb_yaml_load(const char *path, gb_yaml_doc *doc, gb_error *err);
/* The same from len bytes of YAML in memory; `name` stands for the file in messages and relative
 * file names (gb_yaml_relative_path) are read from its directory. */
gb_status gb_yaml_load_text(const char *text, size_t len, const char *name, gb_yaml_doc *doc, gb_error *err);
void gb_yaml_free(gb_yaml_doc *doc);

/* 1-based line and column of a node (of its first scalar for a collection); 0 if unknown. */
void gb_yaml_where(struct fy_node *node, int *line, int *col);

/* Records "file:line:col: message" for the node (or the file alone when node is NULL). */
gb_status gb_yaml_fail(const gb_yaml_doc *doc, struct fy_node *at, gb_error *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* A scalar node as a finite number; `what` names it in the message. */
gb_status gb_yaml_number(const gb_yaml_doc *doc, struct fy_node *node, const char *what, double *out,
                         gb_error *err);

enum {
    GB_Y_OPTIONAL = 0,
    GB_Y_REQUIRED = 1 << 0,
    GB_Y_POSITIVE = 1 << 1, /* > 0 */
    GB_Y_NONNEG = 1 << 2    /* >= 0 */
};

#define GB_YMAP_MAX_KEYS 48

/* A mapping being read: keys that are looked up are marked, and gb_ymap_close refuses the rest. */
typedef struct {
    const gb_yaml_doc *doc;
    struct fy_node *node;
    char name[160]; /* dotted path for messages, e.g. "materials.grain_grain" */
    const char *asked[GB_YMAP_MAX_KEYS];
    int n_asked;
} gb_ymap;

/* `node` must be a mapping (NULL: an empty one, for an optional section that is absent). */
gb_status gb_ymap_open(const gb_yaml_doc *doc, struct fy_node *node, const char *name, gb_ymap *m,
                       gb_error *err);
/* The value of `key`, or NULL if absent (then it is an error when `flags` has GB_Y_REQUIRED). */
gb_status gb_ymap_find(gb_ymap *m, const char *key, int flags, struct fy_node **out, gb_error *err);
/* A number; when optional and absent, *out keeps its value (the default). */
gb_status gb_ymap_number(gb_ymap *m, const char *key, int flags, double *out, gb_error *err);
/* A whole number in [lo, hi]. */
gb_status gb_ymap_int(gb_ymap *m, const char *key, int flags, long lo, long hi, long *out, gb_error *err);
gb_status gb_ymap_bool(gb_ymap *m, const char *key, int flags, int *out, gb_error *err);
/* A string copied into buf (size n); when optional and absent, buf is unchanged. */
gb_status gb_ymap_string(gb_ymap *m, const char *key, int flags, char *buf, size_t n, gb_error *err);
/* A nested mapping. When optional and absent, sub is opened on an empty mapping. */
gb_status gb_ymap_map(gb_ymap *m, const char *key, int flags, gb_ymap *sub, gb_error *err);
/* A number array of exactly n entries ([x, y] and the like). */
gb_status gb_ymap_vector(gb_ymap *m, const char *key, int flags, int n, double *out, gb_error *err);
/* A list of 1 to max numbers into out, their count in *n (unchanged when optional and absent). */
gb_status gb_ymap_numbers(gb_ymap *m, const char *key, int flags, int max, double *out, int *n, gb_error *err);
/* Refuses any key that was never looked up, naming the keys that are expected. */
gb_status gb_ymap_close(gb_ymap *m, gb_error *err);
/* The required `units: {length, force}` of a run scene or a BEM scene, each into a buffer of n. */
gb_status gb_ymap_units(gb_ymap *top, char *length, char *force, size_t n, gb_error *err);

/* The first of names[0..n) that `written` (len bytes) is a likely misspelling of (an edit or two,
 * case aside), or -1: for "did you mean" in messages. */
int gb_yaml_closest(const char *written, size_t len, const char *const *names, int n);

/* Resolve a path named in a scene relative to the scene file's directory. */
void gb_yaml_relative_path(const gb_yaml_doc *doc, const char *name, char *out, size_t n);

#endif
