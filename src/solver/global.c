/* The global system's solution: its sparse pattern, its factorisation and solves by the linear
 * solver the settings name (a backend of linear.h), the corrections of sliding contacts it unloads,
 * and the moves it gives (assembly: assemble.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "solver/global_impl.h"

/* Smallest relative diagonal shift: it keeps a system with a free rigid mode (a cluster held by
 * nothing) positive definite; if the factorisation still meets a zero pivot it grows tenfold. */
static const double REGULARISE = 1e-10;
/* A grain's largest turn in one line search move, in max_move (solver.max_move rad; 1 rad by
 * default): beyond it the grain rolls in a mechanism (gb_global_moves). */
static const double TURN_MOVES = 10;

static int node_dofs(const gb_global *gl, int v) { return v < gl->n ? 3 : v < gl->n + gl->np ? 2 : 1; }

gb_status gb_global_create(const gb_solver_settings *set, int n_grains, int n_particles, gb_global **out,
                           gb_error *err)
{
    gb_global *gl = calloc(1, sizeof *gl);
    if (!gl) return gb_fail(err, GB_ENOMEM, "out of memory");
    gl->set = set;
    gl->linear = gb_linear_backend_of(set->linear);
    if (!gl->linear) {
        free(gl);
        return gb_fail(err, GB_EINPUT, "solver.linear: no linear solver of kind %d in this gembem", set->linear);
    }
    gl->n = n_grains;
    gl->np = n_particles;
    gl->nodes = n_grains + n_particles + NW;
    gl->ndof = 3 * n_grains + 2 * n_particles + NW;
    gl->pattern_of = -1;
    size_t nd = (size_t)gl->ndof, nn = (size_t)gl->nodes, ng = (size_t)n_grains + 1;
    gl->dof0 = malloc(nn * sizeof(int));
    gl->adj_start = calloc(nn + 1, sizeof(int));
    gl->collen = calloc(nn, sizeof(int));
    gl->colstart = calloc(nn, sizeof(int));
    gl->wall_in_grain = malloc(NW * ng * sizeof(int));
    gl->grain_in_wall = malloc(NW * ng * sizeof(int));
    gl->touch = calloc(ng, 1);
    gl->Ap = calloc(nd + 1, sizeof(int));
    gl->rhs = calloc(nd, sizeof(double));
    gl->x = calloc(nd, sizeof(double));
    gl->held = calloc(nd, 1);
    gl->S = calloc(6 * ng, sizeof(double));
    gl->Sp = calloc(3 * (size_t)n_particles + 1, sizeof(double));
    if (!gl->dof0 || !gl->adj_start || !gl->collen || !gl->colstart || !gl->wall_in_grain || !gl->grain_in_wall ||
        !gl->touch || !gl->Ap || !gl->rhs || !gl->x || !gl->held || !gl->S || !gl->Sp) {
        gb_global_free(gl);
        return gb_fail(err, GB_ENOMEM, "out of memory for the global system of %d grains", n_grains);
    }
    for (int v = 0, d = 0; v < gl->nodes; v++) {
        gl->dof0[v] = d;
        d += node_dofs(gl, v);
    }
    *out = gl;
    return GB_OK;
}

void gb_global_free(gb_global *gl)
{
    if (!gl) return;
    if (gl->ls) gl->linear->free(gl->ls);
    free(gl->dof0), free(gl->adj_start), free(gl->adj), free(gl->adj_off), free(gl->collen), free(gl->colstart);
    free(gl->pos_ij), free(gl->pos_ji), free(gl->wall_in_grain), free(gl->grain_in_wall), free(gl->touch);
    free(gl->Ap), free(gl->Ai), free(gl->Ax), free(gl->rhs), free(gl->x), free(gl->held);
    free(gl->S), free(gl->Sp), free(gl->kt), free(gl->slide), free(gl->stick), free(gl->unloading);
    free(gl->resumed);
    free(gl);
}

const gb_global_stats *gb_global_statistics(const gb_global *gl) { return &gl->stats; }

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}


/* Which wall DOFs a grain touching these walls is coupled to. */
static int couples(unsigned char touch, int w) { return w == W_X ? (touch & 1) : w == W_Y ? (touch & 2) >> 1 : touch != 0; }

/* The nodes' adjacency (gl->adj from gl->adj_start: each node, itself included, sorted): the
 * pairs' grains and particles, every particle with every other (the host), every wall DOF with
 * every other, and the grains touching walls with the wall DOFs that move them (gl->touch). */
static gb_status node_adjacency(gb_global *gl, const gb_pair_set *P, gb_error *err)
{
    int n = gl->n, np = gl->np, nodes = gl->nodes;
    memset(gl->touch, 0, (size_t)n);
    for (int k = 0; k < P->n; k++) {
        const gb_pair *p = &P->p[k];
        if (p->j < 0 && !GB_IS_PARTICLE(p->j)) {
            int w = -1 - p->j;
            gl->touch[p->i] |= (w == GB_WALL_LEFT || w == GB_WALL_RIGHT) ? 1 : 2;
        }
    }
    /* Degrees, then the lists. */
    int *deg = gl->adj_start;
    memset(deg, 0, ((size_t)nodes + 1) * sizeof(int));
    for (int v = 0; v < nodes; v++) deg[v + 1] = 1;                    /* itself */
    for (int e = 0; e < np; e++) deg[n + e + 1] += np - 1;              /* the host couples all particles */
    for (int w = 0; w < NW; w++) deg[wall_node(gl, w) + 1] += NW - 1;   /* and all wall DOFs */
    for (int k = 0; k < P->n; k++) {
        const gb_pair *p = &P->p[k];
        if (p->j >= 0) deg[p->i + 1]++, deg[p->j + 1]++;
        else if (GB_IS_PARTICLE(p->j)) deg[p->i + 1]++, deg[n + GB_PARTICLE_OF(p->j) + 1]++;
    }
    for (int i = 0; i < n; i++)
        for (int w = 0; w < NW; w++)
            if (couples(gl->touch[i], w)) deg[i + 1]++, deg[wall_node(gl, w) + 1]++;
    for (int v = 0; v < nodes; v++) deg[v + 1] += deg[v];
    int total = deg[nodes];
    if (total > gl->adj_cap) {
        int *a = realloc(gl->adj, (size_t)total * sizeof(int)), *o = realloc(gl->adj_off, (size_t)total * sizeof(int));
        if (!a || !o) return gb_fail(err, GB_ENOMEM, "out of memory for the sparsity pattern");
        gl->adj = a, gl->adj_off = o, gl->adj_cap = total;
    }
    int *fill = gl->collen; /* a cursor per node, for now */
    for (int v = 0; v < nodes; v++) fill[v] = deg[v];
    for (int v = 0; v < nodes; v++) gl->adj[fill[v]++] = v;
    for (int e = 0; e < np; e++)
        for (int f = 0; f < np; f++)
            if (f != e) gl->adj[fill[n + e]++] = n + f;
    for (int w = 0; w < NW; w++)
        for (int u = 0; u < NW; u++)
            if (u != w) gl->adj[fill[wall_node(gl, w)]++] = wall_node(gl, u);
    for (int k = 0; k < P->n; k++) {
        const gb_pair *p = &P->p[k];
        int j = p->j >= 0 ? p->j : GB_IS_PARTICLE(p->j) ? n + GB_PARTICLE_OF(p->j) : -1;
        if (j < 0) continue;
        gl->adj[fill[p->i]++] = j;
        gl->adj[fill[j]++] = p->i;
    }
    for (int i = 0; i < n; i++)
        for (int w = 0; w < NW; w++)
            if (couples(gl->touch[i], w)) {
                gl->adj[fill[i]++] = wall_node(gl, w);
                gl->adj[fill[wall_node(gl, w)]++] = i;
            }
    for (int v = 0; v < nodes; v++) qsort(gl->adj + deg[v], (size_t)(deg[v + 1] - deg[v]), sizeof(int), cmp_int);
    return GB_OK;
}

/* The matrix's pattern from the adjacency: its column starts (Ap) and row indices (Ai), each node's
 * column block as long as its neighbours' DOFs. */
static gb_status matrix_pattern(gb_global *gl, gb_error *err)
{
    const int *deg = gl->adj_start;
    int nodes = gl->nodes;
    int nnz = 0;
    for (int v = 0; v < nodes; v++) {
        int off = 0;
        for (int q = deg[v]; q < deg[v + 1]; q++) gl->adj_off[q] = off, off += node_dofs(gl, gl->adj[q]);
        gl->collen[v] = off;
        gl->colstart[v] = nnz;
        for (int b = 0; b < node_dofs(gl, v); b++) gl->Ap[gl->dof0[v] + b] = nnz + b * off;
        nnz += node_dofs(gl, v) * off;
    }
    gl->Ap[gl->ndof] = nnz;
    if (nnz > gl->cap) {
        int *ai = realloc(gl->Ai, (size_t)nnz * sizeof(int));
        double *ax = realloc(gl->Ax, (size_t)nnz * sizeof(double));
        if (!ai || !ax) return gb_fail(err, GB_ENOMEM, "out of memory for %d matrix entries", nnz);
        gl->Ai = ai, gl->Ax = ax, gl->cap = nnz;
    }
    gl->nnz = nnz;
    gl->stats.unknowns = gl->ndof, gl->stats.entries = nnz;
    for (int v = 0; v < nodes; v++)
        for (int b = 0; b < node_dofs(gl, v); b++) {
            int q = gl->Ap[gl->dof0[v] + b];
            for (int e = deg[v]; e < deg[v + 1]; e++)
                for (int a = 0; a < node_dofs(gl, gl->adj[e]); a++) gl->Ai[q++] = gl->dof0[gl->adj[e]] + a;
        }
    return GB_OK;
}

/* Where each pair's blocks (pos_ij, pos_ji) and each grain's coupling with a wall DOF go. */
static gb_status pair_positions(gb_global *gl, const gb_pair_set *P, gb_error *err)
{
    int n = gl->n;
    if (P->n > gl->pos_cap) {
        int *a = realloc(gl->pos_ij, (size_t)P->n * sizeof(int)), *b = realloc(gl->pos_ji, (size_t)P->n * sizeof(int));
        if (!a || !b) return gb_fail(err, GB_ENOMEM, "out of memory for the sparsity pattern");
        gl->pos_ij = a, gl->pos_ji = b, gl->pos_cap = P->n;
    }
    for (int k = 0; k < P->n; k++) {
        const gb_pair *p = &P->p[k];
        int j = p->j >= 0 ? p->j : GB_IS_PARTICLE(p->j) ? n + GB_PARTICLE_OF(p->j) : -1;
        gl->pos_ij[k] = j < 0 ? -1 : entry_of(gl, j, p->i);
        gl->pos_ji[k] = j < 0 ? -1 : entry_of(gl, p->i, j);
    }
    for (int i = 0; i < n; i++)
        for (int w = 0; w < NW; w++) {
            gl->wall_in_grain[w * (n + 1) + i] = couples(gl->touch[i], w) ? entry_of(gl, i, wall_node(gl, w)) : -1;
            gl->grain_in_wall[w * (n + 1) + i] = couples(gl->touch[i], w) ? entry_of(gl, wall_node(gl, w), i) : -1;
        }
    return GB_OK;
}

/* The pattern of the candidate pairs: it changes only when the pair list is rebuilt. */
static gb_status build_pattern(gb_global *gl, const gb_pair_set *P, gb_error *err)
{
    gb_status st = node_adjacency(gl, P, err);
    if (!st) st = matrix_pattern(gl, err);
    if (!st) st = pair_positions(gl, P, err);
    return st;
}

static gb_linear_matrix matrix_of(const gb_global *gl)
{
    return (gb_linear_matrix){.n = gl->ndof, .nnz = gl->nnz, .Ap = gl->Ap, .Ai = gl->Ai, .Ax = gl->Ax};
}

static gb_status analyse(gb_global *gl, gb_error *err)
{
    double t0 = gb_clock_seconds();
    gb_linear_matrix A = matrix_of(gl);
    gb_status st = gl->linear->analyse(gl->ls, &A, err);
    if (st) return st;
    gl->stats.analyses++;
    gl->stats.analyse += gb_clock_seconds() - t0;
    return GB_OK;
}

/* Factorises and solves K x = rhs; *singular if K was not positive definite (Cholesky) or was
 * singular, so that the caller can regularise further. */
static gb_status factor_solve(gb_global *gl, int *singular, gb_error *err)
{
    const gb_linear_backend *b = gl->linear;
    gb_linear_matrix A = matrix_of(gl);
    double t0 = gb_clock_seconds();
    gb_status st = b->factorise(gl->ls, &A, singular, err);
    gb_linear_stats last = b->statistics(gl->ls);
    gl->stats.factorisations++;
    gl->stats.factor_entries = last.factor_entries, gl->stats.factor_flops = last.factor_flops;
    gl->stats.factorise += gb_clock_seconds() - t0;
    if (st || *singular) return st;
    t0 = gb_clock_seconds();
    st = b->solve(gl->ls, &A, gl->rhs, gl->x, singular, err);
    gl->stats.ksp_iterations += b->statistics(gl->ls).iterations;
    gl->stats.solve += gb_clock_seconds() - t0;
    return st;
}

/* The system solved on the previous factorisation, where the backend can (a correction's: it
 * differs by a few contacts' kt); 1 if that converged. */
static int solve_on_factor(gb_global *gl, gb_error *err, gb_status *st)
{
    const gb_linear_backend *b = gl->linear;
    int converged = 0;
    *st = GB_OK;
    if (!b->solve_on_factor) return 0;
    gb_linear_matrix A = matrix_of(gl);
    double t0 = gb_clock_seconds();
    *st = b->solve_on_factor(gl->ls, &A, gl->rhs, gl->x, &converged, err);
    gl->stats.pcg_steps += b->statistics(gl->ls).iterations;
    gl->stats.solve += gb_clock_seconds() - t0;
    return !*st && converged;
}

/* The wall DOFs' residuals (force conjugate to each DOF minus its target, docs/method.md section 5):
 * stress control, (F_left + F_right) - 2 s2 H and (F_bottom + F_top) - 2 s1 W; constant mean
 * stress, ((s1 + s2)/2 - m0) (W H_ref + H W_ref), the mean-stress error times the area change per
 * unit isotropic strain. Unused DOFs (and all of them without walls) are held. */
static void wall_residuals(gb_global *gl, const gb_sim *sim, const gb_wall_control *wc)
{
    int d = gl->dof0[wall_node(gl, 0)];
    const double *f = sim->state.wall_force;
    const gb_box *b = &sim->state.box;
    double W = b->right - b->left, H = b->top - b->bottom;
    for (int w = 0; w < NW; w++) gl->held[d + w] = 1, gl->rhs[d + w] = 0;
    if (!sim->world.box) return;
    if (wc->mode == GB_WALLS_STRESS) {
        gl->held[d + W_X] = gl->held[d + W_Y] = 0;
        gl->rhs[d + W_X] = -(f[GB_WALL_LEFT] + f[GB_WALL_RIGHT] - 2 * wc->s2 * H);
        gl->rhs[d + W_Y] = -(f[GB_WALL_BOTTOM] + f[GB_WALL_TOP] - 2 * wc->s1 * W);
    } else if (wc->mode == GB_WALLS_MEAN) {
        gl->held[d + W_MEAN] = 0;
        gl->rhs[d + W_MEAN] = gb_gem_mean_stress_error(sim, wc) * (W * sim->ref_height + H * sim->ref_width);
    }
}

/* A test hook: with GB_DUMP_FIRST_SOLVE=FILE, the first solution of the process (one value a line)
 * is written to FILE if it does not exist yet, to compare linear solvers on the same system
 * (tests/petsc). */
static void dump_first_solution(gb_global *gl)
{
    const char *path = getenv("GB_DUMP_FIRST_SOLVE");
    gl->dumped = 1;
    FILE *f = path ? fopen(path, "wx") : NULL;
    if (!f) return;
    for (int k = 0; k < gl->ndof; k++) fprintf(f, "%.17g\n", gl->x[k]);
    fclose(f);
}

/* Holds what the system does not move, sets the right-hand side -F, assembles with the damping mu
 * and solves (analysing first on a new pattern), regularising a singular matrix. */
static gb_status solve_system(gb_global *gl, const gb_sim *sim, const unsigned char *in_system, const gb_wall_control *wc,
                              double mu, int new_pattern, int reuse_factor, gb_error *err)
{
    gb_status st;
    double t0 = gb_clock_seconds();
    int n = gl->n, np = gl->np;
    for (int i = 0; i < n; i++) {
        int out = !in_system[i];
        gl->held[3 * i] = gl->held[3 * i + 1] = (unsigned char)out;
        gl->held[3 * i + 2] = (unsigned char)(out || in_system[i] == GB_IN_SYSTEM_NO_ROTATION ||
                                              !(gl->S[6 * i + 5] > 0)); /* no rotational stiffness */
        for (int a = 0; a < 3; a++) gl->rhs[3 * i + a] = gl->held[3 * i + a] ? 0 : -sim->scratch.F[3 * i + a];
    }
    int rigid = sim->scene->host.rigid; /* a rigid cavity: its particles are held */
    for (int e = 0; e < np; e++)
        for (int a = 0; a < 2; a++) {
            int d = gl->dof0[n + e] + a;
            gl->held[d] = (unsigned char)rigid;
            gl->rhs[d] = rigid ? 0 : -sim->scratch.bp_F[2 * e + a];
        }
    wall_residuals(gl, sim, wc);
    double shift = fmax(mu, REGULARISE), cap = fmax(1e3 * shift, 1e-3);
    gb_global_assemble(gl, sim, shift);
    gl->stats.assemble += gb_clock_seconds() - t0;
    /* UMFPACK's symbolic analysis reads the values too: analyse the assembled matrix. */
    if (new_pattern && (st = analyse(gl, err))) return st;
    if (reuse_factor) {
        int done = solve_on_factor(gl, err, &st);
        if (st) return st;
        if (done) {
            gl->stats.pcg_solves++;
            return GB_OK;
        }
    }
    for (;;) {
        int singular;
        if ((st = factor_solve(gl, &singular, err))) return st;
        if (!singular) break;
        if (shift >= cap)
            return gb_fail(err, GB_ENUMERIC, "the contact stiffness stays singular after a relative diagonal shift "
                                             "of %g", shift);
        shift *= 10;
        gl->stats.regularised++;
        t0 = gb_clock_seconds();
        gb_global_assemble(gl, sim, shift);
        gl->stats.assemble += gb_clock_seconds() - t0;
    }
    if (!gl->dumped) dump_first_solution(gl);
    return GB_OK;
}

/* A resumed run: the checkpoint's flags replace the zeros of the new pattern if the pair list is the
 * one they were saved for (no rebuild since), as if the pattern had never been lost. */
static void resume_unloading(gb_global *gl, const gb_pair_set *P)
{
    if (gl->resumed_of == P->generation && P->n) memcpy(gl->unloading, gl->resumed, (size_t)P->n);
    free(gl->resumed);
    gl->resumed = NULL;
}

const unsigned char *gb_global_unloading(const gb_global *gl, const gb_pair_set *P)
{
    return gl->pattern_of == P->generation && P->n ? gl->unloading : NULL;
}

gb_status gb_global_resume(gb_global *gl, const gb_pair_set *P, const unsigned char *unloading, gb_error *err)
{
    free(gl->resumed);
    gl->resumed = NULL;
    gl->pattern_of = -1;
    if (!unloading || !P->n) return GB_OK;
    if (!(gl->resumed = malloc((size_t)P->n))) return gb_fail(err, GB_ENOMEM, "out of memory");
    memcpy(gl->resumed, unloading, (size_t)P->n);
    gl->resumed_of = P->generation;
    return GB_OK;
}

/* A sliding contact has no tangential stiffness in K (it slides on), but if the solution moves it
 * back, it sticks again with its spring kt: Newton's step, blind to that, overshoots, and the
 * contact flips between sliding and sticking from one iteration to the next. Such contacts get kt
 * (an active set): if they are few, at once, the system solved once more by conjugate gradients on
 * the first factor where the linear solver can (solve_on_factor: CG needs about one step per
 * contact changed); if they are many (dozens at 1e5 grains), from the next iteration on, which
 * costs fewer factorisations than a second one now (1e5 jammed discs: 67 instead of 97 for a load
 * step, 43 s instead of 61 s; 1e4: even). They keep kt until a solution loads them again in their
 * sliding direction. Returns how many the solution gl->x unloads now. */
static int unload_sliding(gb_global *gl, const gb_sim *sim)
{
    int unloaded = 0, n = gl->n;
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        if (!(p->d > 0) || !(gb_sim_material(sim, p->j)->kt > 0) || p->pt == 0) continue;
        if (p->j < 0 && !GB_IS_PARTICLE(p->j)) continue; /* walls: moved by their own DOFs */
        if (gl->kt[k] > 0 && !gl->unloading[k]) continue;
        double b[3] = {0, 0, 0};
        if (p->j >= 0) memcpy(b, &gl->x[3 * p->j], sizeof b);
        else memcpy(b, &gl->x[gl->dof0[n + GB_PARTICLE_OF(p->j)]], 2 * sizeof(double));
        double load = gb_pair_du_t(p, &gl->x[3 * p->i], b) * p->pt;
        if (gl->unloading[k]) {
            if (load > 0) gl->unloading[k] = 0;
            continue;
        }
        if (load < 0) gl->stick[k] = 1, gl->unloading[k] = 1, unloaded++;
    }
    return unloaded;
}

/* The moves from the solution gl->x, scaled down as a whole if a grain or particle would move more
 * than max_move (a share of its radius), and the reference cases for the held grains. With the
 * line search, a grain that would then turn by more than TURN_MOVES max_move rad does not
 * turn: two touching grains whose other contacts all slide roll on each other (r1 dw1 = -r2
 * dw2 leaves their contact unstrained) at no stiffness, a mechanism that the solve answers
 * with any turn (up to 3.8e5 rad in 30 runs of the localisation statistics, 1 606 moves; other
 * moves turn a grain by at most 0.28 rad there, the mechanism's mildest by 0.31-0.78). Scaled
 * to the bound, such a turn is still arbitrary (the smoother then starts from a pair rolled by
 * 1 rad); held, it is left to the smoother, which sees the contacts' laws
 * (tests/unit/test_rolling_mechanism.c). The damped solver has no smoother: held, the pair of
 * tests/hybrid/load_grains.yaml stalls it (it converges after turning by 2.1e5 rad). */
static void set_moves(const gb_global *gl, gb_sim *sim, const unsigned char *in_system)
{
    int n = gl->n, np = gl->np;
    const gb_solver_settings *sv = gl->set;
    double worst = 0;
    for (int i = 0; i < n; i++) worst = fmax(worst, hypot(gl->x[3 * i], gl->x[3 * i + 1]) / sim->state.g[i].r);
    for (int e = 0; e < np; e++) {
        const double *x = &gl->x[gl->dof0[n + e]];
        worst = fmax(worst, hypot(x[0], x[1]) / sim->bp.r[e]);
    }
    double a = sv->global_alpha, scale = worst * a > sv->max_move ? sv->max_move / worst : a;
    for (int i = 0; i < n; i++) {
        double *d = &sim->scratch.dX[3 * i];
        if (!in_system[i]) {
            gb_gem_grain_move(sim, i, d);
            continue;
        }
        for (int q = 0; q < 3; q++) d[q] = gl->held[3 * i + q] ? 0 : scale * gl->x[3 * i + q];
        if (sv->newton == GB_NEWTON_LINE_SEARCH && fabs(d[2]) > TURN_MOVES * sv->max_move * sim->state.g[i].r)
            d[2] = 0; /* d[2] = r dw */
    }
    for (int e = 0; e < np; e++)
        for (int q = 0; q < 2; q++) sim->bp.dx[2 * e + q] = scale * gl->x[gl->dof0[n + e] + q];
    memset(sim->scratch.wall_dx, 0, sizeof sim->scratch.wall_dx);
    int d = gl->dof0[wall_node(gl, 0)];
    for (int w = 0; w < NW; w++) {
        if (gl->held[d + w]) continue;
        double v = scale * gl->x[d + w];
        for (int wall = 0; wall < GB_N_WALLS; wall++) {
            double in = v * gb_global_wall_lever(sim, w, wall);
            if (wall == GB_WALL_LEFT) sim->scratch.wall_dx[wall][0] += in;
            if (wall == GB_WALL_RIGHT) sim->scratch.wall_dx[wall][0] -= in;
            if (wall == GB_WALL_BOTTOM) sim->scratch.wall_dx[wall][1] += in;
            if (wall == GB_WALL_TOP) sim->scratch.wall_dx[wall][1] -= in;
        }
    }
}

gb_status gb_global_moves(gb_global *gl, gb_sim *sim, const unsigned char *in_system, const gb_wall_control *wc,
                          double mu, gb_error *err)
{
    gb_status st;
    /* The linear solver, made at the first move (PETSc's starts MPI): the scene's settings and the
     * matrix's symmetry are known then. */
    if (!gl->ls) {
        gl->symmetric = gb_linear_symmetric(gl->linear, gl->set);
        if ((st = gl->linear->create(gl->set, gl->symmetric, &gl->ls, err))) return st;
    }
    double t0 = gb_clock_seconds();
    gl->stats.moves++;
    int new_pattern = gl->pattern_of != sim->state.pairs.generation;
    if (new_pattern) {
        if ((st = build_pattern(gl, &sim->state.pairs, err))) return st;
        gl->pattern_of = sim->state.pairs.generation;
    }
    if ((st = gb_global_pair_buffers(gl, &sim->state.pairs, err))) return st;
    if (new_pattern && sim->state.pairs.n) memset(gl->unloading, 0, (size_t)sim->state.pairs.n);
    if (gl->resumed) resume_unloading(gl, &sim->state.pairs);
    /* A grain with a single contact in the system keeps that contact's kt (see gb_solver_mark_system). */
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        int single_i = in_system[p->i] >= GB_IN_SYSTEM_NO_ROTATION; /* NO_ROTATION or SINGLE */
        int single_j = p->j >= 0 && in_system[p->j] >= GB_IN_SYSTEM_NO_ROTATION;
        gl->stick[k] = p->d > 0 && (gl->unloading[k] || single_i || single_j);
    }
    gb_global_tangents(gl, sim);
    gl->stats.assemble += gb_clock_seconds() - t0;
    if ((st = solve_system(gl, sim, in_system, wc, mu, new_pattern, 0, err))) return st;
    int unloaded = unload_sliding(gl, sim);
    if (unloaded && unloaded <= GB_LINEAR_ON_FACTOR_MAX / 2) {
        t0 = gb_clock_seconds();
        gb_global_tangents(gl, sim);
        gl->stats.assemble += gb_clock_seconds() - t0;
        if ((st = solve_system(gl, sim, in_system, wc, mu, 0, 1, err))) return st;
        gl->stats.corrections++;
    }
    set_moves(gl, sim, in_system);
    return GB_OK;
}
