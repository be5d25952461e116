/* The state a scene can start from (`initial_state:`): box, grains and contact forces. */
#include <stdio.h>

#include "gembem/output.h"
#include "io/contacts_file.h"
#include "io/file_util.h"
#include "scene/grains_file.h"
#include "solver/solver.h"

#include <stdlib.h>

static int grain_row(char *buf, size_t cap, int i, const void *data)
{
    gb_grain g = gb_sim_grain(data, i);
    return snprintf(buf, cap, "%.17g,%.17g,%.17g,%.17g\n", g.x, g.y, g.r, g.rot);
}

static void write_grains(FILE *f, const void *data)
{
    const gb_sim *sim = data;
    fprintf(f, "x,y,r,rotation\n");
    gb_write_rows(f, gb_sim_n_grains(sim), sim->scene->solver.threads, grain_row, sim);
}

gb_status gb_grains_csv_write(const char *path, const gb_sim *sim, gb_error *err)
{
    return gb_atomic_write(path, write_grains, sim, err);
}

typedef struct {
    const gb_sim *sim;
    const gb_contact *c;
    int rolling; /* the column mr only where there is rolling resistance */
} contact_rows;

/* (xi, yi) - (xj, yj): grain i's centre to the contact's far end, for drawing force chains. */
static int contact_row(char *buf, size_t cap, int k, const void *data)
{
    const contact_rows *r = data;
    const gb_contact *c = &r->c[k];
    const gb_material *mat = gb_sim_material(r->sim, c->j);
    double e = gb_spring_energy(c->pn, c->pt, c->mr, mat);
    gb_grain gi = gb_sim_grain(r->sim, c->i);
    double xj, yj;
    gb_contact_far_end(r->sim, c, &xj, &yj);
    char side[32];
    gb_side_name(c->j, side, sizeof side);
    int n = snprintf(buf, cap, "%d,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.10e,%.10e,%.17g,%.17g,%.17g,%.17g", c->i, side,
                     c->pn, c->pt, c->nx, c->ny, c->overlap, e, c->diss, gi.x, gi.y, xj, yj);
    if (r->rolling && n >= 0 && (size_t)n < cap) n += snprintf(buf + n, cap - (size_t)n, ",%.17g", c->mr);
    if (n >= 0 && (size_t)n + 1 < cap) buf[n++] = '\n', buf[n] = 0;
    return n;
}

static void write_contacts(FILE *f, const gb_sim *sim, const gb_contact *c, int m)
{
    contact_rows r = {sim, c, gb_scene_rolling(sim->scene)};
    fprintf(f, "i,j,pn,pt,nx,ny,overlap,energy,dissipation,xi,yi,xj,yj%s\n", r.rolling ? ",mr" : "");
    gb_write_rows(f, m, sim->scene->solver.threads, contact_row, &r);
}

gb_status gb_contacts_csv_write(const char *path, const gb_sim *sim, gb_error *err)
{
    return gb_contacts_file_write(path, sim, write_contacts, err);
}

/* A group's condition in the scene's syntax (host.boundary), with its current values. */
static void write_bc(FILE *f, const gb_bem_bc *bc)
{
    const double *v = bc->value;
    switch (bc->kind) {
    case GB_BEM_BC_FIXED: fprintf(f, "fixed"); break;
    case GB_BEM_BC_DISPLACEMENT: fprintf(f, "{displacement: [%.17g, %.17g]}", v[0], v[1]); break;
    case GB_BEM_BC_TRACTION: fprintf(f, "{traction: [%.17g, %.17g]}", v[0], v[1]); break;
    case GB_BEM_BC_PRESSURE: fprintf(f, "{pressure: %.17g}", v[0]); break;
    case GB_BEM_BC_NORMAL_DISPLACEMENT: fprintf(f, "{normal_displacement: %.17g}", v[0]); break;
    case GB_BEM_BC_COMPONENTS:
        fprintf(f, "{%s: %.17g, %s: %.17g}", bc->u_given & 1 ? "ux" : "tx", v[0], bc->u_given & 2 ? "uy" : "ty", v[1]);
        break;
    default: fprintf(f, "free"); break;
    }
}

/* state_host.csv: per cavity element, in the host's order, its boundary particle's centre now and
 * its displacement (the particle moves with it: centre = midpoint + displacement, to rounding). */
static void write_host_csv(FILE *f, const void *data)
{
    const gb_sim *sim = data;
    const gb_host *h = sim->host;
    fprintf(f, "element,x,y,ux,uy\n");
    for (int k = 0; k < h->m / 2; k++) {
        double u[2]; /* since rest: summed over a followed host's rebases */
        gb_host_cavity_displacement(h, &sim->state.host, k, u);
        fprintf(f, "%d,%.17g,%.17g,%.17g,%.17g\n", h->K.elem[k], sim->bp.x[k], sim->bp.y[k], u[0], u[1]);
    }
}

static void write_host_yaml(FILE *f, const gb_sim *sim)
{
    const gb_host *h = sim->host;
    gb_bem_problem now = gb_host_problem(h, &sim->state.host);
    fprintf(f, "host:   # where the host was: checked against the scene's mesh and conditions when read\n"
               "  elements: %d\n  cavity_elements: %d\n  particles: state_host.csv\n  boundary:%s\n",
            h->mesh.n, h->m / 2, h->mesh.n_groups > 1 ? "" : " {}");
    for (int g = 0; g < h->mesh.n_groups; g++) {
        if (g == h->cavity) continue;
        fprintf(f, "    %s: ", h->mesh.group_name[g]);
        write_bc(f, &now.bc[g]);
        fprintf(f, "\n");
    }
    if (h->mesh.unbounded)
        fprintf(f, "  remote_stress: [%.17g, %.17g, %.17g]\n", now.remote_stress[0], now.remote_stress[1],
                now.remote_stress[2]);
    if (h->rebases)
        fprintf(f, "  followed: %d   # rebases of a host that followed its boundary: not a restart's start\n",
                h->rebases);
}

gb_status gb_state_write(const char *dir, const gb_sim *sim, gb_error *err)
{
    char path[1024];
    gb_status st;
    snprintf(path, sizeof path, "%s/state_grains.csv", dir);
    if ((st = gb_grains_csv_write(path, sim, err))) return st;
    snprintf(path, sizeof path, "%s/state_contacts.csv", dir);
    if ((st = gb_contacts_csv_write(path, sim, err))) return st;
    snprintf(path, sizeof path, "%s/state_host.csv", dir);
    if (sim->host && (st = gb_atomic_write(path, write_host_csv, sim, err))) return st;
    snprintf(path, sizeof path, "%s/state.yaml", dir);
    gb_atomic_file a;
    if ((st = gb_atomic_open(&a, path, err))) return st;
    gb_box b = gb_sim_box(sim);
    fprintf(a.f,
            "# gembem %s state: the box, grains and contact forces of the last converged step%s.\n"
            "# A scene starts from it with   initial_state: %s\n"
            "gembem_state: 1\n"
            "box: {left: %.17g, right: %.17g, bottom: %.17g, top: %.17g}\n"
            "grains: {file: state_grains.csv, contacts: state_contacts.csv",
            gb_version(), sim->host ? ", and the host (the scene gives the same host: section)" : "", path, b.left,
            b.right, b.bottom, b.top);
    /* a scene that admitted larger overlaps admits its state's too */
    double mo = sim->scene->max_overlap;
    if (mo != GB_MAX_OVERLAP_DEFAULT) fprintf(a.f, ", max_overlap: %.15g", mo);
    fprintf(a.f, "}\n");
    if (sim->host) write_host_yaml(a.f, sim);
    if (gb_solver_is_global(sim)) {
        const gb_solver_damping *d = gb_solver_damping_of(sim);
        fprintf(a.f, "solver_state: {damping: %.17g, damping_next: %d, damping_history: [", d->mu, d->next);
        for (int k = 0; k < GB_SOLVER_HISTORY; k++) fprintf(a.f, "%s%.17g", k ? ", " : "", d->history[k]);
        fprintf(a.f, "], smoother_first: %.17g, newton_due: %d}\n", d->smoother_first, d->newton_due);
    }
    return gb_atomic_commit(&a, err);
}
