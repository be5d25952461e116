/* Rigid-body motions (docs/method.md section 12): for a closed bounded body, H times a rigid
 * translation vanishes to round-off (the element integrals are exact, so the identity
 * c + int p* = 0 holds exactly for the polygon); for a cavity in an infinite plane the same
 * sum is the identity (c = 1/2 I plus the cavity's 1/2 I). A rigid rotation is not constant on
 * an element: H times its midpoint values vanishes only as the mesh is refined. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "gembem/bem.h"

/* max over rows of |H v - want| for v a rigid motion at the midpoints (kind 0: x, 1: y, 2: rotation). */
static double rigid_residual(const gb_bem_mesh *m, const gb_bem_system *s, int kind, double want_identity)
{
    int nd = s->ndof;
    double *v = malloc(sizeof(double) * (size_t)nd), worst = 0;
    for (int e = 0; e < m->n; e++) {
        v[2 * e] = kind == 0 ? 1 : kind == 1 ? 0 : -m->mid[2 * e + 1];
        v[2 * e + 1] = kind == 0 ? 0 : kind == 1 ? 1 : m->mid[2 * e];
    }
    for (int i = 0; i < nd; i++) {
        double r = 0;
        for (int j = 0; j < nd; j++) r += s->H[(size_t)j * (size_t)nd + (size_t)i] * v[j];
        worst = fmax(worst, fabs(r - want_identity * v[i]));
    }
    free(v);
    return worst;
}

static int load(const char *path, int unbounded, double size, gb_bem_mesh *m, gb_bem_system *s)
{
    gb_error err = {0};
    gb_bem_mesh_opts o = gb_bem_mesh_opts_default();
    o.unbounded = unbounded;
    o.size = size;
    gb_bem_material mat = {1.0, 0.3, GB_BEM_PLANE_STRAIN};
    if (gb_bem_mesh_load(path, &o, m, &err) || gb_bem_assemble(m, &mat, s, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 0;
    }
    return 1;
}

int main(void)
{
    const char *bodies[3] = {"meshes/annulus.geo", "meshes/square_cavity.geo", "meshes/irregular_cavity.geo"};
    double sizes[3] = {0.1, 0.4, 0.4};
    for (int b = 0; b < 3; b++) {
        gb_bem_mesh m;
        gb_bem_system s;
        double rot[2];
        for (int r = 0; r < 2; r++) {
            CHECK(load(bodies[b], 0, sizes[b] / (1 + r), &m, &s));
            if (r == 0) {
                double tx = rigid_residual(&m, &s, 0, 0), ty = rigid_residual(&m, &s, 1, 0);
                printf("%s: %d elements, |H t_x| %.2e, |H t_y| %.2e\n", bodies[b], m.n, tx, ty);
                CHECK(tx < 1e-12 && ty < 1e-12);
            }
            rot[r] = rigid_residual(&m, &s, 2, 0);
            printf("%s: %d elements, |H rotation| %.3e\n", bodies[b], m.n, rot[r]);
            gb_bem_system_free(&s);
            gb_bem_mesh_free(&m);
        }
        CHECK(rot[1] < 0.6 * rot[0]); /* it goes to zero with the element size */
    }
    /* unbounded: H t = t for a translation t */
    gb_bem_mesh m;
    gb_bem_system s;
    CHECK(load("meshes/hole_infinite.geo", 1, 0.1, &m, &s));
    double tx = rigid_residual(&m, &s, 0, 1), ty = rigid_residual(&m, &s, 1, 1);
    printf("hole in an infinite plane: |H t - t| %.2e %.2e\n", tx, ty);
    CHECK(tx < 1e-12 && ty < 1e-12);
    gb_bem_system_free(&s);
    gb_bem_mesh_free(&m);
    TEST_END();
}
