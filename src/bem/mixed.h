/* The mixed system of H u = G t (one unknown per DOF), shared by the solver and the condensation,
 * with the degenerate-scale guard. The guard works on G_lambda = G - (3 - 4 nu) lambda E / (8 pi mu
 * (1 - nu)), E_(2i+l, 2j+k) = L_j delta_lk: exactly the G of the body with all lengths multiplied by
 * s = exp(lambda) (u* has ln(1/r)), written in the original units. */
#ifndef GB_BEM_MIXED_H
#define GB_BEM_MIXED_H

#include "bem/linalg.h"
#include "gembem/bem.h"

typedef struct {
    const gb_bem_mesh *mesh;
    const gb_bem_system *sys;
    const unsigned char *t_unknown; /* per DOF: 1 = displacement given, traction unknown (column -G) */
    int border;                     /* 1: three rigid-body constraint rows and columns are added */
    double cdeg;                    /* (3 - 4 nu) / (8 pi mu (1 - nu)) */
} gb_bem_mixed;

gb_status gb_bem_mixed_init(gb_bem_mixed *mx, const gb_bem_mesh *mesh, const gb_bem_system *sys,
                            const unsigned char *t_unknown, int border, gb_error *err);
int gb_bem_mixed_size(const gb_bem_mixed *mx);
/* The system matrix at log-scale lambda (column-major, gb_bem_mixed_size squared). */
void gb_bem_mixed_fill(const gb_bem_mixed *mx, double lambda, double *A);
/* y += f * column d of G_lambda. */
void gb_bem_mixed_gcol(const gb_bem_mixed *mx, double lambda, int d, double f, double *y);
/* Builds and factorises at lambda = 0; if the system holds G columns and its rcond is below the
 * guard's threshold, retries at a rescaled length and keeps the better conditioned one. */
gb_status gb_bem_mixed_factor(const gb_bem_mixed *mx, const gb_bem_guard *guard, gb_bem_lu *lu, double *lambda,
                              double *rcond_first, gb_error *err);

#endif
