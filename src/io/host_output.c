/* The host's files in a run directory: its cavity elements with the boundary particles' forces,
 * its whole boundary (CSV, VTK) and its interior displacement and stress (VTK) for the final
 * displacements of the cavity. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/bem_output.h"
#include "gem/sim.h"
#include "io/host_output.h"
#include "io/file_util.h"

/* Cavity elements: the particle's centre at rest, its displacement (since rest: summed over a
 * followed host's rebases), the force the host asks for (K u + f0) and the force the grains put on it. */
static void write_particles(FILE *f, const void *data)
{
    const gb_sim *sim = data;
    const gb_host *h = sim->host;
    const gb_bem_mesh *rest = gb_host_rest_mesh(h);
    fprintf(f, "element,x,y,r,nx,ny,ux,uy,host_fx,host_fy,grain_fx,grain_fy\n");
    for (int k = 0; k < sim->bp.n; k++) {
        int e = h->K.elem[k];
        /* bp_F = (K u + f0) - (force of the grains on the particle) */
        double gx = h->force[2 * k] - sim->scratch.bp_F[2 * k], gy = h->force[2 * k + 1] - sim->scratch.bp_F[2 * k + 1];
        double u[2];
        gb_host_cavity_displacement(h, &sim->state.host, k, u);
        fprintf(f, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", e, rest->mid[2 * e],
                rest->mid[2 * e + 1], sim->bp.r[k], sim->bp.nx[k], sim->bp.ny[k], u[0], u[1],
                h->force[2 * k], h->force[2 * k + 1], gx, gy);
    }
}

/* What the condensation measured: the asymmetry of K that a symmetric solver neglects. */
static void write_info(FILE *f, const void *data)
{
    const gb_host *h = data;
    fprintf(f, "# The host's condensed cavity stiffness K = L G^-1 H (H 7).\n"
                 "elements: %d\ncavity_elements: %d\nasymmetry: %.6e   # ||K - K^t||_F / ||K||_F\n"
                 "rcond: %.6e\nlength_scale: %.6g   # 1 unless the degenerate scale was avoided\n",
            h->mesh.n, h->m / 2, h->K.asymmetry, h->K.rcond, h->K.scale);
}

gb_status gb_host_write_outputs(const char *dir, const gb_sim *sim, gb_error *err)
{
    const gb_host *h = sim->host;
    /* the whole state in the frame of the body at rest (gb_host_solve), as a host that never moved */
    const gb_bem_mesh *mesh = gb_host_rest_mesh(h);
    char path[1024];
    gb_status st;
    snprintf(path, sizeof path, "%s/host_info.yaml", dir);
    if ((st = gb_atomic_write(path, write_info, h, err))) return st;
    snprintf(path, sizeof path, "%s/host_particles.csv", dir);
    if ((st = gb_atomic_write(path, write_particles, sim, err))) return st;
    gb_bem_solution sol;
    gb_bem_problem now = gb_host_problem(h, &sim->state.host);
    if ((st = gb_host_solve(h, &sim->state.host, &sol, err))) return st;
    /* An interior grid over the body's bounding box: points closer to the boundary than a fifth of
     * the mean element length are left out (constant elements are inaccurate there). */
    double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL, lmean = 0;
    for (int e = 0; e < mesh->n; e++) {
        xmin = fmin(xmin, mesh->mid[2 * e]), xmax = fmax(xmax, mesh->mid[2 * e]);
        ymin = fmin(ymin, mesh->mid[2 * e + 1]), ymax = fmax(ymax, mesh->mid[2 * e + 1]);
        lmean += mesh->length[e] / mesh->n;
    }
    enum { NG = 61 };
    gb_bem_scene grid;
    memset(&grid, 0, sizeof grid);
    grid.npts = NG * NG;
    grid.grid_nx = grid.grid_ny = NG;
    grid.pts = malloc(2 * NG * NG * sizeof(double));
    grid.pt_inside = calloc(NG * NG, sizeof(int));
    double *inside_xy = malloc(2 * NG * NG * sizeof(double)), *u = calloc(2 * NG * NG, sizeof(double)),
           *s = calloc(3 * NG * NG, sizeof(double)), *uin = malloc(2 * NG * NG * sizeof(double)),
           *sin_ = malloc(3 * NG * NG * sizeof(double)), *bs = malloc(3 * (size_t)mesh->n * sizeof(double));
    if (!grid.pts || !grid.pt_inside || !inside_xy || !u || !s || !uin || !sin_ || !bs) {
        st = gb_fail(err, GB_ENOMEM, "out of memory for the host's field");
        goto done;
    }
    int nin = 0;
    for (int j = 0; j < NG; j++)
        for (int i = 0; i < NG; i++) {
            int q = j * NG + i;
            double x = xmin + (xmax - xmin) * i / (NG - 1), y = ymin + (ymax - ymin) * j / (NG - 1);
            grid.pts[2 * q] = x, grid.pts[2 * q + 1] = y;
            grid.pt_inside[q] = gb_bem_mesh_inside(mesh, x, y) && gb_bem_mesh_distance(mesh, x, y) > 0.2 * lmean;
            if (grid.pt_inside[q]) inside_xy[2 * nin] = x, inside_xy[2 * nin + 1] = y, nin++;
        }
    if ((st = gb_bem_interior(mesh, &h->sys.material, &now, &sol, nin, inside_xy, uin, sin_, err))) goto done;
    for (int q = 0, k = 0; q < NG * NG; q++)
        if (grid.pt_inside[q]) {
            memcpy(&u[2 * q], &uin[2 * k], 2 * sizeof(double));
            memcpy(&s[3 * q], &sin_[3 * k], 3 * sizeof(double));
            k++;
        }
    snprintf(path, sizeof path, "%s/host_field.vtu", dir);
    if ((st = gb_bem_write_interior_vtu(path, &grid, u, s, err))) goto done;
    if ((st = gb_bem_boundary_stress(mesh, &h->sys.material, &sol, bs, err))) goto done;
    snprintf(path, sizeof path, "%s/host_boundary.csv", dir);
    if ((st = gb_bem_write_boundary_csv(path, mesh, &sol, bs, err))) goto done;
    snprintf(path, sizeof path, "%s/host_boundary.vtp", dir);
    st = gb_bem_write_boundary_vtp(path, mesh, &sol, err);
done:
    free(grid.pts), free(grid.pt_inside), free(inside_xy), free(u), free(s), free(uin), free(sin_), free(bs);
    gb_bem_solution_free(&sol);
    return st;
}

void gb_host_write_steps_header(FILE *f, const gb_scene *scene)
{
    fprintf(f, "step,group,condition,ux,uy,fx,fy%s\n", scene->host.mesh_opts.unbounded ? ",sxx,syy,sxy" : "");
}

static const char *condition_name(gb_bem_bc_kind k)
{
    static const char *const names[] = {"none", "free", "fixed", "displacement", "traction", "pressure",
                                        "normal_displacement", "components"};
    return (int)k >= 0 && (int)k <= GB_BEM_BC_COMPONENTS ? names[k] : "none";
}

gb_status gb_host_write_step(FILE *f, int step, const gb_sim *sim, gb_error *err)
{
    const gb_host *h = sim->host;
    for (int g = 0; g < h->mesh.n_groups; g++) {
        double force[2], disp[2];
        gb_host_group_resultant(h, &sim->state.host, g, force, disp);
        fprintf(f, "%d,%s,%s,%.17g,%.17g,%.17g,%.17g", step, h->mesh.group_name[g],
                g == h->cavity ? "cavity" : condition_name(h->prob.bc[g].kind), disp[0], disp[1], force[0], force[1]);
        if (h->mesh.unbounded)
            fprintf(f, ",%.17g,%.17g,%.17g", sim->state.host.remote[0], sim->state.host.remote[1],
                    sim->state.host.remote[2]);
        fputc('\n', f);
    }
    return fflush(f) == 0 ? GB_OK : gb_fail(err, GB_EIO, "host_steps.csv: write failed");
}
