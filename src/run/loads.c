/* The control phase's loads of a load step (src/run/program.c): a sub-step's loads applied to the
 * problem, and whether its walls can reach their targets at all. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "run/loads.h"
#include "solver/solver.h"

/* Imposes a strain increment (compression positive) on the walls, symmetrically, grains held. */
static gb_status impose_strain(gb_sim *sim, double de1, double de2, gb_error *err)
{
    gb_gem_forces(sim); /* the walls' forces before the move, for their work */
    sim->state.acc.half_pending = 0;
    memset(sim->scratch.dX, 0, (size_t)sim->state.n * 3 * sizeof(double));
    if (sim->bp.n) memset(sim->bp.dx, 0, 2 * (size_t)sim->bp.n * sizeof(double));
    memset(sim->scratch.wall_dx, 0, sizeof sim->scratch.wall_dx);
    double dy = 0.5 * de1 * sim->ref_height, dx = 0.5 * de2 * sim->ref_width;
    sim->scratch.wall_dx[GB_WALL_BOTTOM][1] = dy;
    sim->scratch.wall_dx[GB_WALL_TOP][1] = -dy;
    sim->scratch.wall_dx[GB_WALL_LEFT][0] = dx;
    sim->scratch.wall_dx[GB_WALL_RIGHT][0] = -dx;
    if (gb_solver_predicts_strain(sim)) {
        /* The grains follow the box affinely, the prediction of a homogeneous strain: Newton
         * starts with the increment spread over the packing instead of concentrated at the walls
         * (FIRE-jammed 1e3 discs, 1 % oedometric in 20 steps: 7.7 iterations a step against 8.3). */
        const gb_box *b = &sim->state.box;
        double xc = 0.5 * (b->left + b->right), yc = 0.5 * (b->bottom + b->top);
        double sx = 2 * dx / (b->right - b->left), sy = 2 * dy / (b->top - b->bottom);
        for (int i = 0; i < sim->state.n; i++) {
            sim->scratch.dX[3 * i] = -sx * (sim->state.g[i].x - xc);
            sim->scratch.dX[3 * i + 1] = -sy * (sim->state.g[i].y - yc);
        }
        /* a move of the grains like an iteration's: the fixing forces' work, by the trapezoid rule */
        sim->state.acc.relaxation -= 0.5 * gb_gem_fixing_work(sim);
        sim->state.acc.half_pending = 1;
    }
    return gb_gem_apply_moves(sim, err);
}

/* The loads of a sub-step of size h: the host's loads grow (grains and cavity held: f0 changes),
 * or the walls move (strain control, and the shear increment of shear_mean_stress). */
gb_status gb_run_apply_loads(gb_sim *sim, const gb_stage *sg, double h, gb_error *err)
{
    gb_status st = GB_OK;
    sim->state.acc.dissipation_step = 0;
    for (int q = 0; q < sim->state.pairs.n; q++) sim->state.pairs.p[q].diss = 0;
    switch (sg->kind) {
    case GB_STAGE_HOST_DISPLACEMENT:
    case GB_STAGE_HOST_LOAD:
        for (int q = 0; q < sg->n_host_groups && !st; q++) {
            double inc[2] = {h * sg->host_increment[q][0], h * sg->host_increment[q][1]};
            st = gb_host_add_load(sim->host, &sim->state.host, sg->host_group[q], inc, err);
        }
        double remote[3] = {h * sg->host_remote_increment[0], h * sg->host_remote_increment[1],
                            h * sg->host_remote_increment[2]};
        if (!st && sim->host->mesh.unbounded) st = gb_host_add_remote(sim->host, &sim->state.host, remote, err);
        return st;
    case GB_STAGE_STRAIN: return impose_strain(sim, h * sg->de1, h * sg->de2, err);
    case GB_STAGE_SHEAR_MEAN: return impose_strain(sim, 0.5 * h * sg->d_shear, -0.5 * h * sg->d_shear, err);
    default: return GB_OK;
    }
}

/* Whether servo walls can reach their target under the grains' weight. Frictionless side walls
 * carry no vertical force, so the bottom wall carries the top's force plus the weight: the walls'
 * mean vertical stress s1 = (F_bottom + F_top) / 2W is at least half the weight over the width
 * (across, the same for a horizontal body force). Below it the top wall would rise after grains
 * that fall back, for ever, and the first step would never end. Refused at once instead, with
 * what the stage needs. Walls with friction or cohesion can carry the weight: not checked. */
gb_status gb_run_weight_reachable(const gb_sim *sim, const gb_stage *sg, const gb_wall_control *wc,
                                  gb_error *err)
{
    const gb_material *m = &sim->scene->grain_wall;
    if (wc->mode != GB_WALLS_STRESS && wc->mode != GB_WALLS_MEAN) return GB_OK;
    if (!sim->world.box || !sim->body || m->friction_deg != 0 || m->cohesion != 0) return GB_OK;
    double bx = 0, by = 0;
    for (int i = 0; i < sim->state.n; i++) bx += sim->body[2 * i], by += sim->body[2 * i + 1];
    const gb_box *b = &sim->state.box;
    double W = b->right - b->left, H = b->top - b->bottom, a = sim->accuracy;
    /* the least s1 and s2, with the walls' residual allowed (K 14: a force, over the side) */
    double s1 = fmax(0, 0.5 * fabs(by) / W - a / W), s2 = fmax(0, 0.5 * fabs(bx) / H - a / H);
    if (wc->mode == GB_WALLS_STRESS && wc->s1 >= s1 && wc->s2 >= s2) return GB_OK;
    if (wc->mode == GB_WALLS_MEAN && wc->mean >= 0.5 * (s1 + s2)) return GB_OK;
    char target[96];
    if (wc->mode == GB_WALLS_MEAN) snprintf(target, sizeof target, "a mean stress of %.6g", wc->mean);
    else snprintf(target, sizeof target, "s1 %.6g and s2 %.6g", wc->s1, wc->s2);
    return gb_fail(err, GB_EINPUT,
                   "loading[%d].%s: the walls cannot reach %s dyn/cm under the grains' weight (%.6g, %.6g dyn): "
                   "frictionless walls carry at least half of it over the side, s1 >= %.6g and s2 >= %.6g (a mean "
                   ">= %.6g) here; expected a larger stress or a smaller body force",
                   (int)(sg - sim->scene->stages), gb_stage_name(sg->kind), target, bx, by, s1, s2, 0.5 * (s1 + s2));
}
