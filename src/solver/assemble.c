/* Assembly of the global system: the tangent of every contact and the sparse matrix of grains,
 * walls and boundary particles (with the host's condensed stiffness). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "solver/global_impl.h"

/* The tangent stiffness, as a share of kn, of a frictionless single contact in the system. */
static const double SINGLE_CONTACT_KT = 1e-2;

/* The length that converts wall DOF w into the inward displacement of wall `wall` (0 if the wall
 * does not move with it): 1 for the axes, half the reference side for the isotropic strain. */
double gb_global_wall_lever(const gb_sim *sim, int w, int wall)
{
    int is_x = wall == GB_WALL_LEFT || wall == GB_WALL_RIGHT;
    if (w == W_X) return is_x ? 1 : 0;
    if (w == W_Y) return is_x ? 0 : 1;
    return is_x ? 0.5 * sim->ref_width : 0.5 * sim->ref_height;
}

/* The rolling stiffness of a contact in the tangent (docs/method.md section 3.1): kr, or 0 at the
 * cap eta R* pn (it rolls on, as a sliding contact slides) unless the contact sticks (gl->stick:
 * a grain's single contact). */
static double rolling_k(const gb_global *gl, const gb_sim *sim, const gb_pair *p, int k, const gb_material *m)
{
    if (!(m->kr > 0)) return 0;
    if (gl->stick[k]) return m->kr;
    double limit = m->eta * gb_pair_rolling_radius(p, &sim->world) * p->pn;
    return fabs(p->mr) >= limit * (1 - 1e-9) ? 0 : m->kr;
}

/* The tangent stiffness of every contact and the diagonal blocks of grains and particles. Unlike
 * the reference iteration, which keeps kt in S (K 8), a contact at its Coulomb limit (K 13) gets no
 * tangential stiffness: it slides, and Newton's method converges when its tangent is the true one. */
gb_status gb_global_pair_buffers(gb_global *gl, const gb_pair_set *P, gb_error *err)
{
    if (P->n <= gl->kt_cap) return GB_OK;
    double *kt = realloc(gl->kt, (size_t)P->cap * sizeof(double));
    if (kt) gl->kt = kt;
    unsigned char *stick = realloc(gl->stick, (size_t)P->cap);
    if (stick) gl->stick = stick;
    double *slide = realloc(gl->slide, (size_t)P->cap * sizeof(double));
    if (slide) gl->slide = slide;
    unsigned char *unloading = realloc(gl->unloading, (size_t)P->cap);
    if (unloading) gl->unloading = unloading;
    if (!kt || !stick || !slide || !unloading) return gb_fail(err, GB_ENOMEM, "out of memory");
    memset(gl->unloading + gl->kt_cap, 0, (size_t)(P->cap - gl->kt_cap));
    gl->kt_cap = P->cap;
    return GB_OK;
}

void gb_global_tangents(gb_global *gl, const gb_sim *sim)
{
    int exact = gl->set->newton == GB_NEWTON_LINE_SEARCH;
    memset(gl->S, 0, 6 * (size_t)gl->n * sizeof(double));
    memset(gl->Sp, 0, 3 * (size_t)gl->np * sizeof(double));
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        gl->kt[k] = 0;
        if (!(p->d > 0)) continue;
        const gb_material *m = gb_sim_material(sim, p->j);
        double limit = p->pn * gb_sim_tan_phi(sim, p->j) + m->cohesion;
        double kn = m->kn, kt = fabs(p->pt) >= limit * (1 - 1e-9) && !gl->stick[k] ? 0 : m->kt;
        /* The single contact of a grain in the system without a tangential spring: a tangent
         * stiffness of its own along t keeps the grain's block regular. Its force has no
         * tangential part, so the solution does not slide it: only K, not the forces, sees it. */
        if (gl->stick[k] && !(kt > 0)) kt = SINGLE_CONTACT_KT * kn;
        gl->kt[k] = kt;
        /* The exact tangent of a sliding contact: pt = +-(pn tan phi + c) follows the overlap. */
        gl->slide[k] = !(kt > 0) && exact && p->pt != 0 && (p->j >= 0 || GB_IS_PARTICLE(p->j)) ? (p->pt > 0 ? 1 : -1) * kn * gb_sim_tan_phi(sim, p->j) : 0;
        double c = p->nx, s = p->ny;
        double s00 = kn * c * c + kt * s * s, s01 = (kn - kt) * c * s, s11 = kn * s * s + kt * c * c;
        double *S = &gl->S[6 * p->i], kr = rolling_k(gl, sim, p, k, m), ri = sim->state.g[p->i].r;
        S[0] += s00, S[1] += s01, S[2] += -kt * s, S[3] += s11, S[4] += kt * c, S[5] += kt + kr / (ri * ri);
        if (p->j >= 0) {
            double rj = sim->state.g[p->j].r;
            S = &gl->S[6 * p->j];
            S[0] += s00, S[1] += s01, S[2] += kt * s, S[3] += s11, S[4] += -kt * c, S[5] += kt + kr / (rj * rj);
        } else if (GB_IS_PARTICLE(p->j)) {
            double *Sp = &gl->Sp[3 * GB_PARTICLE_OF(p->j)];
            Sp[0] += s00, Sp[1] += s01, Sp[2] += s11;
        }
    }
}

/* The exact tangent's terms of a contact between grain i and node j (a grain, nb = 3, or a boundary
 * particle, nb = 2) beyond K 8 and 25, for a Newton method whose tangent is the derivative of the
 * forces it balances (solver.newton: line_search; unsymmetric, UMFPACK):
 * - a sliding contact, pt = +-(pn tan phi + c): its diagonal blocks' part, row t from column n
 *   (the off-diagonal part is added with K 25's blocks);
 * - the contact's rotation (geometric stiffness): F_i = pn n + pt t with n, t turning with the
 *   branch vector of length l = r_i + r_j - d, so dF_i = (pn t - pt n) (t . (dx_j - dx_i)) / l and
 *   F_j = -F_i. Compression makes it negative along t: it is what decides whether a chain of
 *   grains buckles, and a tangent without it predicts the wrong sign of the force change along the
 *   soft (rolling) modes of a loose packing, where Newton's step then raises the residual. */
static void add_exact_diagonal(gb_global *gl, const gb_sim *sim, const gb_pair *p, int k, int i, int j, int nb)
{
    const unsigned char *held = gl->held;
    double c = p->nx, s = p->ny, sl = gl->slide[k];
    double r1[3] = {c, s, 0}, r2[3] = {-s, c, 1}, q1[3] = {-c, -s, 0}, q2[3] = {s, -c, 1};
    int qi = entry_of(gl, i, i), qj = entry_of(gl, j, j), dj = gl->dof0[j];
    if (sl != 0) {
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                if (!held[3 * i + a] && !held[3 * i + b]) add(gl, i, b, qi, a, sl * r2[a] * r1[b]);
        for (int a = 0; a < nb; a++)
            for (int b = 0; b < nb; b++)
                if (!held[dj + a] && !held[dj + b]) add(gl, j, b, qj, a, sl * q2[a] * q1[b]);
    }
    double rj = p->j >= 0 ? sim->state.g[p->j].r : sim->bp.r[GB_PARTICLE_OF(p->j)];
    const gb_material *m = gb_sim_material(sim, p->j);
    if (p->j >= 0 && m->kr > 0 && rolling_k(gl, sim, p, k, m) == 0 && p->mr != 0) {
        /* A rolling moment at its cap follows the overlap: mr = +-eta R* kn d, d(d)/dx_i = n = -d(d)/dx_j;
         * on i the fixing force's third row is -mr / r_i, on j +mr / r_j (docs/method.md section 3.1). */
        double g = (p->mr > 0 ? 1 : -1) * m->eta * gb_pair_rolling_radius(p, &sim->world) * m->kn;
        double ri = sim->state.g[i].r;
        double nn[2] = {c, s};
        for (int b = 0; b < 2; b++) {
            if (!held[3 * i + 2] && !held[3 * i + b]) add(gl, i, b, qi, 2, -g * nn[b] / ri);
            if (!held[3 * i + 2] && !held[dj + b]) add(gl, j, b, gl->pos_ij[k], 2, g * nn[b] / ri);
            if (!held[dj + 2] && !held[3 * i + b]) add(gl, i, b, gl->pos_ji[k], 2, g * nn[b] / rj);
            if (!held[dj + 2] && !held[dj + b]) add(gl, j, b, qj, 2, -g * nn[b] / rj);
        }
    }
    double len = sim->state.g[i].r + rj - p->d, t[2] = {-s, c};
    double u[2] = {(p->pn * t[0] - p->pt * c) / len, (p->pn * t[1] - p->pt * s) / len};
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++) {
            double G = u[a] * t[b]; /* dF_i[a] / dx_j[b] */
            if (!held[3 * i + a] && !held[dj + b]) {
                add(gl, j, b, gl->pos_ij[k], a, G);
                add(gl, i, a, gl->pos_ji[k], b, u[b] * t[a]); /* dF_j[b] / dx_i[a] = G[b][a] (dF_j = -dF_i) */
            }
            if (!held[3 * i + a] && !held[3 * i + b]) add(gl, i, b, qi, a, -G);
            if (!held[dj + a] && !held[dj + b]) add(gl, j, b, qj, a, -G);
        }
}

/* K = sum over contacts of [T T']^t S_c [T T'] (K 1-8, 25) over grains, boundary particles (the
 * translational part of T') and walls, plus the host's condensed stiffness on the particles (its
 * symmetric part for a symmetric system: CHOLMOD, PETSc with newton: damped), held DOFs as identity
 * rows. A wall DOF that moves walls inward by lever x its value changes a wall contact's overlap by
 * as much: its coupling with grain i is kn lever (c, s, 0). */
/* The grains' diagonal blocks: each grain's contact stiffness S (K 8), its diagonal times 1 + shift. */
static void add_grain_blocks(gb_global *gl, double shift)
{
    const unsigned char *held = gl->held;
    for (int i = 0; i < gl->n; i++) {
        const double *S = &gl->S[6 * i];
        double blk[3][3] = {{S[0], S[1], S[2]}, {S[1], S[3], S[4]}, {S[2], S[4], S[5]}};
        int q = entry_of(gl, i, i);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                int h = held[3 * i + a] || held[3 * i + b];
                add(gl, i, b, q, a, h ? (a == b ? 1.0 : 0.0) : blk[a][b] * (a == b ? 1 + shift : 1));
            }
    }
}

/* The host's condensed stiffness between the boundary particles (its symmetric part for a
 * symmetric system), each particle's contact stiffness on its diagonal block. */
static void add_host(gb_global *gl, const gb_sim *sim, double shift)
{
    const unsigned char *held = gl->held;
    const gb_host *host = sim->host;
    const double *K = gl->symmetric ? host->Ksym : host->K.K;
    int m = host->m, n = gl->n, np = gl->np;
    for (int e = 0; e < np; e++) {
        int first = entry_of(gl, n + e, n); /* the particles are contiguous in every particle's list */
        for (int f = 0; f < np; f++)
            for (int a = 0; a < 2; a++)
                for (int b = 0; b < 2; b++) {
                    double v = K[(2 * f + a) + (size_t)(2 * e + b) * m];
                    if (held[gl->dof0[n + e] + b] || held[gl->dof0[n + f] + a]) {
                        add(gl, n + e, b, first + f, a, f == e && a == b ? 1.0 : 0.0);
                        continue;
                    }
                    if (f == e) {
                        const double *Sp = &gl->Sp[3 * e];
                        double c[2][2] = {{Sp[0], Sp[1]}, {Sp[1], Sp[2]}};
                        v += c[a][b];
                        if (a == b) v *= 1 + shift;
                    }
                    add(gl, n + e, b, first + f, a, v);
                }
    }
}

/* A grain's contact with a wall: its coupling with each wall DOF that moves the wall (kn lever
 * (c, s, 0)), the wall DOF's own stiffness into kww. */
static void add_wall_contact(gb_global *gl, const gb_sim *sim, const gb_pair *p, double kn, double *kww)
{
    const unsigned char *held = gl->held;
    int i = p->i, n = gl->n;
    double g[2] = {kn * p->nx, kn * p->ny};
    for (int w = 0; w < NW; w++) {
        double lever = gb_global_wall_lever(sim, w, -1 - p->j);
        int nw = wall_node(gl, w);
        if (lever == 0 || held[gl->dof0[nw]]) continue;
        kww[w] += kn * lever * lever;
        int qi = gl->wall_in_grain[w * (n + 1) + i], qw = gl->grain_in_wall[w * (n + 1) + i];
        for (int a = 0; a < 2; a++) {
            if (held[3 * i + a]) continue;
            add(gl, i, a, qi, 0, g[a] * lever);  /* (wall, grain a) */
            add(gl, nw, 0, qw, a, g[a] * lever); /* (grain a, wall) */
        }
    }
}

/* A contact k between grain i and a grain or boundary particle: the off-diagonal blocks
 * T^t S_c T' (K 1-8, 25), a sliding contact's pt following the overlap, the rolling spring, and
 * with the line search the exact tangent's diagonal terms. */
static void add_pair(gb_global *gl, const gb_sim *sim, const gb_pair *p, int k, const gb_material *mat)
{
    const unsigned char *held = gl->held;
    int i = p->i, n = gl->n;
    double c = p->nx, s = p->ny, kn = mat->kn, kt = gl->kt[k];
    double r1[3] = {c, s, 0}, r2[3] = {-s, c, 1}, q1[3] = {-c, -s, 0}, q2[3] = {s, -c, 1};
    int j = p->j >= 0 ? p->j : n + GB_PARTICLE_OF(p->j), nb = p->j >= 0 ? 3 : 2;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < nb; b++) {
            if (held[3 * i + a] || held[gl->dof0[j] + b]) continue;
            double v = kn * r1[a] * q1[b] + kt * r2[a] * q2[b]; /* T^t S_c T' */
            double sl = gl->slide[k]; /* a sliding contact's pt follows the overlap (rows r2, q2) */
            add(gl, j, b, gl->pos_ij[k], a, v + sl * r2[a] * q1[b]); /* (i, a) row, (j, b) column */
            add(gl, i, a, gl->pos_ji[k], b, v + sl * q2[b] * r1[a]); /* (j, b) row, (i, a) column */
        }
    double kr = p->j >= 0 ? rolling_k(gl, sim, p, k, mat) : 0;
    if (kr > 0 && !held[3 * i + 2] && !held[gl->dof0[j] + 2]) {
        /* Rolling: F_i's third row holds -mr / r_i, F_j's +mr / r_j, mr -= kr (dw_i - dw_j). */
        double v = -kr / (sim->state.g[i].r * sim->state.g[p->j].r);
        add(gl, j, 2, gl->pos_ij[k], 2, v);
        add(gl, i, 2, gl->pos_ji[k], 2, v);
    }
    if (gl->set->newton == GB_NEWTON_LINE_SEARCH) add_exact_diagonal(gl, sim, p, k, i, j, nb);
}

void gb_global_assemble(gb_global *gl, const gb_sim *sim, double shift)
{
    memset(gl->Ax, 0, (size_t)gl->nnz * sizeof(double));
    add_grain_blocks(gl, shift);
    if (gl->np > 0) add_host(gl, sim, shift);
    double kww[NW] = {0, 0, 0};
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        if (!(p->d > 0)) continue;
        const gb_material *mat = gb_sim_material(sim, p->j);
        if (p->j < 0 && !GB_IS_PARTICLE(p->j)) add_wall_contact(gl, sim, p, mat->kn, kww);
        else add_pair(gl, sim, p, k, mat);
    }
    /* A wall DOF whose walls touch nothing gets the stiffness of one grain-wall contact, as in the
     * reference iteration. */
    for (int w = 0; w < NW; w++) {
        int nw = wall_node(gl, w);
        double lever = w == W_MEAN ? 0.5 * fmax(sim->ref_width, sim->ref_height) : 1;
        double kmin = sim->scene->grain_wall.kn * lever * lever;
        add(gl, nw, 0, entry_of(gl, nw, nw), 0, gl->held[gl->dof0[nw]] ? 1.0 : fmax(kww[w], kmin) * (1 + shift));
    }
}

