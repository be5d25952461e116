#include "scene/grains_file.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/admit.h"
#include "scene/csv_read.h"

static const char *const wall_names[GB_N_WALLS] = {"left", "right", "bottom", "top"};

int gb_wall_from_name(const char *name)
{
    for (int w = 0; w < GB_N_WALLS; w++)
        if (!strcmp(name, wall_names[w])) return w;
    return -1;
}

const char *gb_wall_name(int wall) { return wall >= 0 && wall < GB_N_WALLS ? wall_names[wall] : "?"; }

void gb_side_name(int j, char *buf, size_t n)
{
    if (j >= 0) snprintf(buf, n, "%d", j);
    else if (j >= -GB_N_WALLS) snprintf(buf, n, "%s", wall_names[-1 - j]);
    else snprintf(buf, n, "p%d", -1 - GB_N_WALLS - j); /* a boundary particle */
}

static gb_status grain_check(const gb_grain *g, gb_status (*fail)(void *, const char *), void *ctx)
{
    if (!(g->r > 0)) return fail(ctx, "a positive radius");
    return GB_OK;
}

typedef struct {
    const gb_yaml_doc *doc;
    struct fy_node *node;
    gb_error *err;
} yaml_ctx;

static gb_status yaml_grain_fail(void *p, const char *what)
{
    yaml_ctx *c = p;
    return gb_yaml_fail(c->doc, c->node, c->err, "grains.list: expected %s", what);
}

/* Room for the line and column of cap grains. */
static gb_status grow_where(gb_scene *s, int cap, gb_error *err)
{
    int *l = realloc(s->grain_line, (size_t)cap * sizeof(int));
    if (l) s->grain_line = l;
    int *c = l ? realloc(s->grain_col, (size_t)cap * sizeof(int)) : NULL;
    if (c) s->grain_col = c;
    return l && c ? GB_OK : gb_fail(err, GB_ENOMEM, "out of memory for %d grains", cap);
}

static gb_status read_list(gb_ymap *m, struct fy_node *list, gb_scene *s, gb_error *err)
{
    if (fy_node_get_type(list) != FYNT_SEQUENCE)
        return gb_yaml_fail(m->doc, list, err, "grains.list: expected a list of [x, y, r] or [x, y, r, rotation]");
    int n = fy_node_sequence_item_count(list);
    s->grains = calloc((size_t)(n > 0 ? n : 1), sizeof *s->grains);
    if (!s->grains) return gb_fail(err, GB_ENOMEM, "out of memory for %d grains", n);
    gb_status st0 = grow_where(s, n > 0 ? n : 1, err);
    if (st0) return st0;
    snprintf(s->grains_file, sizeof s->grains_file, "%s", m->doc->path);
    for (int i = 0; i < n; i++) {
        struct fy_node *item = fy_node_sequence_get_by_index(list, i);
        int k = fy_node_get_type(item) == FYNT_SEQUENCE ? fy_node_sequence_item_count(item) : 0;
        if (k != 3 && k != 4)
            return gb_yaml_fail(m->doc, item, err, "grains.list[%d]: expected [x, y, r] or [x, y, r, rotation]", i);
        double v[4] = {0, 0, 0, 0};
        for (int c = 0; c < k; c++) {
            gb_status st = gb_yaml_number(m->doc, fy_node_sequence_get_by_index(item, c), "grains.list", &v[c], err);
            if (st) return st;
        }
        gb_grain g = {v[0], v[1], v[2], v[3]};
        yaml_ctx ctx = {m->doc, fy_node_sequence_get_by_index(item, 2), err};
        gb_status st = grain_check(&g, yaml_grain_fail, &ctx);
        if (st) return st;
        gb_yaml_where(item, &s->grain_line[s->n_grains], &s->grain_col[s->n_grains]);
        s->grains[s->n_grains++] = g;
    }
    return GB_OK;
}

typedef struct {
    gb_csv *csv;
    int field;
    gb_error *err;
} csv_ctx;

static gb_status csv_grain_fail(void *p, const char *what)
{
    csv_ctx *c = p;
    return gb_csv_fail(c->csv, c->field, c->err, what);
}

static gb_status read_grains_csv(const char *path, gb_scene *s, gb_error *err)
{
    gb_csv csv;
    gb_status st = gb_csv_open(path, &csv, err);
    if (st) return st;
    int col[4] = {gb_csv_column(&csv, "x"), gb_csv_column(&csv, "y"), gb_csv_column(&csv, "r"),
                  gb_csv_column(&csv, "rotation")};
    int cap = 1024;
    if (col[0] < 0 || col[1] < 0 || col[2] < 0)
        st = gb_fail(err, GB_EINPUT, "%s:1: the header must name the columns x, y, r (and optionally rotation)", path);
    for (int k = 0; !st && k < csv.n_header; k++)
        if (k != col[0] && k != col[1] && k != col[2] && k != col[3])
            st = gb_fail(err, GB_EINPUT, "%s:1:%d: unknown column '%s'; expected x, y, r, rotation", path,
                         csv.column[k], csv.header[k]);
    if (!st && !(s->grains = malloc((size_t)cap * sizeof *s->grains))) st = gb_fail(err, GB_ENOMEM, "out of memory");
    if (!st) st = grow_where(s, cap, err);
    snprintf(s->grains_file, sizeof s->grains_file, "%s", path);
    for (int has = 1; !st;) {
        if ((st = gb_csv_next(&csv, &has, err)) || !has) break;
        if (s->n_grains == cap) {
            gb_grain *g = realloc(s->grains, (size_t)(cap *= 2) * sizeof *g);
            if (!g) {
                st = gb_fail(err, GB_ENOMEM, "out of memory for %d grains", cap);
                break;
            }
            s->grains = g;
            if ((st = grow_where(s, cap, err))) break;
        }
        double v[4] = {0, 0, 0, 0};
        for (int c = 0; c < 4 && !st; c++)
            if (col[c] >= 0) st = gb_csv_number(&csv, col[c], &v[c], err);
        if (st) break;
        gb_grain g = {v[0], v[1], v[2], v[3]};
        csv_ctx ctx = {&csv, col[2], err};
        if ((st = grain_check(&g, csv_grain_fail, &ctx))) break;
        s->grain_line[s->n_grains] = csv.line;
        s->grain_col[s->n_grains] = csv.column[col[0]];
        s->grains[s->n_grains++] = g;
    }
    gb_csv_close(&csv);
    return st;
}

/* Contacts file: columns i, j, pt (j a grain index or a wall name), optionally mr (the rolling
 * moment on grain i, docs/method.md section 3.1); the other columns gembem writes
 * (pn, nx, ny, overlap, energy, dissipation, end points) may be present and are not read: the
 * normal force follows from the overlap. */
static gb_status read_contacts_csv(const char *path, gb_scene *s, gb_error *err)
{
    gb_csv csv;
    gb_status st = gb_csv_open(path, &csv, err);
    if (st) return st;
    int ci = gb_csv_column(&csv, "i"), cj = gb_csv_column(&csv, "j"), cp = gb_csv_column(&csv, "pt");
    int cm = gb_csv_column(&csv, "mr");
    static const char *const informative[] = {"pn", "nx", "ny", "overlap", "energy", "dissipation",
                                              "xi", "yi", "xj", "yj"};
    enum { N_INFORMATIVE = sizeof informative / sizeof *informative };
    if (ci < 0 || cj < 0 || cp < 0)
        st = gb_fail(err, GB_EINPUT, "%s:1: the header must name the columns i, j, pt", path);
    for (int k = 0; !st && k < csv.n_header; k++) {
        int known = k == ci || k == cj || k == cp || k == cm;
        for (int q = 0; q < N_INFORMATIVE; q++) known |= !strcmp(csv.header[k], informative[q]);
        if (!known)
            st = gb_fail(err, GB_EINPUT, "%s:1:%d: unknown column '%s'; expected i, j, pt, mr and those gembem writes",
                         path, csv.column[k], csv.header[k]);
    }
    int cap = 1024;
    if (!st && !(s->restart.contacts = malloc((size_t)cap * sizeof *s->restart.contacts))) st = gb_fail(err, GB_ENOMEM, "out of memory");
    for (int has = 1; !st;) {
        if ((st = gb_csv_next(&csv, &has, err)) || !has) break;
        if (s->restart.n_contacts == cap) {
            gb_contact_init *c = realloc(s->restart.contacts, (size_t)(cap *= 2) * sizeof *c);
            if (!c) {
                st = gb_fail(err, GB_ENOMEM, "out of memory");
                break;
            }
            s->restart.contacts = c;
        }
        double i, j = 0, pt, mr = 0;
        if ((st = gb_csv_number(&csv, ci, &i, err)) || (st = gb_csv_number(&csv, cp, &pt, err)) ||
            (cm >= 0 && (st = gb_csv_number(&csv, cm, &mr, err))))
            break;
        /* the bound's reason: src/scene/admit.h */
        if (!(fabs(pt) <= GB_FORCE_MAX) || !(fabs(mr) <= GB_FORCE_MAX)) {
            st = gb_csv_fail(&csv, fabs(pt) <= GB_FORCE_MAX ? cm : cp, err,
                             "a magnitude of at most 1e145 (a run squares forces and moments and sums them over "
                             "the grains: beyond it, the run goes non-finite)");
            break;
        }
        int wall = gb_wall_from_name(csv.field[cj]), particle = -1;
        /* a boundary particle of a host, p<e> (a hybrid run's state) */
        if (s->host.present && csv.field[cj][0] == 'p' && csv.field[cj][1] >= '0' && csv.field[cj][1] <= '9') {
            char *end;
            long e = strtol(csv.field[cj] + 1, &end, 10);
            if (*end || e > 100000000L) {
                st = gb_csv_fail(&csv, cj, err, "a grain index or a boundary particle p<element>");
                break;
            }
            particle = (int)e;
        }
        if (wall >= 0 && s->host.present) {
            st = gb_csv_fail(&csv, cj, err, "a grain index or a boundary particle p<element> (a host has no walls)");
            break;
        }
        if (wall < 0 && particle < 0 && (st = gb_csv_number(&csv, cj, &j, err))) {
            st = gb_csv_fail(&csv, cj, err, s->host.present ? "a grain index or a boundary particle p<element>"
                                                            : "a grain index or a wall name (left, right, bottom, top)");
            break;
        }
        if (i != floor(i) || i < 0 || i >= s->n_grains) {
            st = gb_csv_fail(&csv, ci, err, "a grain index of the grains file");
            break;
        }
        if (wall < 0 && particle < 0 && (j != floor(j) || j < 0 || j >= s->n_grains || j == i)) {
            st = gb_csv_fail(&csv, cj, err, "another grain's index of the grains file");
            break;
        }
        gb_contact_init c = {(int)i, wall >= 0 ? -1 - wall : particle >= 0 ? -1 - GB_N_WALLS - particle : (int)j, pt, mr};
        s->restart.contacts[s->restart.n_contacts++] = c;
    }
    gb_csv_close(&csv);
    return st;
}

gb_status gb_grains_section_read(gb_ymap *m, gb_scene *s, gb_error *err)
{
    struct fy_node *list, *file;
    char name[512] = "", path[1024];
    gb_status st;
    if ((st = gb_ymap_find(m, "list", 0, &list, err)) || (st = gb_ymap_find(m, "file", 0, &file, err))) return st;
    if (!list == !file)
        return gb_yaml_fail(m->doc, m->node, err, "%s: expected exactly one of 'list' (inline grains) or 'file' (CSV)",
                            m->name);
    if (list) {
        if ((st = read_list(m, list, s, err))) return st;
    } else {
        if ((st = gb_ymap_string(m, "file", GB_Y_REQUIRED, name, sizeof name, err))) return st;
        gb_yaml_relative_path(m->doc, name, path, sizeof path);
        if ((st = read_grains_csv(path, s, err))) return st;
    }
    if (s->n_grains == 0) return gb_yaml_fail(m->doc, m->node, err, "%s: expected at least one grain", m->name);
    /* jammed inputs may overlap more than the default admits (src/scene/admit.c) */
    struct fy_node *mo;
    s->max_overlap = GB_MAX_OVERLAP_DEFAULT;
    if ((st = gb_ymap_find(m, "max_overlap", 0, &mo, err)) ||
        (st = gb_ymap_number(m, "max_overlap", GB_Y_POSITIVE, &s->max_overlap, err)))
        return st;
    if (!(s->max_overlap <= 1))
        return gb_yaml_fail(m->doc, mo, err, "%s.max_overlap: expected a share of the smaller radius in (0, 1] (1: "
                                             "a centre on the other grain's edge or on the wall)", m->name);
    name[0] = '\0';
    if ((st = gb_ymap_string(m, "contacts", 0, name, sizeof name, err))) return st;
    if (name[0]) {
        gb_yaml_relative_path(m->doc, name, path, sizeof path);
        if ((st = read_contacts_csv(path, s, err))) return st;
    }
    return gb_ymap_close(m, err);
}

gb_status gb_box_read(gb_ymap *parent, gb_box *box, gb_error *err)
{
    gb_ymap m;
    gb_status st;
    if ((st = gb_ymap_map(parent, "box", GB_Y_REQUIRED, &m, err))) return st;
    if ((st = gb_ymap_number(&m, "left", GB_Y_REQUIRED, &box->left, err)) ||
        (st = gb_ymap_number(&m, "right", GB_Y_REQUIRED, &box->right, err)) ||
        (st = gb_ymap_number(&m, "bottom", GB_Y_REQUIRED, &box->bottom, err)) ||
        (st = gb_ymap_number(&m, "top", GB_Y_REQUIRED, &box->top, err)) || (st = gb_ymap_close(&m, err)))
        return st;
    if (!(box->right > box->left) || !(box->top > box->bottom))
        return gb_yaml_fail(m.doc, m.node, err, "box: expected right > left and top > bottom");
    return GB_OK;
}

static double overlap(const gb_scene *s, const gb_contact_init *c)
{
    const gb_grain *a = &s->grains[c->i];
    if (c->j >= 0) {
        const gb_grain *b = &s->grains[c->j];
        return a->r + b->r - hypot(b->x - a->x, b->y - a->y);
    }
    switch (-1 - c->j) {
    case GB_WALL_LEFT: return a->r - (a->x - s->box.left);
    case GB_WALL_RIGHT: return a->r - (s->box.right - a->x);
    case GB_WALL_BOTTOM: return a->r - (a->y - s->box.bottom);
    default: return a->r - (s->box.top - a->y);
    }
}

gb_status gb_grains_check(const gb_scene *s, const char *where, gb_error *err)
{
    for (int k = 0; k < s->restart.n_contacts; k++) {
        const gb_contact_init *c = &s->restart.contacts[k];
        if (!(overlap(s, c) > 0))
            return gb_fail(err, GB_EINPUT, "%s: initial contact %d (grain %d with %s %d) does not overlap; "
                           "expected a contact force only where grains overlap",
                           where, k, c->i, c->j >= 0 ? "grain" : gb_wall_name(-1 - c->j), c->j >= 0 ? c->j : 0);
    }
    return GB_OK;
}
