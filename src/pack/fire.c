/* FIRE 2.0 relaxation of discs (fire.h), first moved here from tools/packgen/jam.c.
 * Contacts come from the contact module (its cell list and geometry: walls, grains and half-disc
 * boundary particles as gembem's solver sees them); without friction the grain-grain pairs, nearly
 * all of them, are tested first on squared distances so that a pair that does not touch costs no
 * root; with friction each pair is updated by gembem's law (gb_pair_update_forces) from the discs' moves
 * since the last evaluation. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pack/fire.h"

static const double PI = 3.14159265358979323846;

/* FIRE's parameters: those of Bitzek et al. 2006 (N_min = 5, alpha_start = 0.1, f_inc, f_dec, f_alpha)
 * with FIRE 2.0's time step bounds (Guenole et al. 2020: the first step a tenth of the largest, the
 * smallest 0.002 of it); measured on 9 seeds of 1 000 discs grown to a stress (docs/packing.md),
 * FIRE 2.0's N_delay = 20 and alpha_start = 0.25 took some 40 % more iterations. */
static const double F_INC = 1.1, F_DEC = 0.5, A_START = 0.1, F_A = 0.99, DT_MAX_MD = 10, DT_MIN_MD = 0.02;
static const int N_DELAY = 5;
/* The largest step, as a share of sqrt(m / kn): one disc of the (common) mass m between springs of
 * the stiffest kn oscillates with a period 2 pi sqrt(m / (z kn)); semi-implicit Euler is stable
 * below 2 / omega, about 0.58 sqrt(m / kn) for the 6 neighbours of a dense packing. */
static const double DT_MAX = 0.5;

/* The force loop and FIRE's passes run on OpenMP's threads in a fixed decomposition, so that the
 * arithmetic and the trajectory are the same bits whatever the thread count (ctest pack_make
 * compares a seed's bytes, .ci/run runs the suite on 1 and 2 threads):
 * - sums over discs in blocks of BLOCK, each summed in its order, the blocks one after the other;
 * - the grain pairs (the list is sorted by (i, j)) in chunks of W discs by i, W at least the
 *   largest j - i: a chunk's pairs then write only to the discs of it and of the next one, so the
 *   even chunks run at once, then the odd ones, each disc's sum in an order fixed by W. The discs
 *   are numbered by rows of cells (pack.c's sort_by_cell), so j - i is about two rows of discs.
 * Below PARALLEL discs the threads' start costs more than they save (the results are the same).
 * The threads run only when the scene's solver.threads asks for them (as in the solver's passes,
 * src/gem/relax.c): libgomp's threads spin while they wait at the end of a loop, and on a machine
 * other jobs load a spinning thread holds the core the other one needs (1e5 discs on 2 threads at
 * load 3-5: 11.4 minutes against 2.6 on one; OMP_WAIT_POLICY=passive 2.5; docs/benchmarks.md). */
enum { BLOCK = 2048, CHUNK_MIN = 1024, PARALLEL = 4096 };
static int blocks(long m) { return (int)((m + BLOCK - 1) / BLOCK); }

typedef struct {
    const gb_fire_world *w;
    gb_world world;
    gb_pair_set own, *L; /* the candidate pairs: the world's (friction) or own */
    gb_pair_search search;
    double scale;       /* the radii's factor */
    double scale0;      /* at the last rebuild */
    double r0max;
    double wr;          /* sum of pn (ri + rj), or pn ri with a wall or particle: -dU/dln(scale) */
    int *gg, n_gg;      /* the grain pairs of the list, (i, j) packed: 8 bytes a pair instead of a gb_pair's 64 */
    int *gk;            /* with friction: each grain pair's index in the list */
    unsigned char *on;  /* with friction: each grain pair touches (at its last update) */
    int *other, n_other; /* the list's pairs with walls and particles, by index */
    int cap;
    int *chunk, n_chunks; /* chunk c's grain pairs: gg's [chunk[c], chunk[c + 1]) */
    int width;          /* the chunks' W */
    double *part;       /* the blocks' and chunks' partial sums and maxima */
    double ff, vv;      /* the discs' sum of |F|^2 (forces), of |v|^2 (the step) */
    int part_cap;
    int threads;        /* gb_fire_world's, at least 1 */
    int par;            /* the discs are many enough for the threads */
    int fr;             /* friction: the rotations are degrees of freedom too */
    double *fw, *vw;    /* with friction: each disc's moment over its radius (a force at its rim), its rim's velocity */
    double *dX;         /* with friction: each disc's move (dx, dy, r dw) since the forces were last evaluated
                         * (written afresh by the next step: the forces have used it) */
    double wall_dx[2 * GB_N_WALLS]; /* the walls' moves: none, they are held */
} fire_state;

/* A frictional pair updated by gembem's law from the moves dX (K 6, 13, 25) and its forces added to
 * its discs: f and fw, the opposite of (K 5)'s out-of-balance terms (K 2: -(pn n + pt t) on i, with
 * t = (-ny, nx), and -pt at its rim; the rolling moment mr on i, -mr on j). Its pn times the
 * distance from i's centre to the contact point(s) and times the radii into virial and wr, as the
 * frictionless loop; returns whether it touches. */
static int friction_pair(fire_state *S, gb_pair *p, double *f, double *fw, double *virial, double *wr)
{
    const gb_fire_world *w = S->w;
    int k = gb_pair_end(p->j), i = p->i, j = p->j;
    gb_pair_update_forces(p, &S->world, S->dX, S->wall_dx, w->mat[k], w->tan_phi[k]);
    if (!(p->d > 0)) return 0;
    const gb_grain *g = w->g;
    double pn = p->pn, pt = p->pt, fx, fy;
    gb_pair_force(p, pn, pt, &fx, &fy);
    f[2 * i] -= fx, f[2 * i + 1] -= fy;
    fw[i] -= p->mr != 0 ? pt - p->mr / g[i].r : pt;
    if (j >= 0) {
        f[2 * j] += fx, f[2 * j + 1] += fy;
        fw[j] -= p->mr != 0 ? pt + p->mr / g[j].r : pt;
        *virial += pn * (g[i].r + g[j].r - p->d), *wr += pn * (g[i].r + g[j].r);
    } else
        *virial += pn * (g[i].r - 0.5 * p->d), *wr += pn * g[i].r;
    return 1;
}

/* The grain pairs of the chunks c = first, first + 2, ... into f; their sums of pn (ri + rj) and
 * pn times the distance into part[2 c], part[2 c + 1]; with full, the contacts and the largest
 * overlap over the smaller radius. */
static void pair_forces(fire_state *S, int first, double *f, int full, int *contacts, double *largest)
{
    const gb_grain *g = S->w->g;
    const int *gg = S->gg, *chunk = S->chunk, half = (S->n_chunks - first + 1) / 2;
    const double kn = S->w->kn_gg;
    double *part = S->part, lo = *largest;
    int nc = *contacts;
#pragma omp parallel for schedule(static) num_threads(S->threads) if (S->par) reduction(max : lo) reduction(+ : nc)
    for (int q = 0; q < half; q++) {
        int c = first + 2 * q;
        double virial = 0, wr = 0;
        if (S->fr)
            for (int k = chunk[c]; k < chunk[c + 1]; k++) {
                /* a pair that did not touch and does not: nothing to update (a new contact's
                 * tangential force starts at 0 whatever its history), and its 64 bytes stay unread */
                int i = gg[2 * k], j = gg[2 * k + 1];
                double dx = g[j].x - g[i].x, dy = g[j].y - g[i].y, sum = g[i].r + g[j].r;
                if (!S->on[k] && dx * dx + dy * dy >= sum * sum) continue;
                gb_pair *p = &S->L->p[S->gk[k]];
                S->on[k] = (unsigned char)friction_pair(S, p, f, S->fw, &virial, &wr);
                if (S->on[k] && full) lo = fmax(lo, p->d / fmin(g[i].r, g[j].r)), nc++;
            }
        else
            for (int k = chunk[c]; k < chunk[c + 1]; k++) {
                int i = gg[2 * k], j = gg[2 * k + 1];
                double dx = g[j].x - g[i].x, dy = g[j].y - g[i].y, sum = g[i].r + g[j].r, d2 = dx * dx + dy * dy;
                if (d2 >= sum * sum) continue;
                double dist = sqrt(d2), d = sum - dist, pn = kn * d, fx = pn, fy = 0;
                if (dist > 0) { /* coincident centres: pushed along x */
                    double h = pn / dist;
                    fx = h * dx, fy = h * dy;
                }
                f[2 * i] -= fx, f[2 * i + 1] -= fy;
                f[2 * j] += fx, f[2 * j + 1] += fy;
                virial += pn * dist, wr += pn * sum;
                if (full) lo = fmax(lo, d / fmin(g[i].r, g[j].r)), nc++;
            }
        part[2 * c] = virial, part[2 * c + 1] = wr;
    }
    *largest = lo, *contacts = nc;
}

/* Disc i's force before its contacts: the body force on it; with friction no moment. */
static inline void reset_disc(const fire_state *S, double *f, int i)
{
    const gb_fire_world *w = S->w;
    double a = w->body[0] != 0 || w->body[1] != 0 ? PI * w->g[i].r * w->g[i].r : 0;
    f[2 * i] = w->body[0] * a, f[2 * i + 1] = w->body[1] * a;
    if (S->fw) S->fw[i] = 0;
}

/* Forces of the springs and the body force into f (2 per disc), with friction the moments into
 * S->fw; returns the largest |F|, in *power the discs' share of F.v (v: their velocities) and in
 * S->ff their sum of |F|^2. With `full`, the report's contact counts, walls and largest overlap too.
 * With `reset`, f and fw are first set to the body force (reset_disc); else the step's pass over the
 * discs has done it. */
static double forces(fire_state *S, double *f, const double *v, double *power, gb_fire_report *rep, int full,
                     int reset)
{
    const gb_fire_world *w = S->w;
    const gb_grain *g = w->g;
    const int n = w->n, nb = blocks(n);
    double *fw = S->fw;
    /* on the threads, not memset on one while the others wait: 9 % of a 1e5-disc frictional step */
    if (reset) {
#pragma omp parallel for schedule(static) num_threads(S->threads) if (S->par)
        for (int i = 0; i < n; i++) reset_disc(S, f, i);
    }
    double largest = 0, virial = 0, wr = 0;
    int contacts = 0;
    pair_forces(S, 0, f, full, &contacts, &largest);
    pair_forces(S, 1, f, full, &contacts, &largest);
    for (int c = 0; c < S->n_chunks; c++) wr += S->part[2 * c + 1], virial += S->part[2 * c];
    if (full) {
        rep->contacts = contacts, rep->wall_contacts = 0, rep->largest_overlap = largest;
        memset(rep->wall, 0, sizeof rep->wall);
    }
    for (int k = 0; k < S->n_other; k++) { /* few: the discs along the walls or the cavity */
        gb_pair *p = &S->L->p[S->other[k]];
        int i = p->i, j = p->j;
        if (S->fr) {
            if (!friction_pair(S, p, f, S->fw, &virial, &wr)) continue;
            if (full) rep->contacts++;
            if (full && !GB_IS_PARTICLE(j)) rep->wall[-1 - j] += p->pn, rep->wall_contacts++;
            continue;
        }
        gb_pair_geometry(p, &S->world);
        if (!(p->d > 0)) continue;
        double pn = (GB_IS_PARTICLE(j) ? w->kn_gb : w->kn_gw) * p->d;
        f[2 * i] -= pn * p->nx, f[2 * i + 1] -= pn * p->ny;
        virial += pn * (g[i].r - 0.5 * p->d), wr += pn * g[i].r;
        if (full) rep->contacts++;
        if (full && !GB_IS_PARTICLE(j)) rep->wall[-1 - j] += pn, rep->wall_contacts++;
    }
    rep->virial = virial, S->wr = wr;
    double *part = S->part;
    const double *vw = S->vw;
#pragma omp parallel for schedule(static) num_threads(S->threads) if (S->par)
    for (int b = 0; b < nb; b++) {
        double worst = 0, P = 0, ff = 0;
        for (int i = b * BLOCK, e = i + BLOCK < n ? i + BLOCK : n; i < e; i++) {
            double q = f[2 * i] * f[2 * i] + f[2 * i + 1] * f[2 * i + 1];
            if (fw) q += fw[i] * fw[i], P += fw[i] * vw[i];
            if (q > worst || q != q) worst = q;
            P += f[2 * i] * v[2 * i], P += f[2 * i + 1] * v[2 * i + 1], ff += q;
        }
        part[3 * b] = worst, part[3 * b + 1] = P, part[3 * b + 2] = ff;
    }
    double worst = 0, P = 0, ff = 0;
    for (int b = 0; b < nb; b++) {
        if (part[3 * b] > worst || part[3 * b] != part[3 * b]) worst = part[3 * b];
        P += part[3 * b + 1], ff += part[3 * b + 2];
    }
    *power = P, S->ff = ff;
    return sqrt(worst);
}

/* Rebuilds the list, its packed copies and their chunks. */
static gb_status rebuild(fire_state *S, gb_error *err)
{
    gb_status st = gb_pairs_rebuild(S->L, &S->search, &S->world, err);
    if (st) return st;
    int n = S->w->n, np = S->L->n;
    if (np > S->cap) {
        int cap = np + np / 2 + 16, *gg = realloc(S->gg, 2 * (size_t)cap * sizeof(int));
        if (gg) S->gg = gg;
        int *other = gg ? realloc(S->other, (size_t)cap * sizeof(int)) : NULL;
        if (other) S->other = other;
        int *gk = other && S->fr ? realloc(S->gk, (size_t)cap * sizeof(int)) : NULL;
        if (gk) S->gk = gk;
        unsigned char *on = gk ? realloc(S->on, (size_t)cap) : NULL;
        if (on) S->on = on;
        if (!gg || !other || (S->fr && !on)) return gb_fail(err, GB_ENOMEM, "out of memory for %d contact pairs", np);
        S->cap = cap;
    }
    int gap = 0;
    S->n_gg = S->n_other = 0;
    for (int k = 0; k < np; k++) {
        const gb_pair *p = &S->L->p[k];
        if (p->j < 0) {
            S->other[S->n_other++] = k;
            continue;
        }
        if (S->fr) S->gk[S->n_gg] = k, S->on[S->n_gg] = p->d > 0;
        S->gg[2 * S->n_gg] = p->i, S->gg[2 * S->n_gg++ + 1] = p->j;
        if (p->j - p->i > gap) gap = p->j - p->i;
    }
    S->width = gap > CHUNK_MIN ? gap : CHUNK_MIN;
    S->n_chunks = (n + S->width - 1) / S->width;
    /* the chunks' 2 sums (at most n / CHUNK_MIN + 1 chunks), or the disc blocks' 3 */
    int part = 2 * S->n_chunks + 3 * blocks(n) + 2;
    if (part > S->part_cap) {
        double *q = realloc(S->part, (size_t)part * sizeof(double));
        int *chunk = q ? realloc(S->chunk, (size_t)part * sizeof(int)) : NULL;
        if (q) S->part = q;
        if (chunk) S->chunk = chunk;
        if (!chunk) return gb_fail(err, GB_ENOMEM, "out of memory for %d grains", n);
        S->part_cap = part;
    }
    for (int c = 0, k = 0; c <= S->n_chunks; c++) {
        while (k < S->n_gg && S->gg[2 * k] < c * S->width) k++;
        S->chunk[c] = k;
    }
    return GB_OK;
}

static void set_scale(fire_state *S, double scale)
{
    S->scale = scale;
    for (int i = 0; S->w->r0 && i < S->w->n; i++) S->w->g[i].r = scale * S->w->r0[i];
}

/* The list covers the pairs within its skin at the last rebuild: stale when displacements (drift2:
 * the largest squared one of a disc, from the step's pass) and the radii's growth since then could
 * close a gap of that skin. The walls and boundary particles are held. */
static gb_status refresh(fire_state *S, double drift2, gb_error *err)
{
    double grain = sqrt(drift2) + fmax(0, S->scale - S->scale0) * S->r0max;
    if (!gb_pairs_drift_stale(&S->search, grain, 0)) return GB_OK;
    S->scale0 = S->scale;
    return rebuild(S, err);
}

/* The relaxation's constants, from the discs and springs at its start. */
typedef struct {
    double inv_m;          /* one over the discs' mass (the lightest disc's, for all) */
    double c;              /* the length of a unit of ln(scale) */
    double dt_max, dt_min; /* FIRE's bounds on its step */
} fire_scales;

/* The relaxation's start: the velocities and forces (v, f: len each), the state S with its scale
 * and the pair list's skin (the list is built next), and the constants. */
static gb_status fire_start(fire_state *S, const gb_fire_world *w, double scale, size_t len, double **v, double **f,
                            fire_scales *k, gb_error *err)
{
    int n = w->n;
    S->w = w, S->world = (gb_world){w->g, n, w->box, w->bp};
    S->fr = w->pairs != NULL, S->L = S->fr ? w->pairs : &S->own;
    *v = calloc(len, sizeof(double)), *f = calloc(len, sizeof(double));
    if (S->fr) {
        S->fw = calloc((size_t)n + 1, sizeof(double)), S->vw = calloc((size_t)n + 1, sizeof(double));
        S->dX = calloc(3 * (size_t)n + 1, sizeof(double));
    }
    S->threads = w->threads > 1 ? w->threads : 1; /* a world made without it: one */
    S->search.threads = S->threads;
    S->par = n >= PARALLEL && S->threads > 1;
    if (!*v || !*f || (S->fr && (!S->fw || !S->vw || !S->dX)))
        return gb_fail(err, GB_ENOMEM, "out of memory for the relaxation of %d grains", n);
    set_scale(S, w->r0 ? scale : 1);
    S->scale0 = S->scale;
    /* One mass for every disc, the lightest's: the statics do not depend on it, and the larger
     * discs then move as fast as the smallest instead of twice as slow (a ratio of 2 in radius). */
    double rmin = HUGE_VAL, c2 = 0, kn = fmax(w->kn_gg, fmax(w->box ? w->kn_gw : 0, w->bp ? w->kn_gb : 0));
    for (int i = 0; i < n; i++) {
        rmin = fmin(rmin, w->g[i].r), c2 += 4 * w->g[i].r * w->g[i].r;
        if (w->r0) S->r0max = fmax(S->r0max, w->r0[i]);
    }
    /* With friction a contact's tangential spring acting on both discs' rims and centres is stiffer
     * than its normal one on the centres alone (its largest eigenvalue 4 kt against 2 kn), the
     * rolling spring kr / r^2 on the rims: the step is bounded by the stiffest. */
    for (int q = 0; S->fr && q < 3; q++)
        kn = fmax(kn, fmax(2 * w->mat[q]->kt, 2 * w->mat[q]->kr / (rmin * rmin)));
    const double m = PI * rmin * rmin;
    k->inv_m = 1 / m;
    /* ln(scale) as the length c ln(scale), c^2 = sum (2 ri)^2: a unit move of it then strains the
     * contacts about as much as a unit move of a disc its own, so that it shares the discs' mass
     * and step (its force is -dH/dln(scale) / c). */
    k->c = sqrt(c2);
    k->dt_max = DT_MAX * sqrt(m / kn), k->dt_min = DT_MIN_MD / DT_MAX_MD * k->dt_max;
    /* a skin of half the smallest radius: the growth's steps of 1 % of a radius rebuild the list
     * every few iterations with less (0.2 rmin: a third more CPU time at 1e4 discs, 0.5 and 1.0
     * about the same); the pairs apart cost little in the force loop */
    S->search.skin = 0.5 * rmin;
    return GB_OK;
}

/* Half a step back: the descent went past a minimum along v, which is then zeroed (with friction
 * the move is one as any other for the tangential springs, kept in S->dX). */
static void step_back(fire_state *S, double *v, size_t len, double dt, int free_scale, double c)
{
    const gb_fire_world *w = S->w;
    int n = w->n;
#pragma omp parallel for schedule(static) num_threads(S->threads) if (S->par)
    for (int i = 0; i < n; i++) {
        w->g[i].x -= 0.5 * dt * v[2 * i], w->g[i].y -= 0.5 * dt * v[2 * i + 1];
        if (S->fr) {
            double *d = S->dX + 3 * i;
            d[0] = -0.5 * dt * v[2 * i], d[1] = -0.5 * dt * v[2 * i + 1], d[2] = -0.5 * dt * S->vw[i];
            w->g[i].rot += d[2] / w->g[i].r;
        }
    }
    if (free_scale) set_scale(S, S->scale * exp(-0.5 * dt * v[2 * n] / c));
    memset(v, 0, len * sizeof(double));
    if (S->fr) memset(S->vw, 0, (size_t)n * sizeof(double));
    S->vv = 0;
}

/* One pass over the discs: each velocity v + h F mixed towards the force (keep, mix), the move by
 * dt, the radii at scale `next`, the drift since the pair list's rebuild and |v|^2 (into S->vv).
 * back: the step began with half a step back, which S->dX holds. Returns the largest squared
 * drift. */
static double move_discs(fire_state *S, double *v, double *f, double dt, double h, double keep, double mix,
                         double next, int back)
{
    const gb_fire_world *w = S->w;
    const int n = w->n, nb = blocks(n);
    double drift2 = 0;
    const double *r0 = w->r0, *fw = S->fw;
    double *vw = S->vw, *dX = S->dX;
    gb_grain *g = w->g;
#pragma omp parallel for schedule(static) num_threads(S->threads) if (S->par) reduction(max : drift2)
    for (int b = 0; b < nb; b++) {
        double sv = 0;
        for (int i = b * BLOCK, e = i + BLOCK < n ? i + BLOCK : n; i < e; i++) {
            double *u = v + 2 * i, *F = f + 2 * i;
            u[0] = keep * (u[0] + h * F[0]) + mix * F[0], u[1] = keep * (u[1] + h * F[1]) + mix * F[1];
            g[i].x += dt * u[0], g[i].y += dt * u[1];
            if (dX) { /* the rotation, and the move the pairs will be updated with */
                vw[i] = keep * (vw[i] + h * fw[i]) + mix * fw[i];
                double *d = dX + 3 * i;
                if (!back) d[0] = d[1] = d[2] = 0;
                d[0] += dt * u[0], d[1] += dt * u[1], d[2] += dt * vw[i];
                g[i].rot += dt * vw[i] / g[i].r;
                sv += vw[i] * vw[i];
            }
            if (r0) g[i].r = next * r0[i];
            reset_disc(S, f, i); /* the next forces' start (its pass over the discs saved) */
            double q = gb_pairs_grain_drift2(S->L, &S->world, i);
            if (q > drift2) drift2 = q;
            sv += u[0] * u[0] + u[1] * u[1];
        }
        S->part[b] = sv;
    }
    S->vv = v[2 * n] * v[2 * n];
    for (int b = 0; b < nb; b++) S->vv += S->part[b];
    return drift2;
}

/* The relaxation's end after `it` iterations: its report, and GB_ENOCONV where the goal's
 * iterations were spent (largest force `worst`, mean stress p). */
static gb_status fire_end(const fire_state *S, const gb_fire_goal *goal, long it, double worst, double p,
                          gb_fire_report *rep, gb_error *err)
{
    if (rep->capped || it < goal->max_iter) return GB_OK;
    if (S->w->r0 && goal->free)
        return gb_fail(err, GB_ENOCONV, "FIRE did not bring the largest force below %g and the mean stress to %g in "
                                        "%ld iterations (they are %g and %g)", goal->tol, goal->stress,
                       goal->max_iter, worst, p);
    return gb_fail(err, GB_ENOCONV, "FIRE did not bring the largest force below %g in %ld iterations (it is %g)",
                   goal->tol, goal->max_iter, worst);
}

gb_status gb_fire_relax_scaled(const gb_fire_world *w, const gb_fire_goal *goal, double *scale,
                               gb_fire_report *rep, gb_error *err)
{
    int n = w->n, free_scale = w->r0 && goal->free, ramp = w->r0 && !free_scale;
    size_t len = 2 * (size_t)n + 1; /* the discs' 2 n coordinates, then ln(scale) as a length */
    memset(rep, 0, sizeof *rep);
    fire_state S;
    memset(&S, 0, sizeof S);
    fire_scales k = {0};
    double *v = NULL, *f = NULL;
    gb_status st = fire_start(&S, w, w->r0 ? *scale : 1, len, &v, &f, &k, err);
    const long rebuilds0 = S.L->rebuilds;
    if (st || (st = rebuild(&S, err))) goto done;
    const double target_ln = ramp ? log(goal->scale_to) : 0, c = k.c;
    double P = 0, dt = k.dt_max / DT_MAX_MD, alpha = A_START, worst = forces(&S, f, v, &P, rep, 0, 1), p = 0;
    long since_neg = 0, it = 0;
    for (;; it++) {
        int back = 0; /* with friction: this step began with half a step back, which dX holds */
        if (free_scale) f[2 * n] = (2 * w->area * goal->stress - S.wr) / c;
        P += f[2 * n] * v[2 * n];
        p = w->area > 0 ? rep->virial / (2 * w->area) : 0;
        if (!isfinite(worst) || !isfinite(p)) {
            st = gb_fail(err, GB_ENUMERIC, "the packing's forces became non-finite at FIRE iteration %ld", it);
            goto done;
        }
        int reached = goal->stress > 0 && p >= goal->stress;
        int scale_done = free_scale ? fabs(p - goal->stress) <= goal->stress_tol * goal->stress
                                    : !ramp || S.scale == goal->scale_to || reached;
        if ((worst <= goal->tol && scale_done) || it >= goal->max_iter) break;
        if (free_scale && S.scale > goal->scale_max) {
            rep->capped = 1;
            break;
        }
        if (P > 0) {
            if (++since_neg > N_DELAY) dt = fmin(dt * F_INC, k.dt_max), alpha *= F_A;
        } else {
            since_neg = 0;
            if (it >= N_DELAY) {
                if (dt * F_DEC >= k.dt_min) dt *= F_DEC;
                alpha = A_START;
            }
            step_back(&S, v, len, dt, free_scale, c);
            back = S.fr;
        }
        /* semi-implicit Euler: the velocity first, v + h F, mixed towards the force while descending
         * (in the pass over the discs below, with their move); the mix needs |v + h F|^2, which is
         * |v|^2 + 2 h F.v + h^2 |F|^2 from the sums the last step and the force pass took (one pass
         * over the discs fewer) */
        const double h = dt * k.inv_m, ff = S.ff + f[2 * n] * f[2 * n];
        const double vv = fmax(0, S.vv + 2 * h * (P > 0 ? P : 0) + h * h * ff);
        const double keep = P > 0 && ff > 0 ? 1 - alpha : 1, mix = P > 0 && ff > 0 ? alpha * sqrt(vv / ff) : 0;
        double next = S.scale;
        v[2 * n] = keep * (v[2 * n] + h * f[2 * n]) + mix * f[2 * n];
        if (free_scale) {
            /* the radii grow at most `ramp` in ln(scale) per step, so that no contact closes by
             * more than a small share of a radius between two force evaluations */
            double lim = goal->ramp * c / dt;
            v[2 * n] = fmax(-lim, fmin(lim, v[2 * n]));
            next = S.scale * exp(dt * v[2 * n] / c);
        } else if (ramp && S.scale != goal->scale_to && !reached && worst <= goal->hold) {
            double step = target_ln - log(S.scale), grow = step > 0 ? goal->ramp : -goal->ramp;
            next = fabs(step) <= goal->ramp ? goal->scale_to : S.scale * exp(grow);
        }
        S.scale = next;
        double drift2 = move_discs(&S, v, f, dt, h, keep, mix, next, back);
        if ((st = refresh(&S, drift2, err))) goto done;
        worst = forces(&S, f, v, &P, rep, 0, 0);
    }
    if (S.fr) memset(S.dX, 0, 3 * (size_t)n * sizeof(double)); /* the last move is in the pairs already */
    worst = forces(&S, f, v, &P, rep, 1, 1);
    rep->iterations = it;
    rep->rebuilds = S.L->rebuilds - rebuilds0;
    rep->max_force = worst;
    if (w->r0) *scale = S.scale;
    if (ramp && goal->stress > 0 && p < goal->stress) rep->capped = 1;
    st = fire_end(&S, goal, it, worst, p, rep, err);
done:
    gb_pair_set_free(&S.own), gb_pair_search_free(&S.search);
    free(S.gg), free(S.other), free(S.gk), free(S.on), free(S.chunk), free(S.part);
    free(S.fw), free(S.vw), free(S.dX);
    free(v), free(f);
    return st;
}

gb_status gb_fire_relax(const gb_fire_world *w, double tol, long max_iter, gb_fire_report *rep, gb_error *err)
{
    gb_fire_world held = *w;
    held.r0 = NULL;
    gb_fire_goal goal = {.tol = tol, .max_iter = max_iter};
    double scale = 1;
    return gb_fire_relax_scaled(&held, &goal, &scale, rep, err);
}
