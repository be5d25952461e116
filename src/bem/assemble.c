/* (H 3-5): the influence matrices H and G of constant elements, dense and column-major. The
 * closed forms of bem/segment.c, specialised for speed: the column block of element j is filled
 * for every collocation point i, log r at the element's start node is reused from the previous
 * element of the loop (its end node), and the columns are shared between threads. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bem/kernel.h"
#include "core/memory.h"
#include "gembem/bem.h"

void gb_bem_system_free(gb_bem_system *sys)
{
    if (!sys) return;
    free(sys->H);
    free(sys->G);
    memset(sys, 0, sizeof *sys);
}

typedef struct {
    const gb_bem_mesh *m;
    const gb_bem_kconst *k;
    gb_bem_system *sys;
    int j0, j1;   /* columns (elements) of this worker */
    double *lr;   /* 2 n: log r to the start and end node of the current element, per row */
    double *flux; /* n_loops x 2n: w_k^t H_half, see gb_bem_assemble */
} work;

static void fill_columns(work *w)
{
    const gb_bem_mesh *m = w->m;
    const gb_bem_kconst *k = w->k;
    size_t nd = 2 * (size_t)m->n;
    int n = m->n;
    double nu = k->nu, c34 = 3 - 4 * nu, c12 = 1 - 2 * nu, cu = k->cu, cp = k->cp, ch = -1 / (2 * GB_PI);
    double *pe = w->lr, *ce = w->lr + n; /* logs at the previous element's end node, this one's */
    const double *X = m->mid;
    for (int j = w->j0; j < w->j1; j++) {
        const double *a = m->p0 + 2 * j, *t = m->tangent + 2 * j;
        double L = m->length[j], tx = t[0], ty = t[1], txx = tx * tx, tyy = ty * ty, txy = tx * ty;
        /* the start node's logs are the previous element's end-node logs when it is the same node */
        int reuse = j > w->j0 && m->loop[j - 1] == m->loop[j];
        double *H0 = w->sys->H + (size_t)(2 * j) * nd, *H1 = H0 + nd;
        double *G0 = w->sys->G + (size_t)(2 * j) * nd, *G1 = G0 + nd;
        for (int i = 0; i < n; i++) {
            double ax = a[0] - X[2 * i], ay = a[1] - X[2 * i + 1];
            double u1 = ax * tx + ay * ty, hh = ax * ty - ay * tx, u2 = u1 + L;
            double h2 = hh * hh, r1s = u1 * u1 + h2, r2s = u2 * u2 + h2;
            double lr1 = reuse ? pe[i] : 0.5 * log(r1s), lr2 = 0.5 * log(r2s);
            ce[i] = lr2;
            double th, P, Q, dl;
            if (i == j) {
                th = P = Q = dl = 0;
                hh = 0;
            } else {
                th = atan2(hh * L, u1 * u2 + h2);
                P = 0.5 * hh * (u2 / r2s - u1 / r1s);
                Q = 0.5 * h2 * (1 / r2s - 1 / r1s);
                dl = lr2 - lr1;
            }
            double I0 = u2 * lr2 - u1 * lr1 - L + hh * th;
            double g00 = cu * (-c34 * I0 + (L - hh * th)), g01 = cu * hh * dl, g11 = cu * (-c34 * I0 + hh * th);
            double h00 = cp * (c12 * th + th - 2 * P), h01 = cp * (-2 * Q - c12 * dl);
            double h10 = cp * (-2 * Q + c12 * dl), h11 = cp * (c12 * th + th + 2 * P);
            /* M = R M_loc R^t, R = [t n], n = (ty, -tx) */
            G0[2 * i] = g00 * txx + g11 * tyy + 2 * g01 * txy;
            G1[2 * i + 1] = g00 * tyy + g11 * txx - 2 * g01 * txy;
            G1[2 * i] = G0[2 * i + 1] = (g00 - g11) * txy - g01 * (txx - tyy);
            H0[2 * i] = h00 * txx + h11 * tyy + (h01 + h10) * txy;
            H1[2 * i + 1] = h00 * tyy + h11 * txx - (h01 + h10) * txy;
            H1[2 * i] = (h00 - h11) * txy - h01 * txx + h10 * tyy;
            H0[2 * i + 1] = (h00 - h11) * txy + h01 * tyy - h10 * txx;
            if (i == j) { /* c = 1/2 I at a smooth midpoint */
                H0[2 * i] += 0.5;
                H1[2 * i + 1] += 0.5;
            }
            /* the incompressible part (nu = 1/2) of H, projected on L_i n_i, per loop of row i */
            double a00 = ch * (th - 2 * P), a11 = ch * (th + 2 * P), a01 = ch * (-2 * Q);
            double A00 = a00 * txx + a11 * tyy + 2 * a01 * txy, A11 = a00 * tyy + a11 * txx - 2 * a01 * txy;
            double A01 = (a00 - a11) * txy - a01 * (txx - tyy);
            if (i == j) A00 += 0.5, A11 += 0.5;
            double wx = m->length[i] * m->normal[2 * i], wy = m->length[i] * m->normal[2 * i + 1];
            double *fl = w->flux + (size_t)m->loop[i] * nd;
            fl[2 * j] += wx * A00 + wy * A01;
            fl[2 * j + 1] += wx * A01 + wy * A11;
        }
        double *tmp = pe; /* this element's end node starts the next one */
        pe = ce;
        ce = tmp;
    }
}

/* The breathing mode. For an incompressible material (nu = 1/2) the flux identities of the
 * double-layer field give, for every loop k with weights w_k = (L_i n_i) on its rows,
 *   w_k^t H_half = 0 (a cavity),   w_k^t H_half = w^t (the outer loop; w over all loops),
 * and H's dependence on nu is H = H_half + (1 - 2 nu) (...). Constant elements satisfy these
 * identities only to O(h^2) (O(h) next to corners), which is harmless for nu = 0.3 but is divided
 * by 1 - 2 nu in the breathing mode of a traction-loaded loop (u = n, where both H and G tend to
 * zero like 1 - 2 nu): at nu = 0.499 a pressurised hole was off by 25 % with 64 elements. The
 * defect is removed by one rank-one update per loop, H -= n_k d_k^t / P_k (n_k the normals on the
 * loop's rows, P_k its perimeter), which changes H by O(h^2) and keeps H times a rigid translation
 * exact (d_k sums to zero against it). */
static void breathing_correction(const gb_bem_mesh *m, gb_bem_system *sys, double *flux)
{
    size_t nd = (size_t)sys->ndof;
    for (int k = 0; k < m->n_loops; k++) {
        double *d = flux + (size_t)k * nd, P = 0;
        if (m->loop_outer[k])
            for (size_t c = 0; c < nd; c++) d[c] -= m->length[c / 2] * m->normal[c];
        for (int e = m->loop_start[k]; e < m->loop_start[k + 1]; e++) P += m->length[e];
        for (size_t c = 0; c < nd; c++) {
            double f = d[c] / P, *col = sys->H + c * nd;
            for (int e = m->loop_start[k]; e < m->loop_start[k + 1]; e++) {
                col[2 * e] -= m->normal[2 * e] * f;
                col[2 * e + 1] -= m->normal[2 * e + 1] * f;
            }
        }
    }
}

static void *worker(void *arg)
{
    fill_columns(arg);
    return NULL;
}

gb_status gb_bem_assemble(const gb_bem_mesh *m, const gb_bem_material *mat, gb_bem_system *sys, gb_error *err)
{
    memset(sys, 0, sizeof *sys);
    gb_bem_kconst k;
    gb_status st = gb_bem_kconst_init(mat, &k, err);
    if (st) return st;
    if (m->n < 1) return gb_fail(err, GB_EINPUT, "the boundary mesh is empty");
    /* The method is dense: H and G, then the mixed system's copy for its LU and the condensation's
     * right-hand sides, about four (2n)^2 matrices of doubles. A mesh that cannot fit is refused
     * before anything is allocated, rather than left to the kernel's out-of-memory killer. */
    double need = 4.0 * 8.0 * (2.0 * m->n) * (2.0 * m->n), have = gb_memory_available();
    if (have > 0 && need > have)
        return gb_fail(err, GB_EINPUT,
                       "the boundary mesh has %d elements: its dense matrices need about %.3g GB (four (2n)^2 "
                       "matrices of doubles), more than the %.3g GB this machine has available; use fewer "
                       "elements",
                       m->n, need / 1e9, have / 1e9);
    size_t nd = 2 * (size_t)m->n;
    sys->ndof = (int)nd;
    sys->material = *mat;
    sys->H = malloc(sizeof(double) * nd * nd);
    sys->G = malloc(sizeof(double) * nd * nd);
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    int nt = m->n < 400 ? 1 : ncpu < 1 ? 1 : ncpu > 8 ? 8 : (int)ncpu;
    work w[8];
    double *lr = malloc(sizeof(double) * 2 * (size_t)m->n * (size_t)nt);
    double *flux = calloc((size_t)m->n_loops * nd, sizeof(double));
    if (!sys->H || !sys->G || !lr || !flux) {
        free(lr);
        free(flux);
        gb_bem_system_free(sys);
        return gb_fail(err, GB_ENOMEM, "out of memory for %zu x %zu influence matrices", nd, nd);
    }
    pthread_t th[8];
    int started[8] = {0};
    for (int i = 0; i < nt; i++) {
        w[i] = (work){m,
                      &k,
                      sys,
                      (int)((long)m->n * i / nt),
                      (int)((long)m->n * (i + 1) / nt),
                      lr + 2 * (size_t)m->n * (size_t)i,
                      flux};
        if (i > 0) started[i] = pthread_create(&th[i], NULL, worker, &w[i]) == 0;
    }
    fill_columns(&w[0]);
    for (int i = 1; i < nt; i++) {
        if (started[i])
            pthread_join(th[i], NULL);
        else
            fill_columns(&w[i]); /* no thread: do it here */
    }
    free(lr);
    breathing_correction(m, sys, flux);
    free(flux);
    return GB_OK;
}
