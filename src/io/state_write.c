/* The state a scene can start from (`initial_state:`): box, grains and contact forces. */
#include <stdio.h>

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

static gb_status write_contacts(const char *path, const gb_sim *sim, gb_error *err)
{
    int m;
    gb_contact *c = gb_sim_contacts_copy(sim, &m, err);
    if (!c) return err->code;
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (!st) {
        fprintf(a.f, "i,j,pn,pt,nx,ny,overlap\n");
        for (int k = 0; k < m; k++) {
            char side[32];
            gb_side_name(c[k].j, side, sizeof side);
            fprintf(a.f, "%d,%s", c[k].i, side);
            fprintf(a.f, ",%.17g,%.17g,%.17g,%.17g,%.17g\n", c[k].pn, c[k].pt, c[k].nx, c[k].ny, c[k].overlap);
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
    if ((st = write_contacts(path, sim, err))) return st;
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
