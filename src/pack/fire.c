/* FIRE relaxation of frictionless discs (fire.h), moved here from tools/packgen/jam.c: the
 * published parameters, the time step from the stiffest spring and the lightest disc. Contacts
 * come from the contact module (its cell list and geometry: walls, grains and half-disc boundary
 * particles as gembem's solver sees them). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pack/fire.h"

static const double PI = 3.14159265358979323846;

/* Forces of the springs and the body force into f (2 per disc); returns the largest |F|. */
static double forces(const gb_fire_world *w, gb_pair_list *L, const gb_world *world, double *f, gb_fire_report *rep)
{
    for (int i = 0; i < w->n; i++) {
        double a = PI * w->g[i].r * w->g[i].r;
        f[2 * i] = w->body[0] * a, f[2 * i + 1] = w->body[1] * a;
    }
    rep->virial = 0, rep->contacts = rep->wall_contacts = 0, rep->largest_overlap = 0;
    memset(rep->wall, 0, sizeof rep->wall);
    for (int k = 0; k < L->n; k++) {
        gb_pair *p = &L->p[k];
        gb_pair_geometry(p, world);
        if (!(p->d > 0)) continue;
        int i = p->i, j = p->j;
        double kn = j >= 0 ? w->kn_gg : GB_IS_PARTICLE(j) ? w->kn_gb : w->kn_gw, pn = kn * p->d;
        f[2 * i] -= pn * p->nx, f[2 * i + 1] -= pn * p->ny;
        if (j >= 0) {
            f[2 * j] += pn * p->nx, f[2 * j + 1] += pn * p->ny;
            rep->virial += pn * (w->g[i].r + w->g[j].r - p->d);
            rep->largest_overlap = fmax(rep->largest_overlap, p->d / fmin(w->g[i].r, w->g[j].r));
        } else {
            rep->virial += pn * (w->g[i].r - 0.5 * p->d);
            if (!GB_IS_PARTICLE(j)) rep->wall[-1 - j] += pn, rep->wall_contacts++;
        }
        rep->contacts++;
    }
    double worst = 0;
    for (int i = 0; i < w->n; i++) worst = fmax(worst, hypot(f[2 * i], f[2 * i + 1]));
    return worst;
}

gb_status gb_fire_relax(const gb_fire_world *w, double tol, long max_iter, gb_fire_report *rep, gb_error *err)
{
    int n = w->n;
    memset(rep, 0, sizeof *rep);
    double *v = calloc(2 * (size_t)n + 1, sizeof(double)), *f = malloc((2 * (size_t)n + 1) * sizeof(double));
    double *m = malloc(((size_t)n + 1) * sizeof(double));
    gb_pair_list L;
    memset(&L, 0, sizeof L);
    gb_status st = GB_OK;
    if (!v || !f || !m) {
        st = gb_fail(err, GB_ENOMEM, "out of memory for the relaxation of %d grains", n);
        goto done;
    }
    double rmin = HUGE_VAL, kn = fmax(w->kn_gg, fmax(w->box ? w->kn_gw : 0, w->bp ? w->kn_gb : 0));
    for (int i = 0; i < n; i++) {
        m[i] = PI * w->g[i].r * w->g[i].r; /* unit density: only the dynamics' pace */
        rmin = fmin(rmin, w->g[i].r);
    }
    gb_world world = {w->g, n, w->box, w->bp};
    L.skin = 0.2 * rmin;
    if ((st = gb_pairs_rebuild(&L, &world, err))) goto done;

    const double dt_max = 0.3 * sqrt(PI * rmin * rmin / kn), f_inc = 1.1, f_dec = 0.5, a_start = 0.1, f_a = 0.99;
    const int n_min = 5;
    double dt = 0.1 * dt_max, alpha = a_start, worst = forces(w, &L, &world, f, rep);
    int since_neg = 0;
    long it = 0;
    for (; worst > tol && it < max_iter; it++) {
        double P = 0, vv = 0, ff = 0;
        for (int k = 0; k < 2 * n; k++) P += f[k] * v[k], vv += v[k] * v[k], ff += f[k] * f[k];
        if (P > 0) {
            double mix = ff > 0 ? alpha * sqrt(vv / ff) : 0;
            for (int k = 0; k < 2 * n; k++) v[k] = (1 - alpha) * v[k] + mix * f[k];
            if (++since_neg > n_min) dt = fmin(dt * f_inc, dt_max), alpha *= f_a;
        } else {
            since_neg = 0;
            dt *= f_dec;
            alpha = a_start;
            memset(v, 0, 2 * (size_t)n * sizeof(double));
        }
        for (int i = 0; i < n; i++) {
            v[2 * i] += dt * f[2 * i] / m[i], v[2 * i + 1] += dt * f[2 * i + 1] / m[i];
            w->g[i].x += dt * v[2 * i], w->g[i].y += dt * v[2 * i + 1];
        }
        if (gb_pairs_stale(&L, &world) && (st = gb_pairs_rebuild(&L, &world, err))) goto done;
        worst = forces(w, &L, &world, f, rep);
        if (!isfinite(worst)) {
            st = gb_fail(err, GB_ENUMERIC, "the packing's forces became non-finite at FIRE iteration %ld", it);
            goto done;
        }
    }
    rep->iterations = it;
    rep->max_force = worst;
    if (worst > tol)
        st = gb_fail(err, GB_ENOCONV, "FIRE did not bring the largest force below %g in %ld iterations (it is %g)",
                     tol, max_iter, worst);
done:
    gb_pairs_free(&L);
    free(v), free(f), free(m);
    return st;
}
