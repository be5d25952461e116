/* Assembly of the granular contact stiffness and its sparse solution. */
#define _POSIX_C_SOURCE 199309L
#include "global/global.h"

#include <cholmod.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <umfpack.h>

#include "gem/sim.h"

enum { NW = 3, W_X = 0, W_Y = 1, W_MEAN = 2 };

/* Smallest relative diagonal shift: it keeps a system with a free rigid mode (a cluster held by
 * nothing) positive definite; if the factorisation still meets a zero pivot it grows tenfold. */
static const double REGULARISE = 1e-10;

struct gb_global {
    gb_linear_kind kind;
    int n;                 /* grains */
    long pattern_of;       /* pairs.rebuilds the pattern was built for (-1: none) */
    /* Full symmetric CSC pattern, 3 x 3 blocks: column block j lists its neighbours and itself. */
    int *Ap, *Ai, nnz, cap;
    double *Ax;
    int *list_start;       /* per grain: start of its sorted neighbour list (incl. itself) */
    int *list;             /* neighbour lists */
    int *self_pos;         /* per grain: position of itself in its list */
    int *pos_ij, *pos_ji;  /* per pair: position of i in j's list, of j in i's list (-1: wall) */
    double *rhs, *x;
    unsigned char *held;   /* per DOF: held (identity row) */
    double *S;             /* per grain: its block of K (s00 s01 s02 s11 s12 s22) */
    double *kt;            /* per pair: tangential stiffness used in K (0 for a sliding contact) */
    int kt_cap;
    /* Wall DOFs after the 3N grain DOFs: x axis (left and right walls inward), y axis (bottom and
     * top inward), and the isotropic strain of constant mean stress control. */
    unsigned char *touch;  /* per grain: bit 0 has a pair with the left/right wall, bit 1 bottom/top */
    int *wall_list[3], wall_n[3]; /* grains coupled to each wall DOF, increasing */
    int *wall_pos[3];      /* per grain: its position in wall_list[w], or -1 */
    cholmod_common cc;
    cholmod_sparse *A;
    cholmod_factor *L;
    void *symbolic, *numeric;
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    gb_global_stats stats;
};

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

gb_status gb_global_create(gb_linear_kind kind, int n_grains, gb_global **out, gb_error *err)
{
    gb_global *gl = calloc(1, sizeof *gl);
    if (!gl) return gb_fail(err, GB_ENOMEM, "out of memory");
    gl->kind = kind;
    gl->n = n_grains;
    gl->pattern_of = -1;
    size_t n3 = 3 * (size_t)n_grains, nd = n3 + NW;
    gl->rhs = calloc(nd, sizeof(double));
    gl->x = calloc(nd, sizeof(double));
    gl->held = calloc(nd, 1);
    gl->touch = calloc((size_t)n_grains + 1, 1);
    gl->S = calloc(6 * (size_t)n_grains + 1, sizeof(double));
    for (int w = 0; w < NW; w++) {
        gl->wall_list[w] = malloc(((size_t)n_grains + 1) * sizeof(int));
        gl->wall_pos[w] = malloc(((size_t)n_grains + 1) * sizeof(int));
        if (!gl->wall_list[w] || !gl->wall_pos[w]) {
            gb_global_free(gl);
            return gb_fail(err, GB_ENOMEM, "out of memory for the global system of %d grains", n_grains);
        }
    }
    gl->list_start = calloc((size_t)n_grains + 1, sizeof(int));
    gl->self_pos = calloc((size_t)n_grains, sizeof(int));
    gl->Ap = calloc(nd + 1, sizeof(int));
    if (!gl->rhs || !gl->x || !gl->held || !gl->touch || !gl->S || !gl->list_start || !gl->self_pos || !gl->Ap) {
        gb_global_free(gl);
        return gb_fail(err, GB_ENOMEM, "out of memory for the global system of %d grains", n_grains);
    }
    cholmod_start(&gl->cc);
    gl->cc.print = 0;
    gl->cc.error_handler = NULL;
    umfpack_di_defaults(gl->control);
    *out = gl;
    return GB_OK;
}

static void free_factors(gb_global *gl)
{
    if (gl->L) cholmod_free_factor(&gl->L, &gl->cc);
    if (gl->A) cholmod_free_sparse(&gl->A, &gl->cc);
    if (gl->symbolic) umfpack_di_free_symbolic(&gl->symbolic);
    if (gl->numeric) umfpack_di_free_numeric(&gl->numeric);
}

void gb_global_free(gb_global *gl)
{
    if (!gl) return;
    free_factors(gl);
    cholmod_finish(&gl->cc);
    free(gl->Ap);
    free(gl->Ai);
    free(gl->Ax);
    free(gl->list_start);
    free(gl->list);
    free(gl->self_pos);
    free(gl->pos_ij);
    free(gl->pos_ji);
    free(gl->rhs);
    free(gl->x);
    free(gl->held);
    free(gl->touch);
    free(gl->S);
    free(gl->kt);
    for (int w = 0; w < NW; w++) free(gl->wall_list[w]), free(gl->wall_pos[w]);
    free(gl);
}

const gb_global_stats *gb_global_statistics(const gb_global *gl) { return &gl->stats; }

static int find(const int *list, int n, int v)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (list[mid] == v) return mid;
        if (list[mid] < v) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* How many wall DOFs a grain with these touch bits is coupled to, and the offset of wall DOF w
 * among them (-1 if not coupled). */
static int n_walls_of(unsigned char t) { return t ? 1 + (t == 3 ? 2 : 1) : 0; }

static int wall_offset(unsigned char t, int w)
{
    if (!t) return -1;
    if (w == W_MEAN) return n_walls_of(t) - 1;
    if (w == W_X) return (t & 1) ? 0 : -1;
    return (t & 2) ? ((t & 1) ? 1 : 0) : -1;
}

/* The pattern of the candidate pairs: it changes only when the pair list is rebuilt. */
static gb_status build_pattern(gb_global *gl, const gb_pair_list *P, gb_error *err)
{
    int n = gl->n;
    int *deg = gl->list_start; /* counts first, then prefix sums */
    memset(deg, 0, ((size_t)n + 1) * sizeof(int));
    for (int i = 0; i < n; i++) deg[i + 1] = 1; /* itself */
    for (int k = 0; k < P->n; k++)
        if (P->p[k].j >= 0) deg[P->p[k].i + 1]++, deg[P->p[k].j + 1]++;
    for (int i = 0; i < n; i++) deg[i + 1] += deg[i];
    int total = deg[n];
    int *list = realloc(gl->list, (size_t)total * sizeof(int));
    int *pij = realloc(gl->pos_ij, (size_t)(P->n > 0 ? P->n : 1) * sizeof(int));
    int *pji = realloc(gl->pos_ji, (size_t)(P->n > 0 ? P->n : 1) * sizeof(int));
    if (!list || !pij || !pji) return gb_fail(err, GB_ENOMEM, "out of memory for the sparsity pattern");
    gl->list = list, gl->pos_ij = pij, gl->pos_ji = pji;
    int *fill = gl->self_pos; /* reused as a cursor */
    for (int i = 0; i < n; i++) {
        fill[i] = deg[i];
        list[fill[i]++] = i;
    }
    for (int k = 0; k < P->n; k++) {
        const gb_pair *p = &P->p[k];
        if (p->j < 0) continue;
        list[fill[p->i]++] = p->j;
        list[fill[p->j]++] = p->i;
    }
    for (int i = 0; i < n; i++) qsort(list + deg[i], (size_t)(deg[i + 1] - deg[i]), sizeof(int), cmp_int);
    for (int i = 0; i < n; i++) gl->self_pos[i] = find(list + deg[i], deg[i + 1] - deg[i], i);
    for (int k = 0; k < P->n; k++) {
        const gb_pair *p = &P->p[k];
        pij[k] = p->j < 0 ? -1 : find(list + deg[p->j], deg[p->j + 1] - deg[p->j], p->i);
        pji[k] = p->j < 0 ? -1 : find(list + deg[p->i], deg[p->i + 1] - deg[p->i], p->j);
    }
    /* The grains coupled to each wall DOF: those with a candidate pair with its walls. */
    memset(gl->touch, 0, (size_t)n);
    for (int k = 0; k < P->n; k++) {
        const gb_pair *p = &P->p[k];
        if (p->j >= 0) continue;
        int w = -1 - p->j;
        gl->touch[p->i] |= (w == GB_WALL_LEFT || w == GB_WALL_RIGHT) ? 1 : 2;
    }
    for (int w = 0; w < NW; w++) {
        gl->wall_n[w] = 0;
        int bits = w == W_X ? 1 : w == W_Y ? 2 : 3;
        for (int i = 0; i < n; i++) {
            gl->wall_pos[w][i] = (gl->touch[i] & bits) ? gl->wall_n[w] : -1;
            if (gl->touch[i] & bits) gl->wall_list[w][gl->wall_n[w]++] = i;
        }
    }
    /* CSC, full (both triangles): column 3j + b holds the 3 rows of every grain in j's list, then
     * the wall DOFs j is coupled to; a wall column holds its grains' rows, then all wall DOFs. */
    int nnz = 0, n3 = 3 * n;
    for (int j = 0; j < n; j++)
        for (int b = 0; b < 3; b++) {
            gl->Ap[3 * j + b] = nnz;
            nnz += 3 * (deg[j + 1] - deg[j]) + n_walls_of(gl->touch[j]);
        }
    for (int w = 0; w < NW; w++) {
        gl->Ap[n3 + w] = nnz;
        nnz += 3 * gl->wall_n[w] + NW;
    }
    gl->Ap[n3 + NW] = nnz;
    if (nnz > gl->cap) {
        int *ai = realloc(gl->Ai, (size_t)nnz * sizeof(int));
        double *ax = realloc(gl->Ax, (size_t)nnz * sizeof(double));
        if (!ai || !ax) return gb_fail(err, GB_ENOMEM, "out of memory for %d matrix entries", nnz);
        gl->Ai = ai, gl->Ax = ax, gl->cap = nnz;
    }
    gl->nnz = nnz;
    for (int j = 0; j < n; j++)
        for (int b = 0; b < 3; b++) {
            int q = gl->Ap[3 * j + b];
            for (int e = deg[j]; e < deg[j + 1]; e++)
                for (int a = 0; a < 3; a++) gl->Ai[q++] = 3 * list[e] + a;
            for (int w = 0; w < NW; w++)
                if (wall_offset(gl->touch[j], w) >= 0) gl->Ai[q++] = n3 + w;
        }
    for (int w = 0; w < NW; w++) {
        int q = gl->Ap[n3 + w];
        for (int e = 0; e < gl->wall_n[w]; e++)
            for (int a = 0; a < 3; a++) gl->Ai[q++] = 3 * gl->wall_list[w][e] + a;
        for (int v = 0; v < NW; v++) gl->Ai[q++] = n3 + v;
    }
    return GB_OK;
}

/* Adds v to the entry (row DOF of grain i, a; column DOF of grain j, b), where pos is the position
 * of i in j's list. */
static inline void add(gb_global *gl, int j, int pos, int a, int b, double v)
{
    gl->Ax[gl->Ap[3 * j + b] + 3 * pos + a] += v;
}

/* Adds v to the entries (grain i, a; wall DOF w) and (wall DOF w; grain i, a). */
static inline void add_grain_wall(gb_global *gl, int i, int a, int w, double v)
{
    int deg = gl->list_start[i + 1] - gl->list_start[i];
    gl->Ax[gl->Ap[3 * gl->n + w] + 3 * gl->wall_pos[w][i] + a] += v;
    gl->Ax[gl->Ap[3 * i + a] + 3 * deg + wall_offset(gl->touch[i], w)] += v;
}

/* Adds v to the entry (wall DOF w; wall DOF v). */
static inline void add_wall_wall(gb_global *gl, int w, int col, double v)
{
    gl->Ax[gl->Ap[3 * gl->n + col] + 3 * gl->wall_n[col] + w] += v;
}

static gb_status analyse(gb_global *gl, gb_error *err)
{
    double t0 = now();
    free_factors(gl);
    int n3 = 3 * gl->n + NW;
    if (gl->kind == GB_LINEAR_CHOLMOD) {
        gl->A = cholmod_allocate_sparse((size_t)n3, (size_t)n3, (size_t)gl->nnz, 1, 1, 1, CHOLMOD_REAL, &gl->cc);
        if (!gl->A) return gb_fail(err, GB_ENOMEM, "CHOLMOD: cannot allocate the matrix");
        memcpy(gl->A->p, gl->Ap, ((size_t)n3 + 1) * sizeof(int));
        memcpy(gl->A->i, gl->Ai, (size_t)gl->nnz * sizeof(int));
        memcpy(gl->A->x, gl->Ax, (size_t)gl->nnz * sizeof(double));
        gl->L = cholmod_analyze(gl->A, &gl->cc);
        if (!gl->L) return gb_fail(err, GB_ENUMERIC, "CHOLMOD analysis failed (status %d)", gl->cc.status);
    } else {
        int st = umfpack_di_symbolic(n3, n3, gl->Ap, gl->Ai, gl->Ax, &gl->symbolic, gl->control, gl->info);
        if (st != UMFPACK_OK) return gb_fail(err, GB_ENUMERIC, "UMFPACK symbolic analysis failed (status %d)", st);
    }
    gl->stats.analyses++;
    gl->stats.analyse += now() - t0;
    return GB_OK;
}

/* Factorises and solves K x = rhs; returns 1 if K was not positive definite (CHOLMOD) or
 * singular (UMFPACK), so that the caller can regularise further. */
static int factor_solve(gb_global *gl, gb_error *err, gb_status *st)
{
    int n3 = 3 * gl->n + NW;
    *st = GB_OK;
    double t0 = now();
    if (gl->kind == GB_LINEAR_CHOLMOD) {
        memcpy(gl->A->x, gl->Ax, (size_t)gl->nnz * sizeof(double));
        cholmod_factorize(gl->A, gl->L, &gl->cc);
        gl->stats.factorisations++;
        gl->stats.factorise += now() - t0;
        if (gl->cc.status == CHOLMOD_NOT_POSDEF) return 1;
        if (gl->cc.status != CHOLMOD_OK) {
            *st = gb_fail(err, GB_ENUMERIC, "CHOLMOD factorisation failed (status %d)", gl->cc.status);
            return 0;
        }
        t0 = now();
        cholmod_dense B = {(size_t)n3, 1, (size_t)n3, (size_t)n3, gl->rhs, NULL, CHOLMOD_REAL, CHOLMOD_DOUBLE};
        cholmod_dense *X = cholmod_solve(CHOLMOD_A, gl->L, &B, &gl->cc);
        if (!X) {
            *st = gb_fail(err, GB_ENUMERIC, "CHOLMOD solve failed (status %d)", gl->cc.status);
            return 0;
        }
        memcpy(gl->x, X->x, (size_t)n3 * sizeof(double));
        cholmod_free_dense(&X, &gl->cc);
    } else {
        if (gl->numeric) umfpack_di_free_numeric(&gl->numeric);
        int s = umfpack_di_numeric(gl->Ap, gl->Ai, gl->Ax, gl->symbolic, &gl->numeric, gl->control, gl->info);
        gl->stats.factorisations++;
        gl->stats.factorise += now() - t0;
        if (s == UMFPACK_WARNING_singular_matrix) return 1;
        if (s != UMFPACK_OK) {
            *st = gb_fail(err, GB_ENUMERIC, "UMFPACK factorisation failed (status %d)", s);
            return 0;
        }
        t0 = now();
        s = umfpack_di_solve(UMFPACK_A, gl->Ap, gl->Ai, gl->Ax, gl->x, gl->rhs, gl->numeric, gl->control, gl->info);
        if (s != UMFPACK_OK) {
            *st = gb_fail(err, GB_ENUMERIC, "UMFPACK solve failed (status %d)", s);
            return 0;
        }
    }
    gl->stats.solve += now() - t0;
    return 0;
}

/* The length that converts wall DOF w into the inward displacement of wall `wall` (0 if the wall
 * does not move with it): 1 for the axes, half the reference side for the isotropic strain. */
static double wall_lever(const gb_sim *sim, int w, int wall)
{
    int is_x = wall == GB_WALL_LEFT || wall == GB_WALL_RIGHT;
    if (w == W_X) return is_x ? 1 : 0;
    if (w == W_Y) return is_x ? 0 : 1;
    return is_x ? 0.5 * sim->ref_width : 0.5 * sim->ref_height;
}

/* The tangent stiffness of every contact and each grain's block of K. Unlike the reference
 * iteration, which keeps kt in S (K 8), a contact at its Coulomb limit (K 13) gets no tangential
 * stiffness: it slides, and Newton's method converges when its tangent is the true one. */
static gb_status tangents(gb_global *gl, const gb_sim *sim, gb_error *err)
{
    if (sim->pairs.n > gl->kt_cap) {
        double *kt = realloc(gl->kt, (size_t)sim->pairs.cap * sizeof(double));
        if (!kt) return gb_fail(err, GB_ENOMEM, "out of memory");
        gl->kt = kt, gl->kt_cap = sim->pairs.cap;
    }
    memset(gl->S, 0, 6 * (size_t)gl->n * sizeof(double));
    for (int k = 0; k < sim->pairs.n; k++) {
        const gb_pair *p = &sim->pairs.p[k];
        gl->kt[k] = 0;
        if (!(p->d > 0)) continue;
        const gb_material *m = p->j >= 0 ? &sim->scene->grain_grain : &sim->scene->grain_wall;
        double limit = p->pn * (p->j >= 0 ? sim->tan_phi_gg : sim->tan_phi_gw) + m->cohesion;
        double kn = m->kn, kt = fabs(p->pt) >= limit * (1 - 1e-9) ? 0 : m->kt;
        gl->kt[k] = kt;
        double c = p->nx, s = p->ny;
        double s00 = kn * c * c + kt * s * s, s01 = (kn - kt) * c * s, s11 = kn * s * s + kt * c * c;
        double *S = &gl->S[6 * p->i];
        S[0] += s00, S[1] += s01, S[2] += -kt * s, S[3] += s11, S[4] += kt * c, S[5] += kt;
        if (p->j >= 0) {
            S = &gl->S[6 * p->j];
            S[0] += s00, S[1] += s01, S[2] += kt * s, S[3] += s11, S[4] += -kt * c, S[5] += kt;
        }
    }
    return GB_OK;
}

/* K = sum over contacts of [T T']^t S_c [T T'] (K 1-8, 25) on grains and walls, held DOFs as
 * identity rows. A wall DOF that moves walls inward by lever x its value changes a wall contact's
 * overlap by the same amount: its coupling with grain i is kn lever (c, s, 0). */
static void assemble(gb_global *gl, const gb_sim *sim, double shift)
{
    memset(gl->Ax, 0, (size_t)gl->nnz * sizeof(double));
    const unsigned char *held = gl->held;
    int n3 = 3 * gl->n;
    for (int i = 0; i < gl->n; i++) {
        const double *S = &gl->S[6 * i];
        double blk[3][3] = {{S[0], S[1], S[2]}, {S[1], S[3], S[4]}, {S[2], S[4], S[5]}};
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                int ha = held[3 * i + a], hb = held[3 * i + b];
                double v = (ha || hb) ? (a == b ? 1.0 : 0.0) : blk[a][b] * (a == b ? 1 + shift : 1);
                add(gl, i, gl->self_pos[i], a, b, v);
            }
    }
    double kww[NW] = {0, 0, 0};
    for (int k = 0; k < sim->pairs.n; k++) {
        const gb_pair *p = &sim->pairs.p[k];
        if (!(p->d > 0)) continue;
        int i = p->i;
        if (p->j < 0) {
            double kn = sim->scene->grain_wall.kn, g[3] = {kn * p->nx, kn * p->ny, 0};
            for (int w = 0; w < NW; w++) {
                double lever = wall_lever(sim, w, -1 - p->j);
                if (lever == 0 || held[n3 + w]) continue;
                kww[w] += kn * lever * lever;
                for (int a = 0; a < 2; a++)
                    if (!held[3 * i + a]) add_grain_wall(gl, i, a, w, g[a] * lever);
            }
            continue;
        }
        double c = p->nx, s = p->ny, kn = sim->scene->grain_grain.kn, kt = gl->kt[k];
        double r1[3] = {c, s, 0}, r2[3] = {-s, c, 1}, q1[3] = {-c, -s, 0}, q2[3] = {s, -c, 1};
        int j = p->j;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                if (held[3 * i + a] || held[3 * j + b]) continue;
                double v = kn * r1[a] * q1[b] + kt * r2[a] * q2[b]; /* T^t S_c T' */
                add(gl, j, gl->pos_ij[k], a, b, v);                 /* (i, a) row, (j, b) column */
                add(gl, i, gl->pos_ji[k], b, a, v);                 /* its transpose */
            }
    }
    /* A wall DOF whose walls touch nothing gets the stiffness of one grain-wall contact, as in the
     * reference iteration. */
    for (int w = 0; w < NW; w++) {
        double lever = w == W_MEAN ? 0.5 * fmax(sim->ref_width, sim->ref_height) : 1;
        double kmin = sim->scene->grain_wall.kn * lever * lever;
        add_wall_wall(gl, w, w, held[n3 + w] ? 1.0 : fmax(kww[w], kmin) * (1 + shift));
    }
}

/* The wall DOFs' residuals (force conjugate to each DOF minus its target, METHOD.md section 5):
 * stress control, (F_left + F_right) - 2 s2 H and (F_bottom + F_top) - 2 s1 W; constant mean
 * stress, ((s1 + s2)/2 - m0) (W H_ref + H W_ref), the mean-stress error times the area change per
 * unit isotropic strain. Unused DOFs are held. */
static void wall_residuals(gb_global *gl, const gb_sim *sim, const gb_wall_control *wc)
{
    int n3 = 3 * gl->n;
    const double *f = sim->wall_force;
    const gb_box *b = &sim->box;
    double W = b->right - b->left, H = b->top - b->bottom;
    for (int w = 0; w < NW; w++) gl->held[n3 + w] = 1, gl->rhs[n3 + w] = 0;
    if (wc->mode == GB_WALLS_STRESS) {
        gl->held[n3 + W_X] = gl->held[n3 + W_Y] = 0;
        gl->rhs[n3 + W_X] = -(f[GB_WALL_LEFT] + f[GB_WALL_RIGHT] - 2 * wc->s2 * H);
        gl->rhs[n3 + W_Y] = -(f[GB_WALL_BOTTOM] + f[GB_WALL_TOP] - 2 * wc->s1 * W);
    } else if (wc->mode == GB_WALLS_MEAN) {
        double s1 = (f[GB_WALL_BOTTOM] + f[GB_WALL_TOP]) / (2 * W), s2 = (f[GB_WALL_LEFT] + f[GB_WALL_RIGHT]) / (2 * H);
        gl->held[n3 + W_MEAN] = 0;
        gl->rhs[n3 + W_MEAN] = -(0.5 * (s1 + s2) - wc->mean) * (W * sim->ref_height + H * sim->ref_width);
    }
}

gb_status gb_global_moves(gb_global *gl, gb_sim *sim, const gb_wall_control *wc, double mu, gb_error *err)
{
    gb_status st;
    double t0 = now();
    if (gl->pattern_of != sim->pairs.rebuilds) {
        if ((st = build_pattern(gl, &sim->pairs, err))) return st;
        gl->pattern_of = sim->pairs.rebuilds;
        gl->stats.assemble += now() - t0;
        if ((st = analyse(gl, err))) return st;
        t0 = now();
    }
    int n = gl->n, n3 = 3 * n;
    if ((st = tangents(gl, sim, err))) return st;
    for (int i = 0; i < n; i++) {
        int few = sim->nc[i] < 2;
        gl->held[3 * i] = gl->held[3 * i + 1] = (unsigned char)few;
        gl->held[3 * i + 2] = (unsigned char)(few || !(gl->S[6 * i + 5] > 0)); /* no rotational stiffness */
        for (int a = 0; a < 3; a++) gl->rhs[3 * i + a] = gl->held[3 * i + a] ? 0 : -sim->F[3 * i + a];
    }
    wall_residuals(gl, sim, wc);
    double shift = fmax(mu, REGULARISE), cap = fmax(1e3 * shift, 1e-3);
    assemble(gl, sim, shift);
    gl->stats.assemble += now() - t0;
    for (;;) {
        int singular = factor_solve(gl, err, &st);
        if (st) return st;
        if (!singular) break;
        if (shift >= cap)
            return gb_fail(err, GB_ENUMERIC, "the contact stiffness stays singular after a relative diagonal shift "
                                             "of %g", shift);
        shift *= 10;
        gl->stats.regularised++;
        t0 = now();
        assemble(gl, sim, shift);
        gl->stats.assemble += now() - t0;
    }
    /* The moves: the solution, scaled down as a whole if some grain would move more than
     * max_move (a share of its radius), and the reference cases for the held grains. */
    const gb_solver_settings *sv = &sim->scene->solver;
    double worst = 0;
    for (int i = 0; i < n; i++) {
        const double *x = &gl->x[3 * i];
        double m = sqrt(x[0] * x[0] + x[1] * x[1]) / sim->g[i].r;
        if (m > worst) worst = m;
    }
    double a = sv->global_alpha, scale = worst * a > sv->max_move ? sv->max_move / worst : a;
    for (int i = 0; i < n; i++) {
        double *d = &sim->dX[3 * i];
        if (sim->nc[i] < 2) {
            gb_gem_grain_move(sim, i, d);
            continue;
        }
        for (int q = 0; q < 3; q++) d[q] = gl->held[3 * i + q] ? 0 : scale * gl->x[3 * i + q];
    }
    memset(sim->wall_dx, 0, sizeof sim->wall_dx);
    for (int w = 0; w < NW; w++) {
        if (gl->held[n3 + w]) continue;
        double v = scale * gl->x[n3 + w];
        for (int wall = 0; wall < GB_N_WALLS; wall++) {
            double in = v * wall_lever(sim, w, wall);
            if (wall == GB_WALL_LEFT) sim->wall_dx[wall][0] += in;
            if (wall == GB_WALL_RIGHT) sim->wall_dx[wall][0] -= in;
            if (wall == GB_WALL_BOTTOM) sim->wall_dx[wall][1] += in;
            if (wall == GB_WALL_TOP) sim->wall_dx[wall][1] -= in;
        }
    }
    return GB_OK;
}
