/* The parts of a state file (`initial_state:`) beyond box and grains: the host of a hybrid run
 * and the global solver's damping. The host is checked against the scene's own mesh and
 * conditions: the same element counts, every group with the same kind of condition, each boundary
 * particle on its element's midpoint plus its displacement. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/bem_scene_read.h"
#include "scene/csv_read.h"
#include "scene/state_read.h"

static const char *bc_kind_name(const gb_bem_bc *bc)
{
    switch (bc->kind) {
    case GB_BEM_BC_FIXED: return "fixed";
    case GB_BEM_BC_FREE: return "free";
    case GB_BEM_BC_DISPLACEMENT: return "displacement";
    case GB_BEM_BC_TRACTION: return "traction";
    case GB_BEM_BC_PRESSURE: return "pressure";
    case GB_BEM_BC_NORMAL_DISPLACEMENT: return "normal_displacement";
    case GB_BEM_BC_COMPONENTS: return "component-wise";
    default: return "none";
    }
}

/* state_host.csv: element, x, y (the particle's centre), ux, uy per cavity element, in mesh order. */
static gb_status read_particles(const char *path, const gb_bem_mesh *mesh, int cavity, gb_host_state *hs,
                                gb_error *err)
{
    gb_csv csv;
    gb_status st = gb_csv_open(path, &csv, err);
    if (st) return st;
    static const char *const names[5] = {"element", "x", "y", "ux", "uy"};
    int col[5];
    for (int c = 0; c < 5; c++)
        if ((col[c] = gb_csv_column(&csv, names[c])) < 0 && !st)
            st = gb_fail(err, GB_EINPUT, "%s:1: the header must name the columns element, x, y, ux, uy", path);
    int k = 0, e = -1;
    for (int has = 1; !st;) {
        if ((st = gb_csv_next(&csv, &has, err)) || !has) break;
        double v[5];
        for (int c = 0; c < 5 && !st; c++) st = gb_csv_number(&csv, col[c], &v[c], err);
        if (st) break;
        for (e++; e < mesh->n && mesh->group[e] != cavity; e++) {}
        if (k == hs->n_cavity || e >= mesh->n) {
            st = gb_csv_fail(&csv, col[0], err, "no more rows than the cavity's elements");
            break;
        }
        if (v[0] != e) {
            char what[128];
            snprintf(what, sizeof what, "element %d, the cavity's element %d of the scene's mesh", e, k);
            st = gb_csv_fail(&csv, col[0], err, what);
            break;
        }
        /* the particle rides on its element: a different mesh puts it elsewhere */
        double tol = 1e-6 * mesh->length[e];
        for (int c = 0; c < 2 && !st; c++)
            if (!(fabs(v[1 + c] - (mesh->mid[2 * e + c] + v[3 + c])) <= tol))
                st = gb_csv_fail(&csv, col[1 + c], err, "the particle's centre on the element's midpoint in the "
                                                        "scene's mesh plus its displacement (another mesh?)");
        if (st) break;
        hs->xy[2 * k] = v[1], hs->xy[2 * k + 1] = v[2];
        hs->u[2 * k] = v[3], hs->u[2 * k + 1] = v[4];
        k++;
    }
    if (!st && k != hs->n_cavity)
        st = gb_fail(err, GB_EINPUT, "%s:%d: %d rows; expected one per cavity element, %d", path, csv.line, k,
                     hs->n_cavity);
    gb_csv_close(&csv);
    return st;
}

static gb_status read_host(gb_ymap *m, gb_scene *s, const gb_bem_mesh *mesh, gb_error *err)
{
    gb_host_state *hs = &s->restart.host;
    const gb_host_def *def = &s->host;
    long ne = 0, nc = 0;
    struct fy_node *v;
    gb_status st;
    int cavity = gb_bem_mesh_group(mesh, def->cavity), count = 0;
    for (int e = 0; e < mesh->n; e++) count += mesh->group[e] == cavity;
    if ((st = gb_ymap_find(m, "followed", 0, &v, err))) return st;
    if (v)
        return gb_yaml_fail(m->doc, v, err, "host.followed: the state's host followed its deformed boundary "
                            "(host.updated_lagrangian), and its moved mesh is not in a state file: such a state "
                            "does not start another run (a run stopped within its loading continues with gembem "
                            "run --resume)");
    if ((st = gb_ymap_int(m, "elements", GB_Y_REQUIRED, 1, 1000000000L, &ne, err))) return st;
    if (ne != mesh->n) {
        gb_ymap_find(m, "elements", 0, &v, err);
        return gb_yaml_fail(m->doc, v, err, "host.elements: the state's host has %ld elements, the scene's mesh %s "
                            "has %d; expected the host the state was computed with", ne, def->mesh, mesh->n);
    }
    if ((st = gb_ymap_int(m, "cavity_elements", GB_Y_REQUIRED, 1, 1000000000L, &nc, err))) return st;
    if (nc != count) {
        gb_ymap_find(m, "cavity_elements", 0, &v, err);
        return gb_yaml_fail(m->doc, v, err, "host.cavity_elements: the state's cavity '%s' has %ld elements, the "
                            "scene's mesh has %d; expected the host the state was computed with", def->cavity, nc,
                            count);
    }
    /* every group of the scene, with the same kind of condition: the state gives its values */
    gb_ymap b;
    if ((st = gb_ymap_map(m, "boundary", GB_Y_REQUIRED, &b, err))) return st;
    for (int k = 0; k < def->n_bcs; k++) {
        char path[GB_BEM_NAME_MAX + 32];
        snprintf(path, sizeof path, "host.boundary.%s", def->bc_group[k]);
        if ((st = gb_ymap_find(&b, def->bc_group[k], GB_Y_REQUIRED, &v, err)) ||
            (st = gb_bem_bc_read(m->doc, v, path, &hs->bc[k], err)))
            return st;
        if (hs->bc[k].kind != def->bc[k].kind ||
            (def->bc[k].kind == GB_BEM_BC_COMPONENTS && hs->bc[k].u_given != def->bc[k].u_given))
            return gb_yaml_fail(m->doc, v, err, "%s: the state's condition is %s, the scene's %s; expected the "
                                "conditions the state was computed with", path, bc_kind_name(&hs->bc[k]),
                                bc_kind_name(&def->bc[k]));
    }
    if ((st = gb_ymap_close(&b, err))) return st;
    if (mesh->unbounded && (st = gb_ymap_vector(m, "remote_stress", GB_Y_REQUIRED, 3, hs->remote_stress, err)))
        return st;
    char name[512], path[1024];
    if ((st = gb_ymap_string(m, "particles", GB_Y_REQUIRED, name, sizeof name, err))) return st;
    gb_yaml_relative_path(m->doc, name, path, sizeof path);
    hs->n_cavity = count;
    hs->u = malloc(2 * (size_t)count * sizeof(double));
    hs->xy = malloc(2 * (size_t)count * sizeof(double));
    if (!hs->u || !hs->xy) return gb_fail(err, GB_ENOMEM, "out of memory for %d cavity elements", count);
    if ((st = read_particles(path, mesh, cavity, hs, err))) return st;
    hs->present = 1;
    return gb_ymap_close(m, err);
}

gb_status gb_state_host_presence(gb_ymap *top, const gb_scene *s, gb_error *err)
{
    struct fy_node *hn;
    gb_status st = gb_ymap_find(top, "host", 0, &hn, err);
    if (st) return st;
    if (!hn && s->host.present)
        return gb_yaml_fail(top->doc, top->node, err, "the state has no host (a run in a box); expected a scene "
                                                      "without 'host:'");
    if (hn && !s->host.present)
        return gb_yaml_fail(top->doc, hn, err, "host: the state comes from a run with a host; expected the scene "
                                               "to give the same 'host:' section");
    return GB_OK;
}

gb_status gb_state_host_read(gb_ymap *top, gb_scene *s, gb_error *err)
{
    gb_status st = gb_state_host_presence(top, s, err);
    if (st || !s->host.present) return st;
    gb_ymap m;
    if ((st = gb_ymap_map(top, "host", GB_Y_REQUIRED, &m, err))) return st;
    gb_bem_mesh mesh;
    if ((st = gb_bem_mesh_load(s->host.mesh, &s->host.mesh_opts, &mesh, err))) return st;
    st = read_host(&m, s, &mesh, err);
    gb_bem_mesh_free(&mesh);
    /* a contact with a boundary particle the host does not have */
    for (int c = 0; !st && c < s->restart.n_contacts; c++) {
        int j = s->restart.contacts[c].j;
        if (j < -GB_N_WALLS && -1 - GB_N_WALLS - j >= s->restart.host.n_cavity)
            st = gb_fail(err, GB_EINPUT, "%s: initial contact %d (grain %d) names the boundary particle p%d; the "
                         "host's cavity has %d elements", top->doc->path, c, s->restart.contacts[c].i, -1 - GB_N_WALLS - j,
                         s->restart.host.n_cavity);
    }
    return st;
}

void gb_host_state_at_rest(const gb_host_state *hs, double x, double y, double out[2])
{
    int near = -1;
    double d2 = HUGE_VAL;
    for (int k = 0; hs->present && k < hs->n_cavity; k++) {
        double dx = hs->xy[2 * k] - x, dy = hs->xy[2 * k + 1] - y;
        if (dx * dx + dy * dy < d2) d2 = dx * dx + dy * dy, near = k;
    }
    out[0] = near < 0 ? x : x - hs->u[2 * near];
    out[1] = near < 0 ? y : y - hs->u[2 * near + 1];
}

gb_status gb_state_solver_read(gb_ymap *top, gb_scene *s, gb_error *err)
{
    gb_ymap m;
    struct fy_node *v;
    gb_status st;
    gb_solver_state *ss = &s->restart.solver;
    long next = 0, due = 0;
    if ((st = gb_ymap_find(top, "solver_state", 0, &v, err))) return st;
    if (!v) return GB_OK;
    if ((st = gb_ymap_map(top, "solver_state", 0, &m, err)) ||
        (st = gb_ymap_number(&m, "damping", GB_Y_REQUIRED | GB_Y_POSITIVE, &ss->mu, err)) ||
        (st = gb_ymap_int(&m, "damping_next", GB_Y_REQUIRED, 0, 2147483647L, &next, err)) ||
        (st = gb_ymap_vector(&m, "damping_history", GB_Y_REQUIRED, GB_SOLVER_HISTORY, ss->history, err)) ||
        (st = gb_ymap_number(&m, "smoother_first", GB_Y_NONNEG, &ss->smoother_first, err)) ||
        (st = gb_ymap_int(&m, "newton_due", 0, 0, 1, &due, err)))
        return st;
    ss->next = (int)next, ss->newton_due = (int)due;
    ss->present = 1;
    return gb_ymap_close(&m, err);
}
