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
