/* The line-search iteration's smoother (line_search.c): a damped inertial relaxation,
 * FIRE (Bitzek, Koskinen, Gaehler, Moseler and Gumbsch, Phys. Rev. Lett. 97, 170201, 2006, with
 * its published parameters), in which each grain's mass is its own contact stiffness S (K 8): its
 * acceleration is its reference move (K 9-12 at alpha = 1), a time step of 1 is one Jacobi sweep of
 * the reference iteration, and servo walls follow at every step (K section 2.6) with the whole
 * packing (affine_walls).
 * A hybrid scene's boundary particles move with the grains, each by its own stiffness (the host's
 * and its contacts': particle_move): without them, the localisation sweep's line search stalled
 * with what was left on the particles (4 of its 8 cases).
 * A Jacobi or Gauss-Seidel iteration needs a number of sweeps that grows like the square of the
 * packing's side to carry a disturbance across it; an inertial one, like the side. Every grain moves
 * at every step (a disturbance must travel), so a step costs one evaluation of every contact.
 * Measured against the over-relaxed Gauss-Seidel sweeps of the unbalanced grains that it replaced
 * (docs/solver-design.md): the 1e3 oedometric path of tools/bench_solver.sh from one
 * start 119 Newton iterations and 20 519 sweeps -> 58 iterations and 5 655 steps, half the time;
 * that packing's friction relaxation 68 088 sweeps -> 1 856 steps; the loose 1e3 deposit
 * compressed isotropically (servo walls, Jacobi sweeps then) 458 108 sweeps, 79 s -> 6 262 steps, 1.9 s. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "solver/solver_impl.h"

/* FIRE's parameters (Bitzek et al. 2006): N_min, f_inc, f_dec, alpha_start, f_alpha. The largest
 * step, in Jacobi sweeps: on the 1e3 path 0.7, 1.0 and 1.3 took 7 668, 6 560 and 51 529 steps
 * (an explicit step scaled by the diagonal is stable below about sqrt(2)). */
enum { N_MIN = 5 };
static const double F_INC = 1.1, F_DEC = 0.5, ALPHA_START = 0.1, F_ALPHA = 0.99, DT_MAX = 1.0, DT_START = 0.5;

/* A boundary particle's acceleration (its move at alpha = 1, as a grain's by K 9): its force over
 * its own stiffness, the host's (the symmetric part of K's diagonal block: K is not symmetric) plus
 * its contacts' (bp_S); the global system's diagonal block for it (assemble.c). */
static void particle_move(const gb_sim *sim, int e, double d[2])
{
    const double *K = sim->host->K.K, *Sp = &sim->scratch.bp_S[3 * e], *F = &sim->scratch.bp_F[2 * e];
    size_t m = (size_t)sim->host->m, r = 2 * (size_t)e;
    double k00 = K[r + r * m] + Sp[0], k11 = K[r + 1 + (r + 1) * m] + Sp[2];
    double k01 = 0.5 * (K[r + 1 + r * m] + K[r + (r + 1) * m]) + Sp[1], det = k00 * k11 - k01 * k01;
    d[0] = d[1] = 0;
    if (!(det > 0) || !(k00 > 0)) return;
    d[0] = -(k11 * F[0] - k01 * F[1]) / det;
    d[1] = -(k00 * F[1] - k01 * F[0]) / det;
}

/* A body's move in a step, dt v, and at most `cap` (its radius times solver.max_move): the velocity
 * is cut to match. Without the cap a grain pushed out of a squeeze coasted on, through the
 * half-discs of a hybrid scene's cavity wall and out of the body (the localisation study: up to
 * 9 grains a case, one 5.5 cm in a step); capped, a grain meeting a half-disc is turned
 * back before it can pass it. Stopping a grain that has lost its last contact as well made the 1e4
 * peer relaxation 5 times slower (28 497 smoother steps against 4 656). */
static void advance(double *v, double *d, int dofs, double dt, double cap)
{
    double len2 = 0;
    for (int k = 0; k < dofs; k++) d[k] = dt * v[k], len2 += d[k] * d[k];
    if (!(len2 > cap * cap)) return;
    double f = cap / sqrt(len2);
    for (int k = 0; k < dofs; k++) d[k] *= f, v[k] *= f;
}

/* The packing's uniform strain that the walls' move of a step carries (zero unless the walls are
 * stress-controlled): grain i moves by (ax (x_i - xc), ay (y_i - yc)) with them. */
typedef struct {
    double ax, ay, xc, yc;
} affine_move;

/* Servo walls (K section 2.6) move, in the smoother, with the whole packing: by Newton's step along
 * the affine mode (every grain moved with the box), whose stiffness is the touching contacts' sum of
 * kn (n.E l)^2 + kt (t.E l)^2 (E the mode's unit strain, l the branch vector: the other centre, or
 * the contact point at r n for a wall). Stress control: each axis by its own mode (E = diag(1, 0)
 * and diag(0, 1)); constant mean stress: the isotropic strain of gb_gem_wall_moves, against the
 * mean-stress error times the area change per unit strain (the global solver's W_MEAN residual,
 * global.c). Moving a wall by its own contacts' stiffness with the grains held (gb_gem_wall_moves)
 * lets the packing follow by a wave from the walls, and on the +5 % stress step of
 * tools/bench_scaling.sh at 1e5 discs no grain was out of balance for the smoother's last 2 700 of
 * 3 444 steps, only the walls' stress (docs/solver-design.md): 36.7 s -> 1.6 s, 143
 * steps. Each wall's move is at most solver.max_move times the mean radius (or its own-stiffness
 * move if larger: a loose packing whose affine stiffness is near zero is pressed at that pace). */
static affine_move affine_walls(gb_sim *sim, const gb_wall_control *wc, double cap)
{
    affine_move a = {0, 0, 0, 0};
    if (wc->mode != GB_WALLS_STRESS && wc->mode != GB_WALLS_MEAN) return a;
    const gb_box *b = &sim->state.box;
    /* summed with the forces (src/gem/relax.c) */
    double W = b->right - b->left, H = b->top - b->bottom, kxx = sim->scratch.affine_k[0],
           kyy = sim->scratch.affine_k[1], kxy = sim->scratch.affine_k[2];
    /* the walls' own moves (inward positive): grains held */
    double own[2] = {sim->scratch.wall_dx[GB_WALL_LEFT][0], sim->scratch.wall_dx[GB_WALL_BOTTOM][1]}, move[2];
    if (wc->mode == GB_WALLS_STRESS) {
        double t[2];
        gb_gem_stress_residuals(sim, wc, t);
        /* d(F_a + F_b)/d(inward move of both) along the mode: the strain is 2 move / side */
        double k[2] = {kxx * 4 / (W * W), kyy * 4 / (H * H)};
        for (int q = 0; q < 2; q++) {
            double newton = k[q] > 0 ? 2 * t[q] / k[q] : HUGE_VAL * t[q];
            double most = fmax(cap, fabs(own[q]));
            move[q] = fabs(newton) <= most ? newton : copysign(most, t[q]);
            if (!(t[q] != 0)) move[q] = 0;
        }
    } else {
        /* the isotropic strain de moves the walls by de W_ref / 2 and de H_ref / 2 (gb_gem_wall_moves):
         * the packing's strains ex = de W_ref / W, ey = de H_ref / H */
        double ex = sim->ref_width / W, ey = sim->ref_height / H;
        double k = kxx * ex * ex + 2 * kxy * ex * ey + kyy * ey * ey;
        double r = gb_gem_mean_stress_error(sim, wc) * (W * sim->ref_height + H * sim->ref_width);
        double half = 0.5 * fmax(sim->ref_width, sim->ref_height), most = fmax(cap, fmax(fabs(own[0]), fabs(own[1])));
        double de = k > 0 ? r / k : copysign(HUGE_VAL, r);
        if (!(fabs(de) * half <= most)) de = copysign(most / half, r);
        if (!(r != 0)) de = 0;
        move[0] = 0.5 * de * sim->ref_width, move[1] = 0.5 * de * sim->ref_height;
    }
    sim->scratch.wall_dx[GB_WALL_LEFT][0] = move[0], sim->scratch.wall_dx[GB_WALL_RIGHT][0] = -move[0];
    sim->scratch.wall_dx[GB_WALL_BOTTOM][1] = move[1], sim->scratch.wall_dx[GB_WALL_TOP][1] = -move[1];
    a.ax = -2 * move[0] / W, a.ay = -2 * move[1] / H;
    a.xc = 0.5 * (b->left + b->right), a.yc = 0.5 * (b->bottom + b->top);
    return a;
}

/* A step's sums over the grains and boundary particles (of its DOFs, np particles): the merit
 * (gb_gem_merit, gb_gem_particle_merit, from the walls' residual), the second half of the last
 * move's fixing work (the trapezoid of gb_gem_balance), the power of the forces (minus the fixing
 * forces) on the velocities, |v|^2 and |a|^2, and whether every grain and particle is balanced. */
typedef struct {
    double merit, work, power, vv, aa;
    int balanced;
} step_sums;

/* The grains' moves at alpha = 1 (K 9: their accelerations), then one pass over the grains in blocks
 * on solver.threads threads (GB_SMOOTHER_BLOCK; the step's cost is its pass over the contacts, and
 * these), then the particles': the step's sums. */
static step_sums force_pass(gb_solver *s, gb_sim *sim, double wall_residual, int np)
{
    int n = sim->state.n, threads = s->set->threads, par = threads > 1 && n >= GB_PARALLEL_GRAINS;
    int nb = gb_smoother_blocks(n);
    double *v = s->velocity, *acc = s->acceleration, inv_alpha = 1 / s->set->alpha;
    double a2 = sim->accuracy * sim->accuracy;
    step_sums t = {wall_residual * wall_residual, 0, 0, 0, 0, 1};
#pragma omp parallel for schedule(static) num_threads(threads) if (par)
    for (int i = 0; i < n; i++) gb_gem_grain_move(sim, i, &acc[3 * i]);
#pragma omp parallel for schedule(static) num_threads(threads) if (par)
    for (int b = 0; b < nb; b++) {
        /* block 0 starts from the walls' merit: one block sums as the grains' order would */
        double m = b ? 0 : t.merit, wk = 0, pw = 0, v2 = 0, a2s = 0, out = 0;
        for (int i = b * GB_SMOOTHER_BLOCK, e = gb_smoother_block_end(b, n); i < e; i++) {
            const double *F = &sim->scratch.F[3 * i];
            if (s->in_system[i]) m += F[0] * F[0], m += F[1] * F[1], m += F[2] * F[2];
            if (!(gb_gem_force2(sim, i) <= a2)) out = 1;
            for (int q = 3 * i; q < 3 * i + 3; q++) {
                wk += sim->scratch.F[q] * sim->scratch.dX[q];
                acc[q] *= inv_alpha;
                pw -= sim->scratch.F[q] * v[q];
                v2 += v[q] * v[q], a2s += acc[q] * acc[q];
            }
        }
        double *sum = &s->block_sums[GB_SMOOTHER_SUMS * b];
        sum[0] = m, sum[1] = wk, sum[2] = pw, sum[3] = v2, sum[4] = a2s, sum[5] = out;
    }
    for (int b = 0; b < nb; b++) {
        const double *sum = &s->block_sums[GB_SMOOTHER_SUMS * b];
        t.merit = b ? t.merit + sum[0] : sum[0];
        t.work += sum[1], t.power += sum[2], t.vv += sum[3], t.aa += sum[4];
        if (sum[5] != 0) t.balanced = 0;
    }
    for (int e = 0; e < np; e++) {
        const double *F = &sim->scratch.bp_F[2 * e];
        t.balanced &= F[0] * F[0] + F[1] * F[1] <= a2;
        particle_move(sim, e, &acc[3 * n + 2 * e]);
        for (int q = 3 * n + 2 * e, k = 0; k < 2; q++, k++) {
            t.power -= F[k] * v[q];
            t.vv += v[q] * v[q], t.aa += acc[q] * acc[q];
        }
    }
    t.merit = gb_gem_particle_merit(sim, t.merit);
    return t;
}

/* Semi-implicit Euler: the velocities by dt times the accelerations, then the moves (each capped at
 * solver.max_move of its radius) with the walls' affine strain aff, into sim->scratch.dX and
 * sim->bp.dx; returns the fixing forces' work on the grains' moves, summed by blocks as
 * force_pass's. */
static double move_pass(gb_solver *s, gb_sim *sim, double dt, const affine_move *aff, int np)
{
    int n = sim->state.n, threads = s->set->threads, par = threads > 1 && n >= GB_PARALLEL_GRAINS;
    int nb = gb_smoother_blocks(n);
    double *v = s->velocity, *acc = s->acceleration, max_move = s->set->max_move, work = 0;
#pragma omp parallel for schedule(static) num_threads(threads) if (par)
    for (int b = 0; b < nb; b++) {
        double wk = 0;
        for (int i = b * GB_SMOOTHER_BLOCK, e = gb_smoother_block_end(b, n); i < e; i++) {
            double *vi = &v[3 * i], *d = &sim->scratch.dX[3 * i];
            for (int k = 0; k < 3; k++) vi[k] += dt * acc[3 * i + k];
            advance(vi, d, 3, dt, max_move * sim->state.g[i].r);
            d[0] += aff->ax * (sim->state.g[i].x - aff->xc), d[1] += aff->ay * (sim->state.g[i].y - aff->yc);
            for (int k = 0; k < 3; k++) wk += sim->scratch.F[3 * i + k] * d[k];
        }
        s->block_sums[GB_SMOOTHER_SUMS * b] = wk;
    }
    for (int b = 0; b < nb; b++) work += s->block_sums[GB_SMOOTHER_SUMS * b];
    for (int e = 0; e < np; e++) {
        double *vp = &v[3 * n + 2 * e];
        for (int k = 0; k < 2; k++) vp[k] += dt * acc[3 * n + 2 * e + k];
        advance(vp, &sim->bp.dx[2 * e], 2, dt, max_move * sim->bp.r[e]);
    }
    return work;
}

gb_status gb_solver_inertial(gb_solver *s, gb_sim *sim, const gb_wall_control *wc, double target, int max_steps,
                             double stall_check, int *stalled, gb_error *err)
{
    *stalled = 0;
    double check_merit = -1, next_check = stall_check;
    /* The DOFs: grains' (3 each), then the boundary particles' (2 each) unless the host is rigid. */
    int n = sim->state.n, np = sim->host && !sim->scene->host.rigid ? sim->bp.n : 0, dofs = 3 * n + 2 * np;
    double *v = s->velocity, *acc = s->acceleration;
    memset(v, 0, (size_t)dofs * sizeof(double));
    memset(sim->scratch.dX, 0, 3 * (size_t)n * sizeof(double));
    if (sim->bp.n) memset(sim->bp.dx, 0, 2 * (size_t)sim->bp.n * sizeof(double));
    double dt = DT_START, mixing = ALPHA_START;
    int since_uphill = 0, threads = s->set->threads, par = threads > 1 && n >= GB_PARALLEL_GRAINS, step = 0;
    gb_status st = GB_OK;
    /* the affine walls' largest move: max_move mean radii (the radii do not change here) */
    double r_sum = 0;
    for (int i = 0; i < n; i++) r_sum += sim->state.g[i].r;
    double wall_cap = s->set->max_move * (n ? r_sum / n : 0);
    for (; step < max_steps; step++) {
        /* servo walls follow the grains at every step (K section 2.6): by their own stiffness,
         * then (stress or mean-stress control) with the whole packing */
        double wall_residual = gb_gem_wall_moves(sim, wc);
        affine_move aff = affine_walls(sim, wc, wall_cap);
        step_sums t = force_pass(s, sim, wall_residual, np);
        sim->state.acc.relaxation -= 0.5 * t.work;
        if (t.merit <= target) break;
        if (t.balanced && wall_residual <= sim->accuracy) break;
        /* Stalled: at the merit's rate of fall over the last stall_check steps, the target is
         * more than another stall_check steps away (FIRE's merit is not monotone: the rate is
         * taken over the whole stretch). */
        if (check_merit < 0) check_merit = t.merit;
        if (stall_check > 0 && step >= next_check) {
            double rate = log(check_merit / t.merit) / stall_check;
            if (!(rate > 0) || log(t.merit / target) > rate * stall_check) {
                *stalled = 1;
                break;
            }
            check_merit = t.merit, next_check += stall_check;
        }
        if (t.power > 0) { /* downhill: turn the velocity towards the force, and speed up */
            double keep = 1 - mixing, mix = t.aa > 0 ? mixing * sqrt(t.vv / t.aa) : 0;
#pragma omp parallel for schedule(static) num_threads(threads) if (par)
            for (int q = 0; q < dofs; q++) v[q] = keep * v[q] + mix * acc[q];
            if (++since_uphill > N_MIN) dt = fmin(F_INC * dt, DT_MAX), mixing *= F_ALPHA;
        } else if (step > 0) { /* uphill: stop, and go on more carefully */
            since_uphill = 0, dt *= F_DEC, mixing = ALPHA_START;
            memset(v, 0, (size_t)dofs * sizeof(double));
        }
        double work = move_pass(s, sim, dt, &aff, np);
        s->work.sweeps++;
        sim->state.acc.relaxation -= 0.5 * work;
        if ((st = gb_gem_move_and_forces(sim, err))) break;
        /* the step's clock (its limit, a long step's progress): past the limit the step fails and
         * goes back to its start, so the move needs no more accounting */
        if (s->work.sweeps % GB_POLL_SWEEPS == 0 && (st = gb_solver_poll(s, sim, NAN))) break;
        if ((s->work.sweeps - s->sweeps0) % GB_HISTORY_SWEEPS == 0) gb_solver_report_smoother(s, sim, wall_residual);
    }
    if (step == max_steps) sim->state.acc.relaxation -= 0.5 * gb_gem_fixing_work(sim);
    memset(sim->scratch.dX, 0, 3 * (size_t)n * sizeof(double));
    if (sim->bp.n) memset(sim->bp.dx, 0, 2 * (size_t)sim->bp.n * sizeof(double));
    memset(sim->scratch.wall_dx, 0, sizeof sim->scratch.wall_dx);
    sim->state.acc.half_pending = 0;
    return st;
}
