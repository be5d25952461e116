/* The grains' radii (sizes.h). */
#include <math.h>
#include <stdlib.h>

#include "gembem/rng.h"
#include "pack/sizes.h"

static const double PI = 3.14159265358979323846;

/* ln r ~ N(ln median, sigma) cut to [rmin, rmax]: the density in u = ln r, unnormalised. */
static double lognormal_weight(const gb_pack_sizes *z, double u)
{
    double t = (u - log(z->median)) / z->sigma;
    return exp(-0.5 * t * t);
}

double gb_sizes_mean_area(const gb_pack_sizes *z)
{
    if (z->kind == GB_SIZES_UNIFORM)
        return PI * (z->rmin * z->rmin + z->rmin * z->rmax + z->rmax * z->rmax) / 3;
    if (z->kind == GB_SIZES_LOGNORMAL) {
        /* Simpson's rule in u = ln r over the cut: E[pi r^2] = int w(u) pi e^2u du / int w(u) du */
        const int m = 400;
        double a = log(z->rmin), h = (log(z->rmax) - a) / m, num = 0, den = 0;
        for (int k = 0; k <= m; k++) {
            double u = a + k * h, c = k == 0 || k == m ? 1 : k % 2 ? 4 : 2, w = c * lognormal_weight(z, u);
            num += w * PI * exp(2 * u), den += w;
        }
        return num / den;
    }
    double s = 0;
    for (int k = 0; k < z->n; k++) {
        double a = PI * z->radius[k] * z->radius[k];
        s += z->by_number ? z->fraction[k] * a : z->fraction[k] / a;
    }
    return z->by_number ? s : 1 / s;
}

double gb_sizes_max_radius(const gb_pack_sizes *z)
{
    if (z->kind != GB_SIZES_DISCRETE) return z->rmax;
    double r = 0;
    for (int k = 0; k < z->n; k++)
        if (z->fraction[k] > 0) r = fmax(r, z->radius[k]);
    return r;
}

/* Counts summing to n, each the floor of its ideal or one more (the largest remainders first). */
static void discrete_counts(const gb_pack_sizes *z, long n, long *count)
{
    double ideal[GB_PACK_MAX_SIZES], total = 0;
    for (int k = 0; k < z->n; k++) {
        ideal[k] = z->by_number ? z->fraction[k] : z->fraction[k] / (z->radius[k] * z->radius[k]);
        total += ideal[k];
    }
    long left = n;
    for (int k = 0; k < z->n; k++) {
        ideal[k] *= (double)n / total;
        count[k] = (long)floor(ideal[k]);
        left -= count[k];
    }
    while (left-- > 0) {
        int best = 0;
        for (int k = 1; k < z->n; k++)
            if (ideal[k] - count[k] > ideal[best] - count[best]) best = k;
        count[best]++;
    }
}

void gb_sizes_draw(const gb_pack_sizes *z, long n, uint64_t seed, double *r)
{
    gb_rng rng;
    gb_rng_seed(&rng, seed, 0);
    if (z->kind == GB_SIZES_DISCRETE) {
        long count[GB_PACK_MAX_SIZES], i = 0;
        discrete_counts(z, n, count);
        for (int k = 0; k < z->n; k++)
            for (long c = 0; c < count[k]; c++) r[i++] = z->radius[k];
        for (long j = n - 1; j > 0; j--) { /* Fisher-Yates */
            long q = (long)gb_rng_below(&rng, (size_t)j + 1);
            double t = r[j];
            r[j] = r[q], r[q] = t;
        }
        return;
    }
    for (long i = 0; i < n; i++) {
        if (z->kind == GB_SIZES_UNIFORM) {
            r[i] = z->rmin + gb_rng_uniform(&rng) * (z->rmax - z->rmin);
            continue;
        }
        do { /* Box-Muller; draws outside the cut are drawn again */
            double u1 = 1 - gb_rng_uniform(&rng), u2 = gb_rng_uniform(&rng);
            r[i] = z->median * exp(z->sigma * sqrt(-2 * log(u1)) * cos(2 * PI * u2));
        } while (!(r[i] >= z->rmin && r[i] <= z->rmax));
    }
}
