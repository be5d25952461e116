/* (H 3-5): the influence matrices H and G of constant elements, dense and column-major. */
#include <stdlib.h>
#include <string.h>

#include "bem/segment.h"
#include "gembem/bem.h"

void gb_bem_system_free(gb_bem_system *sys)
{
    if (!sys) return;
    free(sys->H);
    free(sys->G);
    memset(sys, 0, sizeof *sys);
}

gb_status gb_bem_assemble(const gb_bem_mesh *m, const gb_bem_material *mat, gb_bem_system *sys, gb_error *err)
{
    memset(sys, 0, sizeof *sys);
    gb_bem_kconst k;
    gb_status st = gb_bem_kconst_init(mat, &k, err);
    if (st) return st;
    if (m->n < 1) return gb_fail(err, GB_EINPUT, "the boundary mesh is empty");
    size_t nd = 2 * (size_t)m->n;
    sys->ndof = (int)nd;
    sys->material = *mat;
    sys->H = malloc(sizeof(double) * nd * nd);
    sys->G = malloc(sizeof(double) * nd * nd);
    if (!sys->H || !sys->G) {
        gb_bem_system_free(sys);
        return gb_fail(err, GB_ENOMEM, "out of memory for %zu x %zu influence matrices", nd, nd);
    }
    /* column block j (element j), rows i (collocation points): contiguous writes */
    for (int j = 0; j < m->n; j++) {
        const double *a = m->p0 + 2 * j, *b = m->p1 + 2 * j;
        double *H0 = sys->H + (size_t)(2 * j) * nd, *H1 = H0 + nd;
        double *G0 = sys->G + (size_t)(2 * j) * nd, *G1 = G0 + nd;
        for (int i = 0; i < m->n; i++) {
            double g[4], h[4];
            gb_bem_segment_gh(&k, m->mid + 2 * i, a, b, i == j, g, h);
            if (i == j) { /* c = 1/2 I at a smooth midpoint */
                h[0] += 0.5;
                h[3] += 0.5;
            }
            H0[2 * i] = h[0];
            H0[2 * i + 1] = h[2];
            H1[2 * i] = h[1];
            H1[2 * i + 1] = h[3];
            G0[2 * i] = g[0];
            G0[2 * i + 1] = g[2];
            G1[2 * i] = g[1];
            G1[2 * i + 1] = g[3];
        }
    }
    return GB_OK;
}
