/* The exact solution for three rigid frictionless discs (Kishino 1989, eqs. 15-21, with the
 * correction of docs/method.md section 7: eq. 20 without its spurious factor 2). */
#ifndef GB_THREE_DISCS_EXACT_H
#define GB_THREE_DISCS_EXACT_H

#include <math.h>

/* Stress ratio (s1 - s2)/(s1 + s2) at the shear strain e1 - e2 = gamma > 0, from theta0. */
static double three_discs_exact_ratio(double gamma, double theta0)
{
    double s0 = sin(theta0), c0 = cos(theta0);
    /* gamma(theta) = e1 - e2 grows as theta falls below theta0; bisect for theta. */
    double lo = 1e-6, hi = theta0;
    for (int it = 0; it < 200; it++) {
        double th = 0.5 * (lo + hi);
        double e1 = -(sin(th) - s0) / (1 + s0);            /* (K 20), corrected; compression + */
        double e2 = -2 * (cos(th) - c0) / (1 + 2 * c0);    /* (K 21) */
        if (e1 - e2 > gamma) lo = th;
        else hi = th;
    }
    double th = 0.5 * (lo + hi);
    double R = 2 * tan(th) * (1 + sin(th)) / (1 + 2 * cos(th)); /* (K 19) */
    return (R - 1) / (R + 1);
}

#endif
