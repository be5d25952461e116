/* The granular scene file: see validation/three_discs/case1.yaml for a commented example. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gembem/scene.h"
#include "scene/admit.h"
#include "scene/grains_file.h"
#include "scene/host_read.h"
#include "scene/scene_pack.h"
#include "scene/solver_read.h"
#include "scene/state_read.h"
#include "scene/yaml_read.h"


void gb_scene_free(gb_scene *s)
{
    if (!s) return;
    free(s->grains);
    free(s->grain_line);
    free(s->grain_col);
    free(s->restart.contacts);
    free(s->stages);
    free(s->snapshot_steps);
    free(s->restart.host.u);
    free(s->restart.host.xy);
    memset(s, 0, sizeof *s);
}

int gb_scene_total_steps(const gb_scene *s)
{
    int n = 0;
    for (int k = 0; k < s->n_stages; k++) n += s->stages[k].steps;
    return n;
}

static gb_status read_material(gb_ymap *parent, const char *key, gb_material *mat, gb_error *err)
{
    gb_ymap m;
    gb_status st;
    mat->cohesion = 0;
    mat->kr = mat->eta = 0;
    if ((st = gb_ymap_map(parent, key, GB_Y_REQUIRED, &m, err)) ||
        (st = gb_ymap_number(&m, "kn", GB_Y_REQUIRED | GB_Y_POSITIVE, &mat->kn, err)) ||
        (st = gb_ymap_number(&m, "kt", GB_Y_REQUIRED | GB_Y_NONNEG, &mat->kt, err)) ||
        (st = gb_ymap_number(&m, "friction_deg", GB_Y_REQUIRED | GB_Y_NONNEG, &mat->friction_deg, err)) ||
        (st = gb_ymap_number(&m, "cohesion", GB_Y_NONNEG, &mat->cohesion, err)))
        return st;
    if (!(mat->friction_deg < 90)) {
        struct fy_node *v;
        gb_ymap_find(&m, "friction_deg", 0, &v, err);
        return gb_yaml_fail(m.doc, v, err, "%s.friction_deg: expected an angle from 0 to below 90 degrees, found "
                            "%g; for a friction coefficient mu give atan(mu) in degrees (mu 0.5: 26.6)", m.name,
                            mat->friction_deg);
    }
    struct fy_node *rolling;
    if ((st = gb_ymap_find(&m, "rolling", 0, &rolling, err))) return st;
    if (rolling) {
        /* Boundary particles do not rotate and pass no moment to the host. */
        if (!strcmp(key, "grain_boundary"))
            return gb_yaml_fail(m.doc, rolling, err, "%s.rolling: boundary particles carry no moment; give rolling "
                                "resistance in grain_grain and grain_wall only", m.name);
        gb_ymap r;
        if ((st = gb_ymap_map(&m, "rolling", 0, &r, err)) ||
            (st = gb_ymap_number(&r, "kr", GB_Y_REQUIRED | GB_Y_POSITIVE, &mat->kr, err)) ||
            (st = gb_ymap_number(&r, "eta", GB_Y_REQUIRED | GB_Y_POSITIVE, &mat->eta, err)) ||
            (st = gb_ymap_close(&r, err)))
            return st;
    }
    return gb_ymap_close(&m, err);
}

static gb_status read_body_force(gb_ymap *top, gb_scene *s, gb_error *err)
{
    gb_ymap m;
    gb_status st;
    if ((st = gb_ymap_map(top, "body_force", 0, &m, err))) return st;
    double w = -1, g[2] = {0, 0}, rho = -1;
    struct fy_node *gv;
    if ((st = gb_ymap_number(&m, "weight_per_area", GB_Y_NONNEG, &w, err)) ||
        (st = gb_ymap_find(&m, "gravity", 0, &gv, err)) || (st = gb_ymap_vector(&m, "gravity", 0, 2, g, err)) ||
        (st = gb_ymap_number(&m, "density", GB_Y_POSITIVE, &rho, err)) || (st = gb_ymap_close(&m, err)))
        return st;
    if (w >= 0 && (gv || rho >= 0))
        return gb_yaml_fail(m.doc, m.node, err, "body_force: give either weight_per_area (downwards) or gravity "
                                                "and density, not both");
    if (!gv != !(rho >= 0))
        return gb_yaml_fail(m.doc, m.node, err, "body_force: gravity [gx, gy] and density go together");
    if (w >= 0) {
        s->body_force_per_area[0] = 0;
        s->body_force_per_area[1] = -w;
    } else if (gv) {
        s->body_force_per_area[0] = rho * g[0];
        s->body_force_per_area[1] = rho * g[1];
    }
    return GB_OK;
}

/* A relative accuracy needs a force to be relative to at the first step: a contact force of the
 * initial state, or a body force or stress target of the first stage (src/gem/accuracy.c). */
/* Where an error about solver.accuracy points: the key, else the solver section, else the top. */
static struct fy_node *accuracy_node(gb_ymap *top, gb_error *err)
{
    struct fy_node *v = NULL, *sv = NULL;
    gb_ymap_find(top, "solver", 0, &sv, err);
    if (sv) v = fy_node_mapping_lookup_by_string(sv, "accuracy", FY_NT);
    return v ? v : sv ? sv : top->node;
}

static gb_status check_force_scale(const gb_yaml_doc *doc, gb_ymap *top, const gb_scene *s, gb_error *err)
{
    const gb_overlaps *o = &s->overlaps;
    if (!(s->solver.accuracy_relative > 0) || o->grain_pairs || o->boundary || o->particles ||
        gb_scene_load_force(s, 0) > 0)
        return GB_OK;
    return gb_yaml_fail(doc, accuracy_node(top, err), err,
                        "solver.accuracy: %s relative accuracy has no force scale at the first step: no grain "
                        "touches another or a boundary, there is no body force and the first stage imposes no "
                        "stress; expected an absolute accuracy (a force, e.g. 'accuracy: 1e-3')",
                        s->solver.accuracy_default ? "without solver.accuracy, the default" : "a");
}

/* A packing's relaxations stop at a force, fixed before the grains exist: a relative accuracy has
 * no scale yet (its scale, the contacts' mean force, is what the packing makes). */
static gb_status check_pack_accuracy(const gb_yaml_doc *doc, gb_ymap *top, const gb_scene *s, gb_error *err)
{
    if (!(s->solver.accuracy_relative > 0)) return GB_OK;
    return gb_yaml_fail(doc, accuracy_node(top, err), err,
                        "solver.accuracy: %s; a pack scene needs an absolute accuracy (a force, e.g. 1e-6 times kn "
                        "times the mean radius: %g x the mean radius here), since the force scale of a relative one "
                        "is the contact forces that the packing makes",
                        s->solver.accuracy_default ? "missing" : "a relative accuracy", 1e-6 * s->grain_grain.kn);
}

/* The increments per step of a host stage: `increments: {group: [a, b] | p, ...}` add to the values
 * of each group's condition as host.boundary gives them (displacement or traction components, or
 * one number for a pressure or normal displacement); host_load also takes `remote_stress: [dsxx,
 * dsyy, dsxy]` (unbounded hosts). host_displacement moves 'displacement' groups only. */
static gb_status read_host_increments(gb_ymap *m, const char *sub, const gb_host_def *host, gb_stage *sg,
                                      gb_error *err)
{
    int disp_only = sg->kind == GB_STAGE_HOST_DISPLACEMENT;
    gb_ymap inc;
    struct fy_node *incn, *rs = NULL;
    gb_status st;
    if (!host->present) return gb_yaml_fail(m->doc, m->node, err, "%s: expected a scene with a host", sub);
    if ((st = gb_ymap_find(m, "increments", disp_only ? GB_Y_REQUIRED : 0, &incn, err)) ||
        (st = gb_ymap_map(m, "increments", disp_only ? GB_Y_REQUIRED : 0, &inc, err)))
        return st;
    if (!disp_only && ((st = gb_ymap_find(m, "remote_stress", 0, &rs, err)) ||
                       (st = gb_ymap_vector(m, "remote_stress", 0, 3, sg->host_remote_increment, err))))
        return st;
    if (!incn && !rs)
        return gb_yaml_fail(m->doc, m->node, err, "%s: expected increments per step: increments: {group: [a, b] | p} "
                                                  "and/or remote_stress: [sxx, syy, sxy]", sub);
    if (rs && !host->mesh_opts.unbounded)
        return gb_yaml_fail(m->doc, rs, err, "%s.remote_stress: the host is bounded; a remote stress applies to an "
                                             "unbounded host only (host.unbounded: true)", sub);
    void *it = NULL;
    struct fy_node_pair *pr;
    while (inc.node && (pr = fy_node_mapping_iterate(inc.node, &it))) {
        size_t gl = 0;
        const char *gname = fy_node_get_scalar(fy_node_pair_key(pr), &gl);
        int ok = -1;
        for (int q = 0; gname && q < host->n_bcs; q++)
            if (strlen(host->bc_group[q]) == gl && !strncmp(host->bc_group[q], gname, gl)) ok = q;
        if (disp_only && (ok < 0 || host->bc[ok].kind != GB_BEM_BC_DISPLACEMENT))
            return gb_yaml_fail(m->doc, fy_node_pair_key(pr), err, "%s.increments: expected groups of the host with "
                                "'displacement' in host.boundary, found '%.*s'", sub, (int)gl, gname ? gname : "");
        if (ok < 0)
            return gb_yaml_fail(m->doc, fy_node_pair_key(pr), err, "%s.increments: host.boundary has no group '%.*s'",
                                sub, (int)gl, gname ? gname : "");
        if (gb_bem_bc_n_values(&host->bc[ok]) == 0)
            return gb_yaml_fail(m->doc, fy_node_pair_key(pr), err,
                                "%s.increments.%s: the group is %s in host.boundary and has no value to load; "
                                "expected a group with a displacement, traction, pressure, normal_displacement or "
                                "component-wise condition",
                                sub, host->bc_group[ok], host->bc[ok].kind == GB_BEM_BC_FIXED ? "fixed" : "free");
        int q = sg->n_host_groups++;
        snprintf(sg->host_group[q], GB_BEM_NAME_MAX, "%s", host->bc_group[ok]);
        if (gb_bem_bc_n_values(&host->bc[ok]) == 1)
            st = gb_ymap_number(&inc, sg->host_group[q], GB_Y_REQUIRED, &sg->host_increment[q][0], err);
        else
            st = gb_ymap_vector(&inc, sg->host_group[q], GB_Y_REQUIRED, 2, sg->host_increment[q], err);
        if (st) return st;
    }
    return gb_ymap_close(&inc, err);
}

/* A stage's target stress on the walls: compression positive, as the strains. */
static gb_status read_stress(gb_ymap *m, const char *key, double *out, gb_error *err)
{
    gb_status st = gb_ymap_number(m, key, GB_Y_REQUIRED, out, err);
    if (st || *out > 0) return st;
    struct fy_node *v;
    gb_ymap_find(m, key, 0, &v, err);
    return gb_yaml_fail(m->doc, v, err, "%s.%s: expected a positive stress (compression is positive in gembem), "
                        "found %g%s", m->name, key, *out, *out < 0 ? ": drop the minus sign" : "");
}

static gb_status read_stage(const gb_yaml_doc *doc, struct fy_node *item, int k, const gb_host_def *host, gb_stage *sg,
                            gb_error *err)
{
    char name[64];
    snprintf(name, sizeof name, "loading[%d]", k);
    if (fy_node_get_type(item) != FYNT_MAPPING || fy_node_mapping_item_count(item) != 1)
        return gb_yaml_fail(doc, item, err, "%s: expected one stage, e.g. '- isotropic: {stress: 1.5e6, steps: 20}'",
                            name);
    void *it = NULL;
    struct fy_node_pair *p = fy_node_mapping_iterate(item, &it);
    size_t len = 0;
    const char *kind = fy_node_get_scalar(fy_node_pair_key(p), &len);
    const char *kinds[GB_STAGE_KINDS];
    int kk = -1;
    for (int q = 0; q < GB_STAGE_KINDS; q++) {
        kinds[q] = gb_stage_name((gb_stage_kind)q);
        if (kind && strlen(kinds[q]) == len && !strncmp(kinds[q], kind, len)) kk = q;
    }
    if (kk < 0) {
        int near = gb_yaml_closest(kind, len, kinds, GB_STAGE_KINDS);
        char hint[64] = "";
        if (near >= 0) snprintf(hint, sizeof hint, " did you mean '%s'?", kinds[near]);
        return gb_yaml_fail(doc, fy_node_pair_key(p), err,
                            "%s: unknown stage '%.*s';%s expected isotropic, strain, shear_mean_stress, biaxial_stress, "
                            "relax, host_displacement or host_load",
                            name, (int)len, kind ? kind : "", hint);
    }
    gb_ymap m;
    gb_status st;
    char sub[96];
    snprintf(sub, sizeof sub, "%s.%s", name, kinds[kk]);
    if ((st = gb_ymap_open(doc, fy_node_pair_value(p), sub, &m, err))) return st;
    memset(sg, 0, sizeof *sg);
    long steps = 0;
    if ((st = gb_ymap_int(&m, "steps", GB_Y_REQUIRED, 1, 100000000L, &steps, err)) ||
        (st = gb_ymap_bool(&m, "reset_strain", 0, &sg->reset_strain, err)))
        return st;
    sg->steps = (int)steps;
    sg->kind = (gb_stage_kind)kk;
    switch (sg->kind) {
    case GB_STAGE_ISOTROPIC: st = read_stress(&m, "stress", &sg->stress, err); break;
    case GB_STAGE_STRAIN:
        if (!(st = gb_ymap_number(&m, "de1", GB_Y_REQUIRED, &sg->de1, err)))
            st = gb_ymap_number(&m, "de2", GB_Y_REQUIRED, &sg->de2, err);
        break;
    case GB_STAGE_SHEAR_MEAN:
        if (!(st = gb_ymap_number(&m, "d_e1_minus_e2", GB_Y_REQUIRED, &sg->d_shear, err)))
            st = read_stress(&m, "mean_stress", &sg->mean_stress, err);
        break;
    case GB_STAGE_BIAXIAL_STRESS:
        if (!(st = read_stress(&m, "s1", &sg->s1, err))) st = read_stress(&m, "s2", &sg->s2, err);
        break;
    case GB_STAGE_HOST_DISPLACEMENT:
    case GB_STAGE_HOST_LOAD: st = read_host_increments(&m, sub, host, sg, err); break;
    case GB_STAGE_RELAX: break;
    }
    if (st) return st;
    if ((sg->kind == GB_STAGE_HOST_DISPLACEMENT || sg->kind == GB_STAGE_HOST_LOAD) && !host->present)
        return gb_yaml_fail(doc, m.node, err, "%s: expected a scene with a host", sub);
    /* A strain increment of a whole side or more per step would turn the box inside out. */
    double worst = fmax(fabs(sg->de1), fmax(fabs(sg->de2), fabs(sg->d_shear)));
    if (!(worst < 0.5))
        return gb_yaml_fail(doc, m.node, err, "%s: expected strain increments per step below 0.5", sub);
    return gb_ymap_close(&m, err);
}

static gb_status read_loading(gb_ymap *top, gb_scene *s, gb_error *err)
{
    struct fy_node *list;
    gb_status st = gb_ymap_find(top, "loading", GB_Y_REQUIRED, &list, err);
    if (st) return st;
    if (fy_node_get_type(list) != FYNT_SEQUENCE || fy_node_sequence_item_count(list) < 1)
        return gb_yaml_fail(top->doc, list, err, "loading: expected a list of stages");
    int n = fy_node_sequence_item_count(list);
    if (!(s->stages = calloc((size_t)n, sizeof *s->stages))) return gb_fail(err, GB_ENOMEM, "out of memory");
    for (int k = 0; k < n; k++) {
        if ((st = read_stage(top->doc, fy_node_sequence_get_by_index(list, k), k, &s->host, &s->stages[k], err)))
            return st;
        s->n_stages++;
    }
    return GB_OK;
}

static gb_status read_output(gb_ymap *top, gb_scene *s, gb_error *err)
{
    gb_ymap m;
    gb_status st;
    long every = 0;
    struct fy_node *list;
    if ((st = gb_ymap_map(top, "output", 0, &m, err)) ||
        (st = gb_ymap_int(&m, "snapshot_every", 0, 0, 100000000L, &every, err)) ||
        (st = gb_ymap_find(&m, "snapshot_steps", 0, &list, err)))
        return st;
    s->snapshot_every = (int)every;
    long contacts_every = 0;
    if ((st = gb_ymap_int(&m, "contacts_every", 0, 0, 100000000L, &contacts_every, err))) return st;
    s->contacts_every = (int)contacts_every;
    /* fields/ of the per-step measures: every step for small scenes, off for large ones (about 600
     * bytes per grain and step) unless the scene says */
    struct fy_node *me;
    long measures_every = s->n_grains < GB_MEASURES_DEFAULT_GRAINS ? s->measures_every : 0;
    if ((st = gb_ymap_find(&m, "measures_every", 0, &me, err)) ||
        (st = gb_ymap_int(&m, "measures_every", 0, 0, 100000000L, &measures_every, err)))
        return st;
    s->measures_every = (int)measures_every;
    s->measures_every_given = me != NULL;
    /* localisation.csv's row: a triangulation and D2min of every grain at every step (about an
     * eighth of the time of a 1e4-disc loading path) */
    if ((st = gb_ymap_bool(&m, "localisation", 0, &s->localisation, err))) return st;
    /* checkpoints (src/io/checkpoint.c): after every step unless the scene says otherwise */
    long ck_every = s->checkpoint_every;
    double ck_minutes = s->checkpoint_minutes;
    if ((st = gb_ymap_int(&m, "checkpoint_every", 0, 0, 100000000L, &ck_every, err)) ||
        (st = gb_ymap_number(&m, "checkpoint_minutes", GB_Y_POSITIVE, &ck_minutes, err)))
        return st;
    s->checkpoint_every = (int)ck_every;
    s->checkpoint_minutes = ck_minutes;
    if (list) {
        int total = gb_scene_total_steps(s);
        if (fy_node_get_type(list) != FYNT_SEQUENCE)
            return gb_yaml_fail(m.doc, list, err, "output.snapshot_steps: expected a list of step numbers");
        int n = fy_node_sequence_item_count(list);
        if (!(s->snapshot_steps = calloc((size_t)(n > 0 ? n : 1), sizeof(int)))) return gb_fail(err, GB_ENOMEM, "oom");
        for (int k = 0; k < n; k++) {
            struct fy_node *v = fy_node_sequence_get_by_index(list, k);
            double x;
            if ((st = gb_yaml_number(m.doc, v, "output.snapshot_steps", &x, err))) return st;
            if (x != floor(x) || x < 0 || x > total)
                return gb_yaml_fail(m.doc, v, err, "output.snapshot_steps: expected step numbers from 0 to %d", total);
            s->snapshot_steps[s->n_snapshot_steps++] = (int)x;
        }
    }
    return gb_ymap_close(&m, err);
}

/* A state written by a previous run: its box, grains and contact forces. */
static gb_status read_initial_state(gb_ymap *top, gb_scene *s, gb_error *err)
{
    char name[512], path[1024];
    gb_status st = gb_ymap_string(top, "initial_state", GB_Y_REQUIRED, name, sizeof name, err);
    if (st) return st;
    gb_yaml_relative_path(top->doc, name, path, sizeof path);
    gb_yaml_doc doc;
    if ((st = gb_yaml_load(path, &doc, err))) return st;
    gb_ymap m, g;
    double version = 0;
    if (!(st = gb_ymap_open(&doc, fy_document_root(doc.fyd), "", &m, err)) &&
        !(st = gb_ymap_number(&m, "gembem_state", GB_Y_REQUIRED, &version, err)) &&
        !(st = gb_box_read(&m, &s->box, err)) && !(st = gb_state_host_presence(&m, s, err)) &&
        !(st = gb_ymap_map(&m, "grains", GB_Y_REQUIRED, &g, err)) &&
        !(st = gb_grains_section_read(&g, s, err)) && !(st = gb_state_host_read(&m, s, err)) &&
        !(st = gb_state_solver_read(&m, s, err)) && !(st = gb_ymap_close(&m, err)) && version != 1)
        st = gb_yaml_fail(&doc, m.node, err, "gembem_state: expected version 1");
    /* With a host the box only bounds the grains for reports (kept as the run had it); the
     * simulation checks that every grain lies in the cavity. */
    if (!st && !s->host.present) st = gb_grains_check(s, doc.path, err);
    gb_yaml_free(&doc);
    return st;
}

/* A pack scene's region: a box or a host, one of them (no grains yet, nothing to admit). */
static gb_status read_region(gb_ymap *top, gb_scene *s, gb_bem_mesh *mesh, gb_error *err)
{
    struct fy_node *host, *box;
    gb_status st;
    if ((st = gb_ymap_find(top, "host", 0, &host, err)) || (st = gb_ymap_find(top, "box", 0, &box, err))) return st;
    if (host && box)
        return gb_yaml_fail(top->doc, host, err, "host: a scene has either a box of walls or a host, not both");
    if (!host && !box)
        return gb_yaml_fail(top->doc, top->node, err, "expected the region to fill: box: {left, right, bottom, top} "
                                                      "or host: (a cavity)");
    return host ? gb_host_section_read(top, &s->host, mesh, err) : gb_box_read(top, &s->box, err);
}

/* The scene's node at a path such as "/solver/accuracy", for a message's line and column. */
static struct fy_node *node_at(const gb_yaml_doc *doc, const char *path)
{
    return fy_node_by_path(fy_document_root(doc->fyd), path, FY_NT, FYNWF_DONT_FOLLOW);
}

/* An accuracy that doubles cannot reach for these springs and coordinates is refused, not
 * iterated for hours (a force given in the scene: 0 is an accuracy not known before the run). */
static gb_status check_accuracy(const gb_yaml_doc *doc, const gb_scene *s, gb_error *err)
{
    double kn, x, res = gb_scene_force_resolution(s, &kn, &x), a = s->solver.accuracy;
    if (!(a > 0 && a < GB_RESOLUTION_REFUSED * res)) return GB_OK;
    return gb_yaml_fail(doc, node_at(doc, "/solver/accuracy"), err,
                        "solver.accuracy: %g is below what doubles resolve for these springs and coordinates: the "
                        "fixing forces stall near kn eps |x|max = %.3g (kn %g, |x|max %g); give solver.accuracy: %g "
                        "or more", a, res, kn, x, gb_scene_suggested_accuracy(res));
}

/* A spring's force over an overlap of the largest radius is bounded as every force is
 * (GB_FORCE_MAX, src/scene/admit.h): kn = 1e300 makes the first contact's energy kn d^2 / 2
 * infinite. */
static gb_status check_stiffness(const gb_yaml_doc *doc, const gb_scene *s, gb_error *err)
{
    double rmax = 0;
    for (int i = 0; i < s->n_grains; i++) rmax = fmax(rmax, s->grains[i].r);
    const char *names[2] = {"grain_grain", s->host.present ? "grain_boundary" : "grain_wall"};
    const gb_material *mats[2] = {&s->grain_grain, s->host.present ? &s->grain_boundary : &s->grain_wall};
    for (int k = 0; k < 2; k++) {
        const char *key[2] = {"kn", "kt"};
        double v[2] = {mats[k]->kn, mats[k]->kt};
        for (int q = 0; q < 2; q++) {
            if (v[q] * rmax <= GB_FORCE_MAX) continue;
            char where[64];
            snprintf(where, sizeof where, "/materials/%s/%s", names[k], key[q]);
            return gb_yaml_fail(doc, node_at(doc, where), err,
                                "materials.%s.%s: %g makes a force of %.3g over the largest radius %g; expected %s "
                                "times the largest radius at most 1e145 (%s: %.3g), as every force: a run squares "
                                "forces and sums them over the grains, and beyond it goes non-finite; check its "
                                "units (%s/%s)", names[k], key[q], v[q], v[q] * rmax, rmax, key[q], key[q],
                                GB_FORCE_MAX / rmax, s->force_unit, s->length_unit);
        }
    }
    return GB_OK;
}

/* A contact under a wall stress sigma (force per length of wall) carries about sigma times a
 * diameter and overlaps by about 2 sigma / kn of a radius, whatever the size. Above a radius the
 * grains would pass through each other: kn or the stress is in another unit (kn in N/m in a cm
 * and dyn scene is 1000 times too soft). Above 0.1 of a radius the small-overlap springs are
 * stretched: warned. */
static gb_status check_springs(const gb_yaml_doc *doc, gb_scene *s, gb_error *err)
{
    if (s->host.present) return GB_OK; /* no wall stress: the host's loads are displacements and tractions */
    int soft_wall = s->grain_wall.kn < s->grain_grain.kn;
    double kn = soft_wall ? s->grain_wall.kn : s->grain_grain.kn;
    const char *name = soft_wall ? "grain_wall" : "grain_grain";
    for (int k = 0; k < s->n_stages; k++) {
        const gb_stage *sg = &s->stages[k];
        double sigma = fmax(fmax(sg->stress, sg->mean_stress), fmax(sg->s1, sg->s2)), share = 2 * sigma / kn;
        if (!(share > 0.1)) continue;
        char where[64];
        snprintf(where, sizeof where, "/materials/%s/kn", name);
        const char *what = "a contact overlaps by about 2 stress / kn";
        if (share > 1)
            return gb_yaml_fail(doc, node_at(doc, where), err,
                                "materials.%s.kn: %g is soft against loading[%d]'s stress %g: %s = %.3g radii, "
                                "through the grains; check the units of kn (%s/%s) and of the stress (%s per %s of "
                                "wall); a kn of %g or more keeps overlaps below 1 %% of a radius", name, kn, k, sigma,
                                what, share, s->force_unit, s->length_unit, s->force_unit, s->length_unit, 200 * sigma);
        gb_scene_warn(s, "materials.%s.kn %g is soft against loading[%d]'s stress %g: %s = %.2g of a radius, beyond "
                      "the small overlaps the springs stand for; a kn of %g or more keeps them below 1 %% (check its "
                      "units: %s/%s)", name, kn, k, sigma, what, share, 200 * sigma, s->force_unit, s->length_unit);
        break; /* one warning for the scene */
    }
    return GB_OK;
}

/* mesh: the host's, as the scene's check meshed it (the caller frees it). read_pack: a pack scene
 * (src/scene/scene_pack.h), else a run scene. */
/* materials: grain_grain, grain_wall and (optional) grain_boundary. */
static gb_status read_materials(gb_ymap *top, gb_scene *s, gb_error *err)
{
    gb_ymap mats;
    gb_status st;
    if ((st = gb_ymap_map(top, "materials", GB_Y_REQUIRED, &mats, err)) ||
        (st = read_material(&mats, "grain_grain", &s->grain_grain, err)) ||
        (st = read_material(&mats, "grain_wall", &s->grain_wall, err)))
        return st;
    /* Grains against boundary particles: normal springs only unless the scene says otherwise
     * (the hybrid paper's Table 1). */
    gb_material gbm = {s->grain_grain.kn, 0, 0, 0, 0, 0};
    s->grain_boundary = gbm;
    struct fy_node *gbn;
    if ((st = gb_ymap_find(&mats, "grain_boundary", 0, &gbn, err))) return st;
    if (gbn && (st = read_material(&mats, "grain_boundary", &s->grain_boundary, err))) return st;
    return gb_ymap_close(&mats, err);
}

/* The grains and what holds them: an initial_state (its grains and box; with a host, the scene's
 * host), or grains with a box of walls or a host (whose grains' extent is the box of the reports). */
static gb_status read_grains_and_walls(const gb_yaml_doc *doc, gb_ymap *top, gb_scene *s, gb_bem_mesh *mesh,
                                       gb_error *err)
{
    gb_status st;
    struct fy_node *state = NULL, *grains = NULL, *host, *box;
    if ((st = gb_ymap_find(top, "initial_state", 0, &state, err)) ||
        (st = gb_ymap_find(top, "grains", 0, &grains, err)))
        return st;
    if (state) {
        gb_ymap_find(top, "box", 0, &box, err);
        if ((st = gb_ymap_find(top, "host", 0, &host, err))) return st;
        if (grains || box)
            return gb_yaml_fail(doc, state, err, "initial_state: gives the grains and the box; do not also give "
                                                 "'grains' or 'box'");
        /* a hybrid state: the scene gives the host, the state where it was */
        if (host && (st = gb_host_section_read(top, &s->host, mesh, err))) return st;
        return read_initial_state(top, s, err);
    }
    gb_ymap g;
    if ((st = gb_ymap_find(top, "host", 0, &host, err)) || (st = gb_ymap_find(top, "box", 0, &box, err))) return st;
    if (host && box) return gb_yaml_fail(doc, host, err, "host: a scene has either a box of walls or a host, not both");
    if ((st = gb_ymap_map(top, "grains", GB_Y_REQUIRED, &g, err)) || (st = gb_grains_section_read(&g, s, err)))
        return st;
    if (!host) return (st = gb_box_read(top, &s->box, err)) ? st : gb_grains_check(s, doc->path, err);
    if ((st = gb_host_section_read(top, &s->host, mesh, err))) return st;
    /* The box only bounds the grains for reports; the host's cavity holds them. */
    s->box.left = s->box.bottom = HUGE_VAL;
    s->box.right = s->box.top = -HUGE_VAL;
    for (int i = 0; i < s->n_grains; i++) {
        const gb_grain *q = &s->grains[i];
        s->box.left = fmin(s->box.left, q->x - q->r), s->box.right = fmax(s->box.right, q->x + q->r);
        s->box.bottom = fmin(s->box.bottom, q->y - q->r), s->box.top = fmax(s->box.top, q->y + q->r);
    }
    if (s->restart.n_contacts)
        return gb_yaml_fail(doc, host, err, "host: initial contact forces are not supported with a host yet");
    return GB_OK;
}

/* A scene with a host: the global solver, and stages that load the host, not walls. */
static gb_status check_host_loading(const gb_yaml_doc *doc, gb_ymap *top, const gb_scene *s, gb_error *err)
{
    struct fy_node *sv;
    gb_ymap_find(top, "solver", 0, &sv, err);
    if (s->solver.method != GB_METHOD_GLOBAL)
        return gb_yaml_fail(doc, sv, err, "solver.method: a scene with a host needs 'global' (one system for "
                                          "grains and host)");
    for (int k = 0; k < s->n_stages; k++)
        if (s->stages[k].kind != GB_STAGE_RELAX && s->stages[k].kind != GB_STAGE_HOST_DISPLACEMENT &&
            s->stages[k].kind != GB_STAGE_HOST_LOAD)
            return gb_yaml_fail(doc, sv, err, "loading[%d]: a scene with a host has no walls; expected 'relax', "
                                              "'host_displacement' or 'host_load'", k);
    return GB_OK;
}

static gb_status load(const gb_yaml_doc *doc, gb_scene *s, gb_bem_mesh *mesh, gb_scene_section_fn read_pack,
                      void *user, gb_error *err)
{
    gb_ymap top;
    gb_status st;
    double version = 0;
    if ((st = gb_ymap_open(doc, fy_document_root(doc->fyd), "", &top, err)) ||
        (st = gb_ymap_number(&top, "gembem", GB_Y_REQUIRED, &version, err)))
        return st;
    if (version != 1) return gb_yaml_fail(doc, top.node, err, "gembem: expected scene format version 1");
    if ((st = gb_ymap_units(&top, s->length_unit, s->force_unit, sizeof s->length_unit, err)) ||
        (st = read_materials(&top, s, err)))
        return st;
    if ((st = read_pack ? read_region(&top, s, mesh, err) : read_grains_and_walls(doc, &top, s, mesh, err))) return st;
    if ((st = read_body_force(&top, s, err)) || (st = gb_solver_section_read(&top, &s->solver, err))) return st;
    if (read_pack ? (st = read_pack(&top, s, s->host.present ? mesh : NULL, user, err))
                  : ((st = read_loading(&top, s, err)) || (st = read_output(&top, s, err))))
        return st;
    if (s->host.present && (st = check_host_loading(doc, &top, s, err))) return st;
    if ((st = gb_ymap_close(&top, err))) return st;
    if (read_pack) return check_pack_accuracy(doc, &top, s, err);
    if ((st = gb_scene_admit(s, s->host.present ? mesh : NULL, err)) || (st = check_stiffness(doc, s, err)) ||
        (st = check_springs(doc, s, err)) ||
        (st = check_accuracy(doc, s, err)))
        return st;
    return check_force_scale(doc, &top, s, err);
}

size_t gb_scene_sizeof(void) { return sizeof(gb_scene); }

gb_scene gb_scene_default(void)
{
    gb_scene s;
    memset(&s, 0, sizeof s);
    s.solver = gb_solver_defaults();
    s.max_overlap = GB_MAX_OVERLAP_DEFAULT;
    s.measures_every = GB_MEASURES_DEFAULT_EVERY;
    s.localisation = 1;
    s.checkpoint_every = GB_CHECKPOINT_EVERY_DEFAULT;
    s.checkpoint_minutes = GB_CHECKPOINT_MINUTES_DEFAULT;
    return s;
}

/* A scene file (or, text not NULL, len bytes of YAML named `path`) into out (from
 * gb_scene_default) and its host's mesh into *mesh; on failure both are freed. */
static gb_status load_file(const char *path, const char *text, size_t len, gb_scene *out, gb_bem_mesh *mesh,
                           gb_scene_section_fn read_pack, void *user, gb_error *err)
{
    *out = gb_scene_default();
    memset(mesh, 0, sizeof *mesh);
    snprintf(out->path, sizeof out->path, "%s", path);
    gb_yaml_doc doc;
    gb_status st = text ? gb_yaml_load_text(text, len, path, &doc, err) : gb_yaml_load(path, &doc, err);
    if (st) return st;
    st = load(&doc, out, mesh, read_pack, user, err);
    gb_yaml_free(&doc);
    if (st) {
        gb_bem_mesh_free(mesh);
        gb_scene_free(out);
    }
    return st;
}

gb_status gb_scene_load(const char *path, gb_scene *out, gb_error *err)
{
    gb_bem_mesh mesh;
    gb_status st = load_file(path, NULL, 0, out, &mesh, NULL, NULL, err);
    if (!st) gb_bem_mesh_free(&mesh);
    return st;
}

gb_status gb_scene_load_text(const char *text, size_t len, const char *path, gb_scene *out, gb_error *err)
{
    gb_bem_mesh mesh;
    gb_status st = load_file(path, text, len, out, &mesh, NULL, NULL, err);
    if (!st) gb_bem_mesh_free(&mesh);
    return st;
}

gb_status gb_scene_load_pack(const char *path, gb_scene *out, gb_bem_mesh *mesh, gb_scene_section_fn read_pack,
                             void *user, gb_error *err)
{
    return load_file(path, NULL, 0, out, mesh, read_pack, user, err);
}
