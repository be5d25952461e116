/* The `host:` section of a scene: an elastic body whose cavity holds the grains. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene/bem_scene_read.h"
#include "scene/host_read.h"

/* Checks, with the scene's line and column, that the mesh's groups are the ones the scene names:
 * the cavity, and a condition for every other group. */
static gb_status check_groups(gb_ymap *m, struct fy_node *bc_node, const gb_host_def *h, const gb_bem_mesh *mesh,
                              gb_error *err)
{
    gb_status st = GB_OK;
    struct fy_node *v;
    char names[GB_BEM_MAX_GROUPS * (GB_BEM_NAME_MAX + 2)] = "";
    for (int g = 0; g < mesh->n_groups; g++) {
        size_t used = strlen(names);
        snprintf(names + used, sizeof names - used, "%s%s", g ? ", " : "", mesh->group_name[g]);
    }
    gb_ymap_find(m, "cavity", 0, &v, err);
    if (gb_bem_mesh_group(mesh, h->cavity) < 0)
        st = gb_yaml_fail(m->doc, v, err, "host.cavity: the mesh %s has no physical group '%s'; expected one of: %s",
                          h->mesh, h->cavity, names);
    for (int k = 0; !st && k < h->n_bcs; k++)
        if (gb_bem_mesh_group(mesh, h->bc_group[k]) < 0 || !strcmp(h->bc_group[k], h->cavity))
            st = gb_yaml_fail(m->doc, bc_node, err, "host.boundary.%s: expected a group of the mesh other than the "
                                                    "cavity (%s)", h->bc_group[k], names);
    for (int g = 0; !st && g < mesh->n_groups; g++) {
        if (!strcmp(mesh->group_name[g], h->cavity)) continue;
        int found = 0;
        for (int k = 0; k < h->n_bcs; k++) found |= !strcmp(h->bc_group[k], mesh->group_name[g]);
        if (!found)
            st = gb_yaml_fail(m->doc, bc_node && fy_node_mapping_item_count(bc_node) ? bc_node : m->node, err,
                              "host.boundary: no condition for the group '%s'", mesh->group_name[g]);
    }
    return st;
}

/* What run_info.yaml reports of the mesh: elements per group, the cavity's shortest and longest. */
static void mesh_info(gb_host_def *h, const gb_bem_mesh *mesh)
{
    int cavity = gb_bem_mesh_group(mesh, h->cavity);
    h->n_groups = mesh->n_groups;
    h->cavity_min = HUGE_VAL, h->cavity_max = 0;
    for (int g = 0; g < mesh->n_groups; g++) snprintf(h->group[g], GB_BEM_NAME_MAX, "%s", mesh->group_name[g]);
    for (int e = 0; e < mesh->n; e++) {
        h->group_elements[mesh->group[e]]++;
        if (mesh->group[e] != cavity) continue;
        h->cavity_min = fmin(h->cavity_min, mesh->length[e]);
        h->cavity_max = fmax(h->cavity_max, mesh->length[e]);
    }
}

/* host.elements: {group: count, ...} for a .geo (without it, the file's own sizes); a .msh is a
 * mesh already, which gembem reads as gmsh wrote it. */
static gb_status read_counts(gb_ymap *m, gb_host_def *h, gb_error *err)
{
    gb_ymap counts;
    struct fy_node *node;
    gb_status st;
    if ((st = gb_ymap_find(m, "elements", 0, &node, err)) || (st = gb_ymap_map(m, "elements", 0, &counts, err)))
        return st;
    if (node && gb_bem_mesh_file_is_msh(h->mesh) && fy_node_get_type(node) == FYNT_MAPPING && fy_node_mapping_item_count(node) > 0)
        return gb_yaml_fail(m->doc, node, err, "host.elements: %s is a mesh already (gmsh chose its elements); "
                                               "element counts apply to a .geo file, which gembem meshes: remove "
                                               "host.elements or give the .geo", h->mesh);
    void *it = NULL;
    struct fy_node_pair *p;
    while (counts.node && (p = fy_node_mapping_iterate(counts.node, &it))) {
        size_t klen = 0;
        const char *key = fy_node_get_scalar(fy_node_pair_key(p), &klen);
        if (h->mesh_opts.n_group_sizes == GB_BEM_MAX_GROUPS || !key || klen == 0 || klen >= GB_BEM_NAME_MAX)
            return gb_yaml_fail(m->doc, fy_node_pair_key(p), err, "host.elements: expected at most %d group names",
                                GB_BEM_MAX_GROUPS);
        gb_bem_group_size *gs = &h->mesh_opts.group_sizes[h->mesh_opts.n_group_sizes++];
        memcpy(gs->group, key, klen);
        gs->group[klen] = '\0';
        long count = 0;
        if ((st = gb_ymap_int(&counts, gs->group, GB_Y_REQUIRED, 3, GB_BEM_MAX_COUNT, &count, err))) return st;
        gs->count = (int)count;
        h->counts_given = 1;
    }
    return gb_ymap_close(&counts, err);
}

/* host.material: the host's elastic constants. */
static gb_status read_material(gb_ymap *m, gb_host_def *h, gb_error *err)
{
    gb_ymap mat;
    gb_status st;
    char plane[16] = "strain";
    if ((st = gb_ymap_map(m, "material", GB_Y_REQUIRED, &mat, err)) ||
        (st = gb_ymap_number(&mat, "shear_modulus", GB_Y_REQUIRED | GB_Y_POSITIVE, &h->material.shear_modulus, err)) ||
        (st = gb_ymap_number(&mat, "poisson", GB_Y_REQUIRED, &h->material.poisson, err)) ||
        (st = gb_ymap_string(&mat, "plane", 0, plane, sizeof plane, err)))
        return st;
    if (!(h->material.poisson > -1 && h->material.poisson < 0.5))
        return gb_yaml_fail(m->doc, mat.node, err, "host.material.poisson: expected a value in (-1, 0.5)");
    if (!strcmp(plane, "stress")) h->material.plane = GB_BEM_PLANE_STRESS;
    else if (strcmp(plane, "strain"))
        return gb_yaml_fail(m->doc, mat.node, err, "host.material.plane: expected 'strain' or 'stress'");
    return gb_ymap_close(&mat, err);
}

/* host.boundary (bcs: its map, kept open for check_groups). */
static gb_status read_boundary(gb_ymap *m, gb_host_def *h, gb_ymap *bcs, gb_error *err)
{
    gb_status st;
    /* boundary: {group: condition, ...} for every group but the cavity; a condition is the BEM
     * module's (fixed, free, {displacement: [ux, uy]}, {traction: [tx, ty]}, {pressure: p},
     * {normal_displacement: d}, {ux | tx: a, uy | ty: b}) or `displacement` ({displacement: [0, 0]}) */
    if ((st = gb_ymap_map(m, "boundary", 0, bcs, err))) return st;
    void *it = NULL;
    struct fy_node_pair *p;
    while (bcs->node && (p = fy_node_mapping_iterate(bcs->node, &it))) {
        size_t len = 0, vlen = 0;
        const char *key = fy_node_get_scalar(fy_node_pair_key(p), &len);
        struct fy_node *vnode = fy_node_pair_value(p);
        const char *val = fy_node_get_type(vnode) == FYNT_SCALAR ? fy_node_get_scalar(vnode, &vlen) : NULL;
        if (h->n_bcs == GB_HOST_MAX_BCS || !key || len == 0 || len >= GB_BEM_NAME_MAX)
            return gb_yaml_fail(m->doc, fy_node_pair_key(p), err, "host.boundary: expected at most %d group names",
                                GB_HOST_MAX_BCS);
        gb_bem_bc *bc = &h->bc[h->n_bcs];
        memcpy(h->bc_group[h->n_bcs], key, len);
        h->bc_group[h->n_bcs][len] = '\0';
        char path[GB_BEM_NAME_MAX + 32];
        snprintf(path, sizeof path, "host.boundary.%s", h->bc_group[h->n_bcs]);
        int is_map = vnode && fy_node_get_type(vnode) == FYNT_MAPPING;
        if (val && vlen == 12 && !strncmp(val, "displacement", 12)) {
            memset(bc, 0, sizeof *bc);
            bc->kind = GB_BEM_BC_DISPLACEMENT;
        } else if (!is_map && !(val && ((vlen == 5 && !strncmp(val, "fixed", 5)) || (vlen == 4 && !strncmp(val, "free", 4))))) {
            /* an empty value has no position of its own: name its key's */
            return gb_yaml_fail(m->doc, vnode && !(val && vlen == 0) ? vnode : fy_node_pair_key(p), err,
                                "%s: expected fixed, free, displacement (from zero, moved by stages), {displacement: "
                                "[ux, uy]}, {traction: [tx, ty]}, {pressure: p}, {normal_displacement: d} or "
                                "{ux | tx: a, uy | ty: b}", path);
        } else if ((st = gb_bem_bc_read(m->doc, vnode, path, bc, err))) {
            return st;
        }
        h->n_bcs++;
        struct fy_node *v;
        gb_ymap_find(bcs, h->bc_group[h->n_bcs - 1], 0, &v, err); /* mark as read */
    }
    return gb_ymap_close(bcs, err);
}

/* host.unbounded and host.remote_stress. */
static gb_status read_unbounded(gb_ymap *m, gb_host_def *h, gb_error *err)
{
    gb_status st;
    /* an infinite plane with cavities, loaded at infinity */
    struct fy_node *rs;
    if ((st = gb_ymap_bool(m, "unbounded", 0, &h->mesh_opts.unbounded, err)) ||
        (st = gb_ymap_find(m, "remote_stress", 0, &rs, err)) ||
        (st = gb_ymap_vector(m, "remote_stress", 0, 3, h->remote_stress, err)))
        return st;
    if (rs && !h->mesh_opts.unbounded)
        return gb_yaml_fail(m->doc, rs, err, "host.remote_stress: applies to an unbounded host only (host.unbounded: "
                                            "true, a mesh of cavities in an infinite plane)");
    return GB_OK;
}

/* updated_lagrangian: {every: k}, the host following its deformed boundary (docs/hybrid.md). */
static gb_status read_follow(gb_ymap *m, gb_host_def *h, gb_error *err)
{
    gb_ymap ul;
    long every;
    gb_status st = gb_ymap_map(m, "updated_lagrangian", 0, &ul, err);
    if (st || !ul.node) return st;
    if ((st = gb_ymap_int(&ul, "every", GB_Y_REQUIRED, 1, 1000000000, &every, err)) || (st = gb_ymap_close(&ul, err)))
        return st;
    if (h->rigid)
        return gb_yaml_fail(m->doc, ul.node, err, "host.updated_lagrangian: a rigid host's cavity does not move; "
                            "remove one of rigid and updated_lagrangian");
    h->follow_every = (int)every;
    return GB_OK;
}

gb_status gb_host_section_read(gb_ymap *top, gb_host_def *h, gb_bem_mesh *mesh, gb_error *err)
{
    gb_ymap m, bcs;
    gb_status st;
    char name[512];
    memset(h, 0, sizeof *h);
    h->present = 1;
    h->mesh_opts = gb_bem_mesh_opts_default();
    if ((st = gb_ymap_map(top, "host", GB_Y_REQUIRED, &m, err)) ||
        (st = gb_ymap_string(&m, "mesh", GB_Y_REQUIRED, name, sizeof name, err)))
        return st;
    gb_yaml_relative_path(m.doc, name, h->mesh, sizeof h->mesh);
    if ((st = gb_ymap_string(&m, "cavity", GB_Y_REQUIRED, h->cavity, sizeof h->cavity, err)) ||
        (st = gb_ymap_bool(&m, "rigid", 0, &h->rigid, err)))
        return st;

    if ((st = read_counts(&m, h, err)) || (st = read_material(&m, h, err)) || (st = read_boundary(&m, h, &bcs, err)) ||
        (st = read_unbounded(&m, h, err)) || (st = read_follow(&m, h, err)) ||
        (st = gb_ymap_close(&m, err)))
        return st;
    if ((st = gb_bem_mesh_load(h->mesh, &h->mesh_opts, mesh, err))) {
        if (st != GB_EINPUT) return st;
        char msg[GB_ERROR_MSG_MAX]; /* the mesh's own message, at the scene's host.mesh */
        snprintf(msg, sizeof msg, "%s", err->msg);
        struct fy_node *v;
        gb_ymap_find(&m, "mesh", 0, &v, err);
        return gb_yaml_fail(m.doc, v, err, "host.mesh: %s", msg);
    }
    if ((st = check_groups(&m, bcs.node, h, mesh, err))) {
        gb_bem_mesh_free(mesh);
        return st;
    }
    mesh_info(h, mesh);
    return GB_OK;
}
