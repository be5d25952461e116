/* The reference iteration of the granular element method (Kishino 1989, section 2.5, Fig. 1). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "gem/sim.h"

/* A 3x3 contact stiffness counts as singular below this fraction of the product of its diagonal
 * (Hadamard's bound for a positive semi-definite matrix): exactly singular only when kt = 0. */
static const double SINGULAR_REL = 1e-10;

const gb_material *gb_sim_material(const gb_sim *sim, int j)
{
    const gb_scene *s = sim->scene;
    switch (gb_pair_end(j)) {
    case GB_END_GRAIN: return &s->grain_grain;
    case GB_END_WALL: return &s->grain_wall;
    default: return &s->grain_boundary;
    }
}

double gb_sim_tan_phi(const gb_sim *sim, int j)
{
    switch (gb_pair_end(j)) {
    case GB_END_GRAIN: return sim->tan_phi_gg;
    case GB_END_WALL: return sim->tan_phi_gw;
    default: return sim->tan_phi_gb;
    }
}

/* What a contact adds to its ends (K 5, 8, 25). */
typedef struct {
    double c, s, kn, kt, kr, pn, pt, mr, fx, fy, s00, s01, s11;
    int rolling;
} contact_terms;

static inline void contact_terms_of(const gb_sim *sim, const gb_pair *p, contact_terms *t)
{
    const gb_material *mat = gb_sim_material(sim, p->j);
    double c = p->nx, s = p->ny, kn = mat->kn, kt = mat->kt;
    /* (K 8): S = sum T^t S_c T with T = [[c, s, 0], [-s, c, 1]] (K 2) */
    t->c = c, t->s = s, t->kn = kn, t->kt = kt;
    t->s00 = kn * c * c + kt * s * s, t->s01 = (kn - kt) * c * s, t->s11 = kn * s * s + kt * c * c;
    t->pn = p->pn, t->pt = p->pt;
    gb_pair_force(p, t->pn, t->pt, &t->fx, &t->fy);
    /* Rolling resistance (docs/method.md section 3.1): the moment mr on i, -mr on j; in the DOF
     * r w its stiffness is kr / r^2, kept at the cap as kt is (K 8). */
    t->mr = p->mr, t->kr = mat->kr;
    t->rolling = mat->kr > 0; /* without, no divisions: they are a good part of a contact's cost */
}

/* A contact's terms added to grain g, its side i (side 1) or j (side -1: B's block T' = [[-c, -s,
 * 0], [s, -c, 1]] (K 25), the same moment, the opposite force): negating is exact, so a grain gets
 * the same bits from either end. */
static inline void add_to_grain(gb_sim *sim, int g, const contact_terms *t, double side)
{
    double r = sim->state.g[g].r, *F = &sim->scratch.F[3 * g], *S = &sim->scratch.S[6 * g];
    F[0] += side * t->fx, F[1] += side * t->fy, F[2] += t->rolling ? t->pt - side * t->mr / r : t->pt;
    S[0] += t->s00, S[1] += t->s01, S[2] += -side * t->kt * t->s, S[3] += t->s11, S[4] += side * t->kt * t->c;
    S[5] += t->rolling ? t->kt + t->kr / (r * r) : t->kt;
    sim->scratch.nc[g]++;
    double *one = &sim->scratch.one[GB_ONE * g];
    one[0] = side * t->c, one[1] = side * t->s, one[2] = t->kn, one[3] = t->kr;
}

/* A contact's terms added to its other end when that is a boundary particle or a wall. */
static inline void add_to_boundary(gb_sim *sim, int j, const contact_terms *t)
{
    if (GB_IS_PARTICLE(j)) {
        /* A boundary particle: the translational part of T' (K 25). */
        int e = GB_PARTICLE_OF(j);
        sim->scratch.bp_F[2 * e] -= t->fx, sim->scratch.bp_F[2 * e + 1] -= t->fy;
        sim->scratch.bp_S[3 * e] += t->s00, sim->scratch.bp_S[3 * e + 1] += t->s01, sim->scratch.bp_S[3 * e + 2] += t->s11;
    } else {
        int w = -1 - j;
        sim->state.wall_force[w] += t->pn;
        sim->scratch.wall_k[w] += t->kn;
    }
}

/* The forces before any contact: the body forces (K 5: F = sum T^t P - B), and on boundary
 * particles the force K u + f0 that their displacement asks of the host. */
static void reset_boundary(gb_sim *sim)
{
    for (int w = 0; w < GB_N_WALLS; w++) sim->state.wall_force[w] = sim->scratch.wall_k[w] = 0;
    if (sim->host) {
        memcpy(sim->scratch.bp_F, sim->host->force, (size_t)sim->host->m * sizeof(double));
        memset(sim->scratch.bp_S, 0, 3 * (size_t)sim->bp.n * sizeof(double));
    }
}

static inline void reset_grain(gb_sim *sim, int i)
{
    double *F = &sim->scratch.F[3 * i];
    F[0] = -sim->body[2 * i], F[1] = -sim->body[2 * i + 1], F[2] = 0;
    memset(&sim->scratch.S[6 * i], 0, 6 * sizeof(double));
    sim->scratch.nc[i] = 0;
}

static void reset_forces(gb_sim *sim)
{
    reset_boundary(sim);
    for (int i = 0; i < sim->state.n; i++) reset_grain(sim, i);
}

/* Solves the symmetric 2x2 system [a b; b c] x = f, or returns 0 if it is singular. */
static int solve2(double a, double b, double c, const double f[2], double x[2])
{
    double det = a * c - b * b;
    if (!(det > SINGULAR_REL * a * c) || !(a > 0) || !(c > 0)) return 0;
    x[0] = (c * f[0] - b * f[1]) / det;
    x[1] = (a * f[1] - b * f[0]) / det;
    return 1;
}

void gb_gem_grain_move(const gb_sim *sim, int i, double dX[3])
{
    const gb_solver_settings *sv = &sim->scene->solver;
    const double *F = &sim->scratch.F[3 * i], *S = &sim->scratch.S[6 * i], *B = &sim->body[2 * i];
    double kn = sim->scene->grain_grain.kn;
    int nc = sim->scratch.nc[i];
    dX[0] = dX[1] = dX[2] = 0;
    if (nc == 0) {
        /* b) no contact: drift along the body force (K 10). */
        dX[0] = sv->beta * B[0] / kn;
        dX[1] = sv->beta * B[1] / kn;
        return;
    }
    /* With rolling resistance (docs/method.md section 3.1) one contact holds a grain in all three
     * directions (kn, kt and kr: S is regular) and can hold it against its weight, as a block on a
     * slope: case a). Rolling it over by case c) would keep the tangential force that its lost
     * neighbours left, which nothing else relaxes. */
    if (nc == 1 && !(sim->scratch.one[GB_ONE * i + 3] > 0)) {
        /* c) one contact (K 11): normal move by the normal stiffness; tangentially the grain rolls
         * over its neighbour under the body force. Rolling means du_t = 0, i.e. r dw = -(dx.t): the
         * printed third row (0, 1) of (K 11) contradicts the paper's own du_t = 0, we keep du_t = 0. */
        const double *one = &sim->scratch.one[GB_ONE * i];
        double c = one[0], s = one[1], knc = one[2];
        double a = -sv->alpha1 * (F[0] * c + F[1] * s) / knc;
        double b = sv->beta1 * (-B[0] * s + B[1] * c) / knc;
        dX[0] = c * a - s * b;
        dX[1] = s * a + c * b;
        dX[2] = -b;
        return;
    }
    /* a) det S != 0: dX = -alpha S^-1 F (K 9), by Cramer's rule on the symmetric 3x3. */
    double s00 = S[0], s01 = S[1], s02 = S[2], s11 = S[3], s12 = S[4], s22 = S[5];
    double c00 = s11 * s22 - s12 * s12, c01 = s02 * s12 - s01 * s22, c02 = s01 * s12 - s02 * s11;
    double det = s00 * c00 + s01 * c01 + s02 * c02;
    if (det > SINGULAR_REL * s00 * s11 * s22 && s22 > 0) {
        double c11 = s00 * s22 - s02 * s02, c12 = s01 * s02 - s00 * s12, c22 = s00 * s11 - s01 * s01;
        double k = -sv->alpha / det;
        dX[0] = k * (c00 * F[0] + c01 * F[1] + c02 * F[2]);
        dX[1] = k * (c01 * F[0] + c11 * F[1] + c12 * F[2]);
        dX[2] = k * (c02 * F[0] + c12 * F[1] + c22 * F[2]);
        return;
    }
    /* d) det S = 0 with two or more contacts (kt = 0): lock the rotation and solve the
     * translational block (K 12). */
    double x[2];
    if (solve2(s00, s01, s11, F, x)) {
        dX[0] = -sv->alpha * x[0];
        dX[1] = -sv->alpha * x[1];
        return;
    }
    /* All contact normals are parallel (kt = 0): the block has rank one. Move along the normal by
     * its stiffness as in d), and along the free direction with the body force as in b). */
    double tr = s00 + s11;
    double ex = s00 >= s11 ? 1 : 0, ey = 1 - ex;
    if (tr > 0) {
        double nrm = hypot(s00, s01);
        if (s00 >= s11 && nrm > 0) ex = s00 / nrm, ey = s01 / nrm;
        else if ((nrm = hypot(s01, s11)) > 0) ex = s01 / nrm, ey = s11 / nrm;
    }
    double fn = F[0] * ex + F[1] * ey, bt = -B[0] * ey + B[1] * ex;
    double an = -sv->alpha * fn / tr, at = sv->beta * bt / kn;
    dX[0] = an * ex - at * ey;
    dX[1] = an * ey + at * ex;
}

/* sum over grains of F.dX with the current F and dX */
double gb_gem_fixing_work(const gb_sim *sim)
{
    double w = 0;
    for (int k = 0; k < 3 * sim->state.n; k++) w += sim->scratch.F[k] * sim->scratch.dX[k];
    return w;
}

void gb_gem_stress_residuals(const gb_sim *sim, const gb_wall_control *wc, double t[2])
{
    const gb_box *b = &sim->state.box;
    const double *f = sim->state.wall_force;
    t[0] = wc->s2 * (b->top - b->bottom) - 0.5 * (f[GB_WALL_LEFT] + f[GB_WALL_RIGHT]);
    t[1] = wc->s1 * (b->right - b->left) - 0.5 * (f[GB_WALL_BOTTOM] + f[GB_WALL_TOP]);
}

double gb_gem_mean_stress_error(const gb_sim *sim, const gb_wall_control *wc)
{
    const gb_box *b = &sim->state.box;
    const double *f = sim->state.wall_force;
    double s1 = (f[GB_WALL_BOTTOM] + f[GB_WALL_TOP]) / (2 * (b->right - b->left));
    double s2 = (f[GB_WALL_LEFT] + f[GB_WALL_RIGHT]) / (2 * (b->top - b->bottom));
    return wc->mean - 0.5 * (s1 + s2);
}

/* Wall moves of this iteration; returns the walls' residual force (0 for fixed walls). */
double gb_gem_wall_moves(gb_sim *sim, const gb_wall_control *wc)
{
    memset(sim->scratch.wall_dx, 0, sizeof sim->scratch.wall_dx);
    if (wc->mode == GB_WALLS_FIXED) return 0;
    const gb_box *b = &sim->state.box;
    double W = b->right - b->left, H = b->top - b->bottom;
    const double *k = sim->scratch.wall_k;
    /* A wall that touches nothing moves as if it had one grain-wall contact. */
    double kmin = sim->scene->grain_wall.kn;
    double dy, dx, residual;
    if (wc->mode == GB_WALLS_STRESS) {
        /* Each axis: the mean force of its two walls against the target stress times the side
         * (K section 2.6); the walls move symmetrically by their own stiffness, grains held. */
        double t[2];
        gb_gem_stress_residuals(sim, wc, t);
        double tx = t[0], ty = t[1];
        dy = ty / fmax(0.5 * (k[GB_WALL_BOTTOM] + k[GB_WALL_TOP]), kmin);
        dx = tx / fmax(0.5 * (k[GB_WALL_LEFT] + k[GB_WALL_RIGHT]), kmin);
        residual = fmax(fabs(ty), fabs(tx));
    } else {
        /* Constant mean stress: an isotropic strain de (de1 = de2) cancels the mean-stress error
         * by the walls' stiffness, leaving the imposed shear unchanged (K section 2.6). */
        double err = gb_gem_mean_stress_error(sim, wc);
        double ky = fmax(k[GB_WALL_BOTTOM] + k[GB_WALL_TOP], 2 * kmin);
        double kx = fmax(k[GB_WALL_LEFT] + k[GB_WALL_RIGHT], 2 * kmin);
        double dmean_de = 0.5 * (ky * sim->ref_height / (4 * W) + kx * sim->ref_width / (4 * H));
        double de = err / dmean_de;
        dy = 0.5 * de * sim->ref_height;
        dx = 0.5 * de * sim->ref_width;
        residual = fabs(err) * 0.5 * (W + H);
    }
    sim->scratch.wall_dx[GB_WALL_BOTTOM][1] = dy;
    sim->scratch.wall_dx[GB_WALL_TOP][1] = -dy;
    sim->scratch.wall_dx[GB_WALL_LEFT][0] = dx;
    sim->scratch.wall_dx[GB_WALL_RIGHT][0] = -dx;
    return residual;
}

/* Moves grains, boundary particles (and the host with them) and walls by dX, bp.dx and wall_dx, and
 * rebuilds the pair list if it may miss a contact now. The grains on solver.threads threads, their
 * drift since the list's rebuild measured as they move (a largest value: the same on any count). */
static gb_status move_bodies(gb_sim *sim, gb_error *err)
{
    double drift2 = 0;
    int n = sim->state.n, threads = sim->scene->solver.threads;
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1 && n >= GB_PARALLEL_GRAINS) reduction(max : drift2)
    for (int i = 0; i < n; i++) {
        gb_grain *g = &sim->state.g[i];
        const double *d = &sim->scratch.dX[3 * i];
        g->x += d[0];
        g->y += d[1];
        g->rot += d[2] / g->r;
        double d2 = gb_pairs_grain_drift2(&sim->state.pairs, &sim->world, i);
        if (d2 > drift2) drift2 = d2;
    }
    for (int e = 0; e < sim->bp.n; e++) {
        sim->bp.x[e] += sim->bp.dx[2 * e];
        sim->bp.y[e] += sim->bp.dx[2 * e + 1];
        sim->state.host.u[2 * e] += sim->bp.dx[2 * e];
        sim->state.host.u[2 * e + 1] += sim->bp.dx[2 * e + 1];
    }
    if (sim->host) gb_host_update_force(sim->host, &sim->state.host);
    gb_box *b = &sim->state.box;
    b->left += sim->scratch.wall_dx[GB_WALL_LEFT][0];
    b->right += sim->scratch.wall_dx[GB_WALL_RIGHT][0];
    b->bottom += sim->scratch.wall_dx[GB_WALL_BOTTOM][1];
    b->top += sim->scratch.wall_dx[GB_WALL_TOP][1];
    if (!(b->right > b->left) || !(b->top > b->bottom))
        return gb_fail(err, GB_ENUMERIC, "the box turned inside out (width %g, height %g): the load step is too "
                       "large for these springs", b->right - b->left, b->top - b->bottom);
    double t0 = gb_clock_seconds();
    gb_status st = gb_pairs_drift_stale(&sim->search, sqrt(drift2), gb_pairs_wall_drift(&sim->state.pairs, &sim->world))
                       ? gb_pairs_rebuild(&sim->state.pairs, &sim->search, &sim->world, err)
                       : GB_OK;
    sim->detect_seconds += gb_clock_seconds() - t0;
    return st;
}

/* The accounts of a move: the energy its contacts dissipated, and the walls' work, mean normal
 * force (before: `before`, after: `after`) times inward displacement. */
static void account_move(gb_sim *sim, double diss, const double before[GB_N_WALLS], const double after[GB_N_WALLS])
{
    double inward[GB_N_WALLS] = {sim->scratch.wall_dx[GB_WALL_LEFT][0], -sim->scratch.wall_dx[GB_WALL_RIGHT][0],
                                 sim->scratch.wall_dx[GB_WALL_BOTTOM][1], -sim->scratch.wall_dx[GB_WALL_TOP][1]};
    for (int w = 0; w < GB_N_WALLS; w++) sim->state.acc.work_walls_iter += 0.5 * (before[w] + after[w]) * inward[w];
    sim->state.acc.dissipation += diss;
    sim->state.acc.dissipation_step += diss;
}

/* Room for a move's per-pair dissipation (sim->scratch.pair_diss). */
static gb_status pair_diss_room(gb_sim *sim, gb_error *err)
{
    if (sim->state.pairs.n > sim->scratch.pair_diss_cap) {
        double *d = realloc(sim->scratch.pair_diss, (size_t)sim->state.pairs.cap * sizeof(double));
        if (!d) return gb_fail(err, GB_ENOMEM, "out of memory for %d pairs", sim->state.pairs.cap);
        sim->scratch.pair_diss = d, sim->scratch.pair_diss_cap = sim->state.pairs.cap;
    }
    return GB_OK;
}

/* Pair k updated to the moved bodies (K 6, 13, 25); returns the energy it dissipated. */
static inline double update_pair(gb_sim *sim, int k)
{
    gb_pair *p = &sim->state.pairs.p[k];
    return gb_pair_update(p, &sim->world, sim->scratch.dX, &sim->scratch.wall_dx[0][0], gb_sim_material(sim, p->j),
                          gb_sim_tan_phi(sim, p->j));
}

/* The pairs' update alone (gb_gem_apply_moves: the reference iteration sums the forces later) runs
 * on solver.threads OpenMP threads from GB_PARALLEL_PAIRS pairs: they are independent (each reads
 * the bodies and writes itself); what is summed over pairs is summed afterwards in the pairs'
 * order, so that every result is the same bits whatever the thread count. The smoother's moves
 * update the pairs in the pass that sums them (contact_sums). */
static int pairs_parallel(const gb_sim *sim)
{
    return sim->scene->solver.threads > 1 && sim->state.pairs.n >= GB_PARALLEL_PAIRS;
}

/* Updates every pair (update_pair); most of a reference iteration's time. */
static gb_status update_pairs(gb_sim *sim, gb_error *err)
{
    gb_status st = pair_diss_room(sim, err);
    if (st) return st;
    int n = sim->state.pairs.n, threads = sim->scene->solver.threads;
#pragma omp parallel for schedule(static) num_threads(threads) if (pairs_parallel(sim))
    for (int k = 0; k < n; k++) sim->scratch.pair_diss[k] = update_pair(sim, k);
    return GB_OK;
}

/* The contacts' sums in chunks of the pair list (from GB_PARALLEL_GRAINS grains, on solver.threads
 * threads), as FIRE's force loop (src/pack/fire.c): the list is sorted by (i, j) and the grains
 * numbered by cell (gb_grains_cell_order), so a grain pair's j - i is about two rows of grains;
 * chunk c holds the pairs whose i is in [c W, (c + 1) W), W more than the largest j - i, so that
 * its pairs add only to the grains of chunks c and c + 1: the even chunks run at once, then the odd
 * ones. The walls' and particles' sums (shared by every chunk) follow, in the list's order. W
 * depends on the list alone, so a grain's terms come in the same order, and its sums are the same
 * bits, on any thread count. Each contact's terms are computed once (gathering every grain's own
 * pairs would compute them from both ends and read the pairs out of order, which made two threads
 * little faster than one). */
enum { CHUNK_MIN = 256 };
/* Per chunk: its contacts' affine_k (3), the energy its pairs' updates dissipated. */
enum { CHUNK_SUMS = 4 };

/* sim->scratch's chunks for the current pair list; 0 without memory for them (the sums then
 * run in the list's order on one thread, other bits). */
static int chunks(gb_sim *sim)
{
    gb_sim_scratch *z = &sim->scratch;
    const gb_pair_set *P = &sim->state.pairs;
    if (z->chunk && z->chunk_of == P->generation) return 1;
    int width = CHUNK_MIN, n = sim->state.n, edges = 0;
    for (int k = 0; k < P->n; k++) {
        if (P->p[k].j >= 0 && P->p[k].j - P->p[k].i >= width) width = P->p[k].j - P->p[k].i + 1;
        edges += P->p[k].j < 0;
    }
    int m = (n + width - 1) / width;
    if (m + 1 > z->chunk_cap) {
        int *q = realloc(z->chunk, ((size_t)m + 1) * sizeof(int));
        if (q) z->chunk = q;
        double *a = q ? realloc(z->chunk_sums, CHUNK_SUMS * ((size_t)m + 1) * sizeof(double)) : NULL;
        if (!a) return 0;
        z->chunk_sums = a, z->chunk_cap = m + 1;
    }
    if (edges > z->edge_cap) {
        int *q = realloc(z->edge, (size_t)edges * sizeof(int));
        if (!q) return 0;
        z->edge = q, z->edge_cap = edges;
    }
    for (int c = 0, k = 0; c <= m; c++) {
        while (k < P->n && P->p[k].i < c * width) k++;
        z->chunk[c] = k;
    }
    z->chunk[m] = P->n;
    z->n_edges = 0;
    for (int k = 0; k < P->n; k++)
        if (P->p[k].j < 0) z->edge[z->n_edges++] = k;
    z->n_chunks = m, z->chunk_of = P->generation;
    return 1;
}

/* A touching contact's terms of sim->scratch.affine_k added to k. */
static inline void add_affine(const gb_sim *sim, const gb_pair *p, const contact_terms *t, double k[3])
{
    const gb_grain *g = sim->state.g;
    double lx = p->j >= 0 ? g[p->j].x - g[p->i].x : g[p->i].r * t->c;
    double ly = p->j >= 0 ? g[p->j].y - g[p->i].y : g[p->i].r * t->s;
    double cx = t->c * lx, sx = t->s * lx, cy = t->c * ly, sy = t->s * ly; /* t = (-s, c) */
    k[0] += t->kn * cx * cx + t->kt * sx * sx;
    k[1] += t->kn * sy * sy + t->kt * cy * cy;
    k[2] += (t->kn - t->kt) * cx * sy;
}

/* A touching contact's force and stiffness (K 5, 8, 25) added to its grains (both when j is a
 * grain), with `boundary` to its wall or particle too, and its affine terms to k. */
static inline void add_contact(gb_sim *sim, const gb_pair *p, int boundary, double k[3])
{
    contact_terms t;
    contact_terms_of(sim, p, &t);
    add_to_grain(sim, p->i, &t, 1);
    if (p->j >= 0) add_to_grain(sim, p->j, &t, -1);
    else if (boundary) add_to_boundary(sim, p->j, &t);
    add_affine(sim, p, &t, k);
}

/* The forces and stiffnesses of every contact (K 5, 8), with `update` each pair first updated to
 * the bodies' moves (update_pair); returns the energy the updates dissipated, summed by chunks
 * (in the list's order on one thread: a serial pass over the pairs for it alone cost some 5 % of a
 * smoother step at 1e6 discs). */
static double contact_sums(gb_sim *sim, int update)
{
    gb_sim_scratch *z = &sim->scratch;
    gb_pair *P = sim->state.pairs.p;
    int n = sim->state.n, np = sim->state.pairs.n, threads = sim->scene->solver.threads;
    double diss = 0, *ka = z->affine_k;
    ka[0] = ka[1] = ka[2] = 0;
    if (n < GB_PARALLEL_GRAINS || !chunks(sim)) {
        reset_forces(sim);
        for (int k = 0; k < np; k++) {
            if (update) diss += update_pair(sim, k);
            if (P[k].d > 0) add_contact(sim, &P[k], 1, ka);
        }
        return diss;
    }
    int par = threads > 1;
    reset_boundary(sim);
#pragma omp parallel for schedule(static) num_threads(threads) if (par)
    for (int i = 0; i < n; i++) reset_grain(sim, i);
    for (int first = 0; first < 2; first++) {
        int half = (z->n_chunks - first + 1) / 2;
#pragma omp parallel for schedule(static) num_threads(threads) if (par)
        for (int q = 0; q < half; q++) {
            int c = first + 2 * q;
            double *kc = &z->chunk_sums[CHUNK_SUMS * c], d = 0;
            kc[0] = kc[1] = kc[2] = 0;
            for (int k = z->chunk[c]; k < z->chunk[c + 1]; k++) {
                if (update) d += update_pair(sim, k);
                if (P[k].d > 0) add_contact(sim, &P[k], 0, kc);
            }
            kc[3] = d;
        }
    }
    for (int c = 0; c < z->n_chunks; c++) {
        for (int q = 0; q < 3; q++) ka[q] += z->chunk_sums[CHUNK_SUMS * c + q];
        diss += z->chunk_sums[CHUNK_SUMS * c + 3];
    }
    for (int e = 0; e < z->n_edges; e++) {
        const gb_pair *p = &P[z->edge[e]];
        if (!(p->d > 0)) continue;
        contact_terms t;
        contact_terms_of(sim, p, &t);
        add_to_boundary(sim, p->j, &t);
    }
    return diss;
}

void gb_gem_forces(gb_sim *sim) { contact_sums(sim, 0); }

gb_status gb_gem_apply_moves(gb_sim *sim, gb_error *err)
{
    gb_status st = move_bodies(sim, err);
    if (!st) st = update_pairs(sim, err);
    if (st) return st;
    double diss = 0, wall_after[GB_N_WALLS] = {0, 0, 0, 0};
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        diss += sim->scratch.pair_diss[k];
        if (p->j < 0 && !GB_IS_PARTICLE(p->j)) wall_after[-1 - p->j] += p->pn;
    }
    account_move(sim, diss, sim->state.wall_force, wall_after);
    return GB_OK;
}

gb_status gb_gem_move_and_forces(gb_sim *sim, gb_error *err)
{
    double wall_before[GB_N_WALLS];
    memcpy(wall_before, sim->state.wall_force, sizeof wall_before);
    gb_status st = move_bodies(sim, err);
    if (st) return st;
    account_move(sim, contact_sums(sim, 1), wall_before, sim->state.wall_force);
    return GB_OK;
}

/* The merit of a configuration: squared fixing forces of the grains that the system moves (those
 * with two contacts or more before the move: the others move by the reference cases, whatever the
 * damping), of the boundary particles, and the walls' residual. */
double gb_gem_merit(const gb_sim *sim, const unsigned char *in_system, double wall_residual)
{
    double m = wall_residual * wall_residual;
    for (int i = 0; i < sim->state.n; i++)
        if (in_system[i])
            for (int k = 3 * i; k < 3 * i + 3; k++) m += sim->scratch.F[k] * sim->scratch.F[k];
    return gb_gem_particle_merit(sim, m);
}

double gb_gem_particle_merit(const gb_sim *sim, double m)
{
    for (int k = 0; k < 2 * sim->bp.n && !sim->scene->host.rigid; k++) m += sim->scratch.bp_F[k] * sim->scratch.bp_F[k];
    return m;
}

/* NaN propagates: a force that became NaN is the largest (gb_gem_balance stops on it). */
static double nan_max(double a, double b) { return a > b || a != a ? a : b; }

double gb_gem_largest_grain_force2(const gb_sim *sim)
{
    double max2 = 0;
    for (int i = 0; i < sim->state.n; i++) max2 = nan_max(gb_gem_force2(sim, i), max2);
    return max2;
}

double gb_gem_largest_particle_force2(const gb_sim *sim)
{
    double max2 = 0;
    for (int k = 0; k < sim->bp.n && !sim->scene->host.rigid; k++)
        max2 = nan_max(sim->scratch.bp_F[2 * k] * sim->scratch.bp_F[2 * k] + sim->scratch.bp_F[2 * k + 1] * sim->scratch.bp_F[2 * k + 1], max2);
    return max2;
}

int gb_gem_balance(gb_sim *sim, const gb_wall_control *wc, double *max_force, double *wall_residual, gb_error *err,
                   gb_status *st)
{
    *st = GB_OK;
    gb_gem_forces(sim);
    double g2 = gb_gem_largest_grain_force2(sim), p2 = gb_gem_largest_particle_force2(sim);
    *max_force = sqrt(g2 != g2 || p2 > g2 ? p2 : g2);
    /* Energy absorbed by the fixing forces (the "hand" that holds each grain) over a move, by the
     * trapezoid rule: the springs' energy changes by sum (F + B).dX + walls' work - dissipation,
     * so -sum F.dX is what the quasi-static iteration loses where a dynamic system would damp. */
    if (sim->state.acc.half_pending) sim->state.acc.relaxation -= 0.5 * gb_gem_fixing_work(sim);
    sim->state.acc.half_pending = 0;
    *wall_residual = gb_gem_wall_moves(sim, wc);
    if (!isfinite(*max_force) || !isfinite(*wall_residual)) {
        *st = gb_fail(err, GB_ENUMERIC, "a fixing force became non-finite");
        return 0;
    }
    double a = sim->accuracy; /* the load step's (src/gem/accuracy.c) */
    if (*max_force <= a && *wall_residual <= a) { /* (K 14) */
        memset(sim->scratch.wall_dx, 0, sizeof sim->scratch.wall_dx);
        return 1;
    }
    return 0;
}

gb_status gb_gem_reference_move(gb_sim *sim, gb_error *err)
{
    int n = sim->state.n, threads = sim->scene->solver.threads;
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1 && n >= GB_PARALLEL_GRAINS)
    for (int i = 0; i < n; i++) gb_gem_grain_move(sim, i, &sim->scratch.dX[3 * i]);
    sim->state.acc.relaxation -= 0.5 * gb_gem_fixing_work(sim);
    sim->state.acc.half_pending = 1;
    return gb_gem_apply_moves(sim, err);
}
