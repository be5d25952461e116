/* Elastostatic scenes (`gembem bem`, and a hybrid scene's host): YAML through the shared reader,
 * every error at file:line:column. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gembem/scene.h"
#include "scene/bem_scene_read.h"
#include "scene/yaml_read.h"

void gb_bem_scene_free(gb_bem_scene *s)
{
    if (!s) return;
    gb_bem_mesh_free(&s->mesh);
    free(s->pts);
    free(s->pt_inside);
    s->pts = NULL;
    s->pt_inside = NULL;
    s->npts = 0;
}

static const char *scalar_of(struct fy_node *n, size_t *len)
{
    *len = 0;
    if (!n || fy_node_get_type(n) != FYNT_SCALAR) return NULL;
    return fy_node_get_scalar(n, len);
}

/* A key's node without marking it asked again (for messages about a value already read). */
static struct fy_node *lookup(const gb_ymap *m, const char *key)
{
    return m->node ? fy_node_mapping_lookup_by_string(m->node, key, FY_NT) : NULL;
}

static int scalar_is(struct fy_node *n, const char *word)
{
    size_t len;
    const char *s = scalar_of(n, &len);
    return s && len == strlen(word) && !strncmp(s, word, len);
}

static gb_status read_material(const gb_yaml_doc *doc, gb_ymap *root, gb_bem_scene *s, gb_error *err)
{
    gb_ymap m;
    gb_status st;
    char plane[16] = "";
    if ((st = gb_ymap_map(root, "material", GB_Y_REQUIRED, &m, err))) return st;
    if ((st = gb_ymap_number(&m, "shear_modulus", GB_Y_REQUIRED | GB_Y_POSITIVE, &s->material.shear_modulus, err)))
        return st;
    if ((st = gb_ymap_number(&m, "poisson", GB_Y_REQUIRED, &s->material.poisson, err))) return st;
    if (!(s->material.poisson > -1 && s->material.poisson < 0.5)) {
        return gb_yaml_fail(doc, lookup(&m, "poisson"), err,
                            "material.poisson: expected a number in (-1, 0.5), found %g", s->material.poisson);
    }
    if ((st = gb_ymap_string(&m, "plane", GB_Y_REQUIRED, plane, sizeof plane, err))) return st;
    if (!strcmp(plane, "strain"))
        s->material.plane = GB_BEM_PLANE_STRAIN;
    else if (!strcmp(plane, "stress"))
        s->material.plane = GB_BEM_PLANE_STRESS;
    else {
        return gb_yaml_fail(doc, lookup(&m, "plane"), err, "material.plane: expected strain or stress, found '%s'",
                            plane);
    }
    return gb_ymap_close(&m, err);
}

/* mesh: file, unbounded, size, groups {name: {size | count}}; the mesh is built here. */
static gb_status read_mesh(const gb_yaml_doc *doc, gb_ymap *root, gb_bem_scene *s, gb_error *err)
{
    gb_ymap m;
    gb_status st;
    char file[512] = "";
    struct fy_node *file_node = NULL, *groups = NULL, *gnodes[GB_BEM_MAX_GROUPS] = {0};
    s->mesh_opts = gb_bem_mesh_opts_default();
    if ((st = gb_ymap_map(root, "mesh", GB_Y_REQUIRED, &m, err))) return st;
    if ((st = gb_ymap_string(&m, "file", GB_Y_REQUIRED, file, sizeof file, err))) return st;
    file_node = lookup(&m, "file");
    if ((st = gb_ymap_bool(&m, "unbounded", 0, &s->mesh_opts.unbounded, err))) return st;
    if ((st = gb_ymap_number(&m, "size", GB_Y_POSITIVE, &s->mesh_opts.size, err))) return st;
    if ((st = gb_ymap_find(&m, "groups", 0, &groups, err))) return st;
    if (groups) {
        if (fy_node_get_type(groups) != FYNT_MAPPING)
            return gb_yaml_fail(doc, groups, err,
                                "mesh.groups: expected a mapping of group names to {size: h} or {count: n}");
        void *it = NULL;
        struct fy_node_pair *p;
        while ((p = fy_node_mapping_iterate(groups, &it))) {
            size_t len;
            const char *name = scalar_of(fy_node_pair_key(p), &len);
            int i = s->mesh_opts.n_group_sizes;
            if (!name || len == 0 || len >= GB_BEM_NAME_MAX)
                return gb_yaml_fail(doc, fy_node_pair_key(p), err, "mesh.groups: expected a group name");
            if (i == GB_BEM_MAX_GROUPS)
                return gb_yaml_fail(doc, fy_node_pair_key(p), err, "mesh.groups: at most %d groups", GB_BEM_MAX_GROUPS);
            gb_bem_group_size *gs = &s->mesh_opts.group_sizes[i];
            memcpy(gs->group, name, len);
            gs->group[len] = '\0';
            gnodes[i] = fy_node_pair_key(p);
            char path[128];
            snprintf(path, sizeof path, "mesh.groups.%s", gs->group);
            gb_ymap g;
            long count = 0;
            if ((st = gb_ymap_open(doc, fy_node_pair_value(p), path, &g, err))) return st;
            if ((st = gb_ymap_number(&g, "size", GB_Y_POSITIVE, &gs->size, err))) return st;
            if ((st = gb_ymap_int(&g, "count", 0, 1, GB_BEM_MAX_COUNT, &count, err))) return st;
            if ((st = gb_ymap_close(&g, err))) return st;
            gs->count = (int)count;
            if ((gs->size > 0) == (gs->count > 0))
                return gb_yaml_fail(doc, fy_node_pair_value(p), err, "%s: give either size or count", path);
            s->mesh_opts.n_group_sizes++;
        }
    }
    if ((st = gb_ymap_close(&m, err))) return st;
    gb_yaml_relative_path(doc, file, s->mesh_path, sizeof s->mesh_path);
    st = gb_bem_mesh_load(s->mesh_path, &s->mesh_opts, &s->mesh, err);
    if (st == GB_EINPUT) {
        char msg[GB_ERROR_MSG_MAX];
        snprintf(msg, sizeof msg, "%s", err->msg);
        for (int i = 0; i < s->mesh_opts.n_group_sizes; i++) {
            char needle[GB_BEM_NAME_MAX + 40];
            snprintf(needle, sizeof needle, "no physical curve group named '%s'", s->mesh_opts.group_sizes[i].group);
            if (strstr(msg, needle))
                return gb_yaml_fail(doc, gnodes[i], err, "mesh.groups: the mesh has no physical curve group named '%s'",
                                    s->mesh_opts.group_sizes[i].group);
            snprintf(needle, sizeof needle, "on group '%s'", s->mesh_opts.group_sizes[i].group);
            if (strstr(msg, "an element size of") && strstr(msg, needle))
                return gb_yaml_fail(doc, gnodes[i], err, "mesh.groups.%s.size: %s", s->mesh_opts.group_sizes[i].group,
                                    msg);
        }
        if (strstr(msg, "an element size of")) return gb_yaml_fail(doc, lookup(&m, "size"), err, "mesh.size: %s", msg);
        return gb_yaml_fail(doc, file_node, err, "mesh.file: %s", msg);
    }
    return st;
}

gb_status gb_bem_bc_read(const gb_yaml_doc *doc, struct fy_node *val, const char *path, gb_bem_bc *bc, gb_error *err)
{
    gb_status st;
    memset(bc, 0, sizeof *bc);
    if (scalar_is(val, "fixed")) {
        bc->kind = GB_BEM_BC_FIXED;
        return GB_OK;
    }
    if (scalar_is(val, "free")) {
        bc->kind = GB_BEM_BC_FREE;
        return GB_OK;
    }
    if (!val || fy_node_get_type(val) != FYNT_MAPPING)
        return gb_yaml_fail(doc, val, err,
                            "%s: expected fixed, free, {displacement: [ux, uy]}, {traction: [tx, ty]}, "
                            "{pressure: p}, {normal_displacement: d} or {ux | tx: a, uy | ty: b}",
                            path);
    gb_ymap c;
    int found = 0;
    if ((st = gb_ymap_open(doc, val, path, &c, err))) return st;
    if (lookup(&c, "displacement")) found++, bc->kind = GB_BEM_BC_DISPLACEMENT;
    if ((st = gb_ymap_vector(&c, "displacement", 0, 2, bc->value, err))) return st;
    if (lookup(&c, "traction")) found++, bc->kind = GB_BEM_BC_TRACTION;
    if ((st = gb_ymap_vector(&c, "traction", 0, 2, bc->value, err))) return st;
    if (lookup(&c, "pressure")) found++, bc->kind = GB_BEM_BC_PRESSURE;
    if ((st = gb_ymap_number(&c, "pressure", 0, &bc->value[0], err))) return st;
    if (lookup(&c, "normal_displacement")) found++, bc->kind = GB_BEM_BC_NORMAL_DISPLACEMENT;
    if ((st = gb_ymap_number(&c, "normal_displacement", 0, &bc->value[0], err))) return st;
    /* component-wise: one of ux / tx and one of uy / ty */
    static const char *const ck[4] = {"ux", "tx", "uy", "ty"};
    int per[2] = {0, 0};
    for (int q = 0; q < 4; q++) {
        double x = NAN;
        if ((st = gb_ymap_number(&c, ck[q], 0, &x, err))) return st;
        if (isnan(x)) continue; /* absent */
        per[q / 2]++;
        bc->value[q / 2] = x;
        if (q % 2 == 0) bc->u_given |= 1 << (q / 2);
    }
    if (per[0] || per[1]) {
        found++;
        bc->kind = GB_BEM_BC_COMPONENTS;
        if (per[0] != 1 || per[1] != 1) return gb_yaml_fail(doc, val, err, "%s: give one of ux, tx and one of uy, ty", path);
    }
    if ((st = gb_ymap_close(&c, err))) return st;
    if (found != 1)
        return gb_yaml_fail(doc, val, err,
                            "%s: expected exactly one of displacement, traction, pressure, normal_displacement, "
                            "or component-wise {ux | tx, uy | ty}",
                            path);
    return GB_OK;
}

/* boundary: {group: condition, ...} for every group of the mesh */
static gb_status read_boundary(const gb_yaml_doc *doc, gb_ymap *root, gb_bem_scene *s, gb_error *err)
{
    struct fy_node *b = NULL;
    gb_status st = gb_ymap_find(root, "boundary", GB_Y_REQUIRED, &b, err);
    if (st) return st;
    if (fy_node_get_type(b) != FYNT_MAPPING)
        return gb_yaml_fail(doc, b, err, "boundary: expected a mapping of group names to conditions");
    void *it = NULL;
    struct fy_node_pair *p;
    while ((p = fy_node_mapping_iterate(b, &it))) {
        struct fy_node *key = fy_node_pair_key(p), *val = fy_node_pair_value(p);
        size_t len;
        const char *name = scalar_of(key, &len);
        char gname[GB_BEM_NAME_MAX] = "";
        if (name && len < sizeof gname) memcpy(gname, name, len), gname[len] = '\0';
        int g = gb_bem_mesh_group(&s->mesh, gname);
        if (g < 0) {
            char known[600] = "";
            size_t used = 0;
            for (int i = 0; i < s->mesh.n_groups && used < sizeof known - 1; i++)
                used +=
                    (size_t)snprintf(known + used, sizeof known - used, "%s%s", i ? ", " : "", s->mesh.group_name[i]);
            return gb_yaml_fail(doc, key, err, "boundary: the mesh has no group '%s'; its groups are: %s", gname,
                                known);
        }
        if (s->problem.bc[g].kind != GB_BEM_BC_NONE)
            return gb_yaml_fail(doc, key, err, "boundary: group '%s' given twice", gname);
        char path[128];
        snprintf(path, sizeof path, "boundary.%s", gname);
        if ((st = gb_bem_bc_read(doc, val ? val : key, path, &s->problem.bc[g], err))) return st;
    }
    for (int g = 0; g < s->mesh.n_groups; g++)
        if (s->problem.bc[g].kind == GB_BEM_BC_NONE)
            return gb_yaml_fail(doc, b, err, "boundary: no condition for group '%s'", s->mesh.group_name[g]);
    return GB_OK;
}

/* Distance from (x, y) to the nearest element, relative to that element's length. */
static double relative_distance(const gb_bem_mesh *m, double x, double y)
{
    double best = INFINITY, rel = INFINITY;
    for (int e = 0; e < m->n; e++) {
        const double *a = m->p0 + 2 * e, *b = m->p1 + 2 * e;
        double d[2] = {b[0] - a[0], b[1] - a[1]}, w[2] = {x - a[0], y - a[1]};
        double t = (w[0] * d[0] + w[1] * d[1]) / (d[0] * d[0] + d[1] * d[1]);
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        double dist = hypot(w[0] - t * d[0], w[1] - t * d[1]);
        if (dist < best) best = dist, rel = dist / m->length[e];
    }
    return rel;
}

/* A point is evaluated if it is inside the body: a listed point anywhere off the boundary, a grid
 * point only from half an element length away (nearer, constant elements give a poor field). */
static gb_status add_point(gb_bem_scene *s, int *cap, double x, double y, int grid, gb_error *err)
{
    if (s->npts == *cap) {
        int nc = *cap ? 2 * *cap : 64;
        double *p = realloc(s->pts, sizeof(double) * 2 * (size_t)nc);
        if (!p) return gb_fail(err, GB_ENOMEM, "out of memory");
        s->pts = p;
        int *q = realloc(s->pt_inside, sizeof(int) * (size_t)nc);
        if (!q) return gb_fail(err, GB_ENOMEM, "out of memory");
        s->pt_inside = q;
        *cap = nc;
    }
    s->pts[2 * s->npts] = x;
    s->pts[2 * s->npts + 1] = y;
    s->pt_inside[s->npts] = gb_bem_mesh_inside(&s->mesh, x, y) && relative_distance(&s->mesh, x, y) > (grid ? 0.5 : 1e-6);
    s->npts++;
    return GB_OK;
}

/* interior: grid {x: [x0, x1], y: [y0, y1], n: [nx, ny]} and/or points [[x, y], ...] */
static gb_status read_interior(const gb_yaml_doc *doc, gb_ymap *root, gb_bem_scene *s, gb_error *err)
{
    gb_ymap in, grid;
    gb_status st;
    struct fy_node *gnode = NULL, *pts = NULL;
    int cap = 0;
    if ((st = gb_ymap_map(root, "interior", 0, &in, err))) return st;
    if ((st = gb_ymap_find(&in, "grid", 0, &gnode, err))) return st;
    if (gnode) {
        double xr[2], yr[2], n[2];
        if ((st = gb_ymap_open(doc, gnode, "interior.grid", &grid, err))) return st;
        if ((st = gb_ymap_vector(&grid, "x", GB_Y_REQUIRED, 2, xr, err))) return st;
        if ((st = gb_ymap_vector(&grid, "y", GB_Y_REQUIRED, 2, yr, err))) return st;
        if ((st = gb_ymap_vector(&grid, "n", GB_Y_REQUIRED, 2, n, err))) return st;
        struct fy_node *nn = lookup(&grid, "n");
        if (n[0] != floor(n[0]) || n[1] != floor(n[1]) || n[0] < 2 || n[1] < 2 || n[0] * n[1] > 1e6)
            return gb_yaml_fail(doc, nn, err, "interior.grid.n: expected two whole numbers >= 2 (at most 1e6 points)");
        if (!(xr[1] > xr[0]) || !(yr[1] > yr[0]))
            return gb_yaml_fail(doc, gnode, err,
                                "interior.grid: expected x: [min, max] and y: [min, max] with min < max");
        if ((st = gb_ymap_close(&grid, err))) return st;
        s->grid_nx = (int)n[0];
        s->grid_ny = (int)n[1];
        for (int j = 0; j < s->grid_ny; j++)
            for (int i = 0; i < s->grid_nx; i++)
                if ((st = add_point(s, &cap, xr[0] + (xr[1] - xr[0]) * i / (s->grid_nx - 1),
                                    yr[0] + (yr[1] - yr[0]) * j / (s->grid_ny - 1), 1, err)))
                    return st;
    }
    if ((st = gb_ymap_find(&in, "points", 0, &pts, err))) return st;
    if (pts) {
        if (fy_node_get_type(pts) != FYNT_SEQUENCE)
            return gb_yaml_fail(doc, pts, err, "interior.points: expected a list of [x, y]");
        int np = fy_node_sequence_item_count(pts);
        for (int i = 0; i < np; i++) {
            struct fy_node *p = fy_node_sequence_get_by_index(pts, i);
            double v[2];
            if (fy_node_get_type(p) != FYNT_SEQUENCE || fy_node_sequence_item_count(p) != 2)
                return gb_yaml_fail(doc, p, err, "interior.points[%d]: expected [x, y]", i);
            for (int c = 0; c < 2; c++)
                if ((st = gb_yaml_number(doc, fy_node_sequence_get_by_index(p, c), "interior.points", &v[c], err)))
                    return st;
            if ((st = add_point(s, &cap, v[0], v[1], 0, err))) return st;
            if (!s->pt_inside[s->npts - 1])
                return gb_yaml_fail(doc, p, err,
                                    "interior.points[%d]: (%g, %g) is not inside the body (or lies on its boundary)", i,
                                    v[0], v[1]);
        }
    }
    return gb_ymap_close(&in, err);
}

gb_status gb_bem_host_read(const gb_yaml_doc *doc, gb_ymap *root, gb_bem_scene *s, gb_error *err)
{
    gb_status st = read_material(doc, root, s, err);
    if (!st) st = read_mesh(doc, root, s, err);
    if (!st) st = read_boundary(doc, root, s, err);
    struct fy_node *rs = lookup(root, "remote_stress");
    if (!st) st = gb_ymap_vector(root, "remote_stress", 0, 3, s->problem.remote_stress, err);
    if (!st && rs && !s->mesh.unbounded)
        st = gb_yaml_fail(doc, rs, err, "remote_stress: applies to an unbounded body only (mesh.unbounded: true)");
    return st;
}

/* updated_lagrangian: {increments: n}; not with a condensed stiffness, whose f0 on the moved mesh
 * would be that of the whole load again. */
static gb_status read_updated(const gb_yaml_doc *doc, gb_ymap *root, gb_bem_scene *s, gb_error *err)
{
    gb_ymap ul;
    long n = 0;
    gb_status st = gb_ymap_map(root, "updated_lagrangian", 0, &ul, err);
    if (st || !ul.node) return st;
    if ((st = gb_ymap_int(&ul, "increments", GB_Y_REQUIRED, 1, GB_BEM_MAX_INCREMENTS, &n, err))) return st;
    s->increments = (int)n;
    if ((st = gb_ymap_close(&ul, err))) return st;
    if (s->stiffness_group[0])
        return gb_yaml_fail(doc, ul.node, err,
                            "updated_lagrangian: the condensed stiffness (stiffness.group) is computed on the "
                            "undeformed body only; remove one of the two");
    return GB_OK;
}

gb_status gb_bem_scene_load(const char *path, gb_bem_scene *s, gb_error *err)
{
    memset(s, 0, sizeof *s);
    snprintf(s->path, sizeof s->path, "%s", path);
    gb_yaml_doc doc;
    gb_status st = gb_yaml_load(path, &doc, err);
    if (st) return st;
    gb_ymap root, stiff;
    if (!st) st = gb_ymap_open(&doc, fy_document_root(doc.fyd), "", &root, err);
    if (!st) st = gb_ymap_units(&root, s->length_unit, s->force_unit, sizeof s->length_unit, err);
    if (!st) st = gb_bem_host_read(&doc, &root, s, err);
    if (!st) st = read_interior(&doc, &root, s, err);
    if (!st) st = gb_ymap_map(&root, "stiffness", 0, &stiff, err);
    if (!st) {
        struct fy_node *g = NULL;
        st = gb_ymap_string(&stiff, "group", 0, s->stiffness_group, sizeof s->stiffness_group, err);
        if (!st) g = lookup(&stiff, "group");
        if (!st && g && gb_bem_mesh_group(&s->mesh, s->stiffness_group) < 0)
            st = gb_yaml_fail(&doc, g, err, "stiffness.group: the mesh has no group '%s'", s->stiffness_group);
        if (!st) st = gb_ymap_bool(&stiff, "write", 0, &s->stiffness_write, err);
        if (!st && s->stiffness_write && !g) st = gb_yaml_fail(&doc, stiff.node, err, "stiffness: write needs a group");
        if (!st) st = gb_ymap_close(&stiff, err);
    }
    if (!st) st = read_updated(&doc, &root, s, err);
    gb_ymap out;
    s->write_boundary_csv = s->write_boundary_vtp = s->write_interior_vtu = s->write_interior_csv = 1;
    if (!st) st = gb_ymap_map(&root, "output", 0, &out, err);
    if (!st) st = gb_ymap_bool(&out, "boundary_csv", 0, &s->write_boundary_csv, err);
    if (!st) st = gb_ymap_bool(&out, "boundary_vtp", 0, &s->write_boundary_vtp, err);
    if (!st) st = gb_ymap_bool(&out, "interior_vtu", 0, &s->write_interior_vtu, err);
    if (!st) st = gb_ymap_bool(&out, "interior_csv", 0, &s->write_interior_csv, err);
    if (!st) st = gb_ymap_close(&out, err);
    if (!st) st = gb_ymap_close(&root, err);
    gb_yaml_free(&doc);
    if (st) gb_bem_scene_free(s);
    return st;
}
