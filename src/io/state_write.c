/* The state a scene can start from (`initial_state:`): box, grains and contact forces. */
#include <stdio.h>

#include "gem/sim.h"
#include "gembem/output.h"
#include "io/file_util.h"
#include "scene/grains_file.h"

#include <stdlib.h>

gb_status gb_grains_csv_write(const char *path, const gb_sim *sim, gb_error *err)
{
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    const gb_grain *g = gb_sim_grains(sim);
    fprintf(a.f, "x,y,r,rotation\n");
    for (int i = 0; i < gb_sim_n_grains(sim); i++)
        fprintf(a.f, "%.17g,%.17g,%.17g,%.17g\n", g[i].x, g[i].y, g[i].r, g[i].rot);
    return gb_atomic_commit(&a, err);
}

gb_status gb_contacts_csv_write(const char *path, const gb_sim *sim, gb_error *err)
{
    int m;
    gb_contact *c = gb_sim_contacts_copy(sim, &m, err);
    if (!c) return err->code;
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (!st) {
        /* (xi, yi) - (xj, yj): grain i's centre to grain j's, or to the contact point on a wall or a
         * boundary particle, for drawing force chains. */
        fprintf(a.f, "i,j,pn,pt,nx,ny,overlap,energy,dissipation,xi,yi,xj,yj\n");
        const gb_grain *g = gb_sim_grains(sim);
        for (int k = 0; k < m; k++) {
            const gb_material *mat = gb_sim_material(sim, c[k].j);
            double e = 0.5 * c[k].pn * c[k].pn / mat->kn + (mat->kt > 0 ? 0.5 * c[k].pt * c[k].pt / mat->kt : 0);
            const gb_grain *gi = &g[c[k].i];
            double xj, yj;
            if (c[k].j >= 0) xj = g[c[k].j].x, yj = g[c[k].j].y;
            else xj = gi->x + c[k].nx * (gi->r - c[k].overlap), yj = gi->y + c[k].ny * (gi->r - c[k].overlap);
            char side[32];
            gb_side_name(c[k].j, side, sizeof side);
            fprintf(a.f, "%d,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.10e,%.10e,%.17g,%.17g,%.17g,%.17g\n", c[k].i, side,
                    c[k].pn, c[k].pt, c[k].nx, c[k].ny, c[k].overlap, e, c[k].diss, gi->x, gi->y, xj, yj);
        }
        st = gb_atomic_commit(&a, err);
    }
    free(c);
    return st;
}

gb_status gb_state_write(const char *dir, const gb_sim *sim, gb_error *err)
{
    char path[1024];
    gb_status st;
    snprintf(path, sizeof path, "%s/state_grains.csv", dir);
    if ((st = gb_grains_csv_write(path, sim, err))) return st;
    snprintf(path, sizeof path, "%s/state_contacts.csv", dir);
    if ((st = gb_contacts_csv_write(path, sim, err))) return st;
    snprintf(path, sizeof path, "%s/state.yaml", dir);
    gb_atomic_file a;
    if ((st = gb_atomic_open(&a, path, err))) return st;
    gb_box b = gb_sim_box(sim);
    fprintf(a.f,
            "# gembem %s state: the box, grains and contact forces of the last converged step.\n"
            "# A scene starts from it with   initial_state: %s\n"
            "gembem_state: 1\n"
            "box: {left: %.17g, right: %.17g, bottom: %.17g, top: %.17g}\n"
            "grains: {file: state_grains.csv, contacts: state_contacts.csv}\n",
            gb_version(), path, b.left, b.right, b.bottom, b.top);
    return gb_atomic_commit(&a, err);
}
