#include "core/number.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

gb_number_result gb_parse_finite(const char *s, double *out)
{
    char *end = NULL;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end != '\0') return GB_NUMBER_SYNTAX;
    /* glibc sets ERANGE on underflow too, with the correctly rounded subnormal as the value */
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1)) return GB_NUMBER_INFINITE;
    *out = v;
    return GB_NUMBER_OK;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double gb_median(double *v, int n)
{
    if (n <= 0) return 0;
    qsort(v, (size_t)n, sizeof *v, by_value);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
