/* Candidate pairs (a Verlet list built with a cell grid) and the contact model on them:
 * kinematics (K 1, 2, 25), the spring law (K 3, 4, 6), opening and Coulomb (K 13). */
#ifndef GB_PAIRS_H
#define GB_PAIRS_H

#include <limits.h>
#include <math.h>
#include <string.h>

#include "gembem/bem.h"
#include "gembem/grain.h"

/* Boundary particles (the hybrid method, docs/method.md section 10): one half-disc on each element of
 * a host's cavity, of diameter the element's length, centred on its midpoint and bulging into the
 * cavity; it moves with its element (2 DOFs, no rotation). In a pair it is j = GB_PARTICLE_J(e)
 * (gembem/grain.h). */

typedef struct {
    int n;
    double *x, *y;    /* centres now (midpoint + element displacement) */
    double *r;        /* half the element length */
    double *nx, *ny;  /* the side it bulges to: the body's outward normal, into the cavity */
    double *dx;       /* its move in the current iteration, 2 per particle */
} gb_particles;

/* The particles of the elements elem[0..m) of mesh, at rest: on each element's midpoint, of radius
 * half its length, bulging along its normal. */
gb_status gb_particles_create(gb_particles *bp, const gb_bem_mesh *mesh, const int *elem, int m, gb_error *err);
void gb_particles_free(gb_particles *bp);

/* What grains touch: each other, the four walls of a box (if any) and boundary particles (if any). */
typedef struct {
    const gb_grain *g;
    int n;
    const gb_box *box;       /* NULL: no walls */
    const gb_particles *bp;  /* NULL: no boundary particles */
} gb_world;

/* A pair of grains, or a grain and a wall or a boundary particle, that may touch before the next rebuild. It keeps the
 * contact's state between iterations. */
typedef struct {
    int i, j;        /* j >= 0: grain (j > i); -GB_N_WALLS <= j < 0: wall -1 - j; else a particle */
    double nx, ny;   /* unit normal from i towards j, at the last geometry update */
    double d;        /* overlap; the pair is a contact when d > 0 */
    double pn, pt;   /* contact forces, compression positive; zero when open */
    double mr;       /* rolling moment on grain i (counter-clockwise), -mr on j; 0 without rolling */
    double diss;     /* energy dissipated at this contact in the current load step */
} gb_pair;

/* The law a pair's other end takes (the scene's grain_grain, grain_wall, grain_boundary): gembem's
 * solver (gb_sim_material) and FIRE's packings (src/pack/fire.c) index their materials by it. */
enum { GB_END_GRAIN, GB_END_WALL, GB_END_PARTICLE };
static inline int gb_pair_end(int j) { return j >= 0 ? GB_END_GRAIN : GB_IS_PARTICLE(j) ? GB_END_PARTICLE : GB_END_WALL; }

/* (K 2): a contact's forces pn, pt in the plane, pn n + pt t with t = (-ny, nx): on j, the
 * opposite on i. */
static inline void gb_pair_force(const gb_pair *p, double pn, double pt, double *fx, double *fy)
{
    *fx = p->nx * pn - p->ny * pt, *fy = p->ny * pn + p->nx * pt;
}

/* The candidate pairs and where they were found: part of a simulation's state (src/gem/sim.h),
 * saved and restored with the grains. */
typedef struct {
    gb_pair *p;
    int n, cap;           /* a rebuild never lowers cap: a list saved earlier fits when restored */
    double *x0;           /* grain positions at the last rebuild (2 per grain) */
    double *px0;          /* particle centres at the last rebuild (2 per particle) */
    gb_box box0;          /* walls at the last rebuild */
    long rebuilds;
    /* Which rebuild the list's pairs come from, unique within the process: `rebuilds` goes back
     * when a saved state is restored and may then count a different list, this never repeats. */
    long generation;
} gb_pair_set;

/* A grain in the search's cell order: its centre and radius at the rebuild, and its index. */
typedef struct {
    double x, y, r;
    int j;
} gb_cell_entry;

/* A rebuild runs on threads from this many grains; at most this many threads. */
enum { GB_PAIRS_PARALLEL = 4096, GB_PAIRS_MAX_THREADS = 64 };

/* How pairs are found: the skin and the search's buffers, which no state needs. */
typedef struct {
    double skin;          /* extra distance covered by the list */
    gb_pair *tmp;         /* the next list while rebuilding */
    int tmp_cap;
    int *pcell_head, *pcell_next, n_pcells_cap, n_particles_cap; /* boundary particles by cell */
    int *cell_start, n_cells_cap; /* cell c's grains: cell_grains[cell_start[c] .. cell_start[c + 1]) */
    gb_cell_entry *cell_grains;
    int *grain_cell;      /* each grain's cell */
    int threads;          /* OpenMP threads of a rebuild (1 if 0); the list is the same on any count */
    int *tcand[GB_PAIRS_MAX_THREADS]; /* each thread's candidates, grain after grain */
    int tcand_cap[GB_PAIRS_MAX_THREADS];
    int *count, count_cap;         /* per grain: its candidates, then its first pair's index */
    int *old_start, old_start_cap; /* per grain: its first pair in the old list */
    long generations;     /* of the lists built in this process (gb_pair_set.generation) */
} gb_pair_search;

/* The most candidate pairs a list holds: pairs are indexed and counted in ints. A packing has
 * about 10 per grain, so only some 2e8 grains reach it. */
#define GB_PAIRS_MAX INT_MAX

/* Turns the candidate counts of grains 0..n-1 in count[0..n) into offsets: count[i] the index of
 * grain i's first pair, count[n] the total. A total above GB_PAIRS_MAX is refused (GB_ENOMEM, what
 * to change in the message) and count left as it was: counted in ints, it would wrap. */
gb_status gb_pairs_offsets(int *count, int n, gb_error *err);

void gb_pair_set_free(gb_pair_set *P);
void gb_pair_search_free(gb_pair_search *S);

/* Rebuilds the candidate pairs from scratch with a cell grid (no O(N^2) loop), carrying over
 * the state of the pairs that persist. Both lists are sorted by (i, j). */
gb_status gb_pairs_rebuild(gb_pair_set *P, gb_pair_search *S, const gb_world *w, gb_error *err);

/* The grain pairs i < j whose discs overlap (distance below r_i + r_j), found with the rebuild's
 * cell grid but without building a list, so that an admission check costs no pair list however
 * many grains coincide: visit(user, i, j, d) with the overlap d, grain after grain in increasing
 * i (its partners in cell order). A nonzero return stops the scan once grain i's pairs are
 * visited. S's cell buffers are used (S->skin is ignored). */
typedef int (*gb_pair_visit)(void *user, int i, int j, double d);
gb_status gb_pairs_scan_overlaps(gb_pair_search *S, const gb_world *w, gb_pair_visit visit, void *user,
                                 gb_error *err);

/* The grains' order by cell: order[k] is the index of the k-th grain of g[0..n) in the grid of
 * gb_pairs_rebuild over their extent, cells row by row from the bottom, each cell's grains in
 * increasing index. Neighbours are then near in memory: a simulation keeps its grains so
 * (src/gem/sim.c), as LAMMPS sorts its atoms by bin. */
gb_status gb_grains_cell_order(const gb_grain *g, int n, int *order, gb_error *err);
/* True when some grain or wall has moved far enough since the last rebuild that a new contact
 * could be missing from the list. */
int gb_pairs_stale(const gb_pair_set *P, const gb_pair_search *S, const gb_world *w);
/* The same test in parts, for callers that measure the grains' drift as they move them: the test
 * on the largest displacement since the rebuild of a grain (`grain`) and of a wall or particle
 * (`wall`), the walls' and particles' largest displacement, and one grain's squared one. */
int gb_pairs_drift_stale(const gb_pair_search *S, double grain, double wall);
double gb_pairs_wall_drift(const gb_pair_set *P, const gb_world *w);
static inline double gb_pairs_grain_drift2(const gb_pair_set *P, const gb_world *w, int i)
{
    double dx = w->g[i].x - P->x0[2 * i], dy = w->g[i].y - P->x0[2 * i + 1];
    return dx * dx + dy * dy;
}

/* Overlap and normal of a pair at the current positions (inline: every contact at every iteration
 * of the solver and FIRE). A grain behind a boundary particle (on
 * its flat side) does not touch it: its overlap is set negative. */
static inline void gb_pair_geometry(gb_pair *p, const gb_world *w)
{
    const gb_grain *a = &w->g[p->i];
    if (p->j >= 0 || GB_IS_PARTICLE(p->j)) {
        double bx, by, br;
        const gb_particles *bp = w->bp;
        int e = GB_PARTICLE_OF(p->j);
        if (p->j >= 0) bx = w->g[p->j].x, by = w->g[p->j].y, br = w->g[p->j].r;
        else bx = bp->x[e], by = bp->y[e], br = bp->r[e];
        double dx = bx - a->x, dy = by - a->y, dist = sqrt(dx * dx + dy * dy);
        if (dist > 0) {
            p->nx = dx / dist;
            p->ny = dy / dist;
        } /* coincident centres keep the previous normal rather than invent one */
        p->d = a->r + br - dist;
        /* A half-disc: the grain must be on the side the particle bulges to. */
        if (p->j < 0 && -(p->nx * bp->nx[e] + p->ny * bp->ny[e]) <= 0 && p->d > 0) p->d = -p->d;
        return;
    }
    const gb_box *box = w->box;
    switch (-1 - p->j) {
    case GB_WALL_LEFT: p->nx = -1, p->ny = 0, p->d = a->r - (a->x - box->left); break;
    case GB_WALL_RIGHT: p->nx = 1, p->ny = 0, p->d = a->r - (box->right - a->x); break;
    case GB_WALL_BOTTOM: p->nx = 0, p->ny = -1, p->d = a->r - (a->y - box->bottom); break;
    default: p->nx = 0, p->ny = 1, p->d = a->r - (box->top - a->y); break;
    }
}

/* (K 25): the tangential relative displacement of a pair, in its tangent t = (-ny, nx), for moves
 * a = (dx, dy, r dw) of grain i and b of its other end (a wall or a particle: b[2] = 0). */
static inline double gb_pair_du_t(const gb_pair *p, const double a[3], const double b[3])
{
    return -(a[0] - b[0]) * p->ny + (a[1] - b[1]) * p->nx + a[2] + b[2];
}

/* The elastic energy of a contact's springs (K 22), with the rolling spring's mr^2 / (2 kr). */
static inline double gb_spring_energy(double pn, double pt, double mr, const gb_material *m)
{
    double e = 0.5 * pn * pn / m->kn + (m->kt > 0 ? 0.5 * pt * pt / m->kt : 0);
    return m->kr > 0 ? e + 0.5 * mr * mr / m->kr : e;
}

/* The rolling radius R* of a pair (docs/method.md section 3.1): r_i r_j / (r_i + r_j) between
 * grains, r_i against a wall (a flat wall is a disc of infinite radius). */
static inline double gb_pair_rolling_radius(const gb_pair *p, const gb_world *w)
{
    double ri = w->g[p->i].r;
    if (p->j < 0) return ri;
    double rj = w->g[p->j].r;
    return ri * rj / (ri + rj);
}

/* The relative rolling of a pair in a move (docs/method.md section 3.1): dw_i - dw_j, dw_i alone
 * against a wall (walls do not rotate), for moves a = (dx, dy, r dw) of grain i and b of grain j. */
static inline double gb_pair_dtheta_r(const gb_pair *p, const gb_world *w, const double a[3], const double b[3])
{
    return a[2] / w->g[p->i].r - (p->j >= 0 ? b[2] / w->g[p->j].r : 0);
}

/* gb_pair_update's parts (below), inline for FIRE's loop over the contacts (src/pack/fire.c: 6 % of a
 * frictional packing's time). (K 25): the tangential relative displacement of a move in the
 * previous tangent t = (-ny, nx), and the relative rolling (with rolling resistance). */
static inline void gb_pair_moves(const gb_pair *p, const gb_world *w, const double *dX, const double *wall_dx,
                                 const gb_material *mat, double *du_t, double *dth)
{
    double b[3] = {0, 0, 0};
    if (p->j >= 0) memcpy(b, &dX[3 * p->j], sizeof b);
    else if (GB_IS_PARTICLE(p->j)) memcpy(b, &w->bp->dx[2 * GB_PARTICLE_OF(p->j)], 2 * sizeof(double));
    else memcpy(b, &wall_dx[2 * (-1 - p->j)], 2 * sizeof(double));
    *du_t = gb_pair_du_t(p, &dX[3 * p->i], b);
    *dth = mat->kr > 0 ? gb_pair_dtheta_r(p, w, &dX[3 * p->i], b) : 0;
}

/* A grain pair that did not touch and does not now: its update changes nothing that is read (its
 * forces stay zero, a new contact starts from zero: K section 2.5), so it is skipped on a squared
 * distance, without the root and divisions of its normal; its nx, ny and d then keep their last
 * values (d <= 0). Most candidate pairs are apart in a packing that loosens: the 1e5 peer
 * relaxation ends with 113 009 contacts, and FIRE's frictional loop (src/pack/fire.c) skips them
 * the same way. */
static inline int gb_pair_stays_apart(const gb_pair *p, const gb_world *w)
{
    if (p->j < 0 || p->d > 0) return 0;
    const gb_grain *a = &w->g[p->i], *b = &w->g[p->j];
    double dx = b->x - a->x, dy = b->y - a->y, sum = a->r + b->r;
    return dx * dx + dy * dy >= sum * sum;
}

/* The law (K 6, 13): the forces at the current geometry from those before the move. */
static inline void gb_pair_law(gb_pair *p, const gb_world *w, int was_contact, double du_t, double dth,
                               const gb_material *mat, double tan_phi)
{
    gb_pair_geometry(p, w);
    if (!(p->d > 0)) { /* opened (K section 2.5): both forces vanish */
        p->pn = p->pt = p->mr = 0;
        return;
    }
    p->pn = mat->kn * p->d;
    double pt = was_contact ? p->pt + mat->kt * du_t : 0.0;
    double limit = p->pn * tan_phi + mat->cohesion; /* (K 13) */
    /* the cap as min and max without branches (slipping and sticking contacts mix unpredictably),
     * a NaN kept: MINSD and MAXSD return their second operand when either is NaN */
    pt = limit < pt ? limit : pt;
    p->pt = -limit > pt ? -limit : pt;
    if (mat->kr > 0) {
        /* Rolling resistance (docs/method.md section 3.1): the same incremental law on the moment. */
        p->mr = was_contact ? p->mr - mat->kr * dth : 0.0;
        double mlim = mat->eta * gb_pair_rolling_radius(p, w) * p->pn;
        if (p->mr > mlim) p->mr = mlim;
        else if (p->mr < -mlim) p->mr = -mlim;
    }
}

/* The forces of gb_pair_update without the energy dissipated (FIRE's packings need none). */
static inline void gb_pair_update_forces(gb_pair *p, const gb_world *w, const double *dX, const double *wall_dx,
                                         const gb_material *mat, double tan_phi)
{
    int was_contact = p->d > 0;
    double du_t, dth;
    gb_pair_moves(p, w, dX, wall_dx, mat, &du_t, &dth);
    gb_pair_law(p, w, was_contact, du_t, dth, mat, tan_phi);
}

/* Contact forces after a move (K 6, 13): the normal force follows the overlap, pn = kn d (a new
 * contact starts at kn d, see docs/method.md section 3); the tangential force is incremental,
 * pt += kt du_t with du_t from (K 25) in the tangent of the previous configuration; a contact
 * that opens (d <= 0) drops both forces; |pt| is capped at pn tan(phi) + c. With rolling
 * resistance (mat->kr > 0, docs/method.md section 3.1) the rolling moment follows the same
 * incremental law: mr -= kr dtheta_r, capped at eta R* pn, dropped when the contact opens.
 * dX holds (dx, dy, r dw) per grain, wall_dx the translation (dx, dy) of each wall, w->bp->dx
 * the particles' moves.
 * Returns the energy dissipated by the update, also added to p->diss: the slip
 * du_d = du_t - dpt/kt times the mean tangential force, zero if either end is zero (K 26-28), and,
 * when the contact opens, the tangential spring energy pt^2/(2 kt) that it releases; the same for
 * the rolling spring (slip -dtheta_r - dmr/kr times the mean moment, mr^2/(2 kr) on opening).
 * Inline: every candidate pair at every step of the solver's smoother. */
static inline double gb_pair_update(gb_pair *p, const gb_world *w, const double *dX, const double *wall_dx,
                                    const gb_material *mat, double tan_phi)
{
    if (gb_pair_stays_apart(p, w)) return 0;
    int was_contact = p->d > 0;
    double du_t, dth, pt0 = p->pt, mr0 = p->mr, diss = 0;
    gb_pair_moves(p, w, dX, wall_dx, mat, &du_t, &dth);
    gb_pair_law(p, w, was_contact, du_t, dth, mat, tan_phi);
    if (!(p->d > 0)) {
        /* the tangential (and rolling) spring's energy is lost */
        if (was_contact && mat->kt > 0) diss = pt0 * pt0 / (2 * mat->kt);
        if (was_contact && mat->kr > 0) diss += mr0 * mr0 / (2 * mat->kr);
    } else {
        /* Only a contact the cap held slips: where pt followed its spring (the law's pt0 + kt du_t,
         * the same bits) du_d is zero, and not computed (a division: a tenth of this function's
         * time in the 1e6 peer relaxation). */
        if (was_contact && mat->kt > 0 && pt0 != 0 && p->pt != 0 && p->pt != pt0 + mat->kt * du_t) {
            double slip = du_t - (p->pt - pt0) / mat->kt; /* (K 26, 27) */
            diss = 0.5 * (pt0 + p->pt) * slip;            /* (K 28) */
        }
        if (mat->kr > 0 && was_contact && mr0 != 0 && p->mr != 0)
            diss += 0.5 * (mr0 + p->mr) * (-dth - (p->mr - mr0) / mat->kr);
    }
    p->diss += diss;
    return diss;
}

/* Brute-force O(N^2) candidate pairs within `range` of touching, for tests. Returns the count and
 * fills out (sorted by (i, j), grains only) up to cap. */
int gb_pairs_brute_force(const gb_grain *g, int n, double range, int *out_i, int *out_j, int cap);

#endif
