/* Numbers read back exactly: every double gembem writes with %.17g, subnormals included (a
 * tangential force of 8.8e-317 in a state file was once refused on restart), parses to the same
 * bits; overflow, inf, nan and trailing text are refused. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "core/number.h"

static int round_trips(double v)
{
    char buf[64];
    double back = -1;
    snprintf(buf, sizeof buf, "%.17g", v);
    return gb_parse_finite(buf, &back) == GB_NUMBER_OK && memcmp(&back, &v, sizeof v) == 0;
}

int main(void)
{
    const double values[] = {0.0, -0.0, 1.0, -2.5e-7, DBL_MAX, -DBL_MAX, DBL_MIN, 8.8e-317, -8.8e-317,
                             4.9406564584124654e-324, nextafter(DBL_MIN, 0), 0.1, 1.0 / 3};
    for (size_t i = 0; i < sizeof values / sizeof *values; i++) {
        CHECK(round_trips(values[i]));
        if (!round_trips(values[i])) printf("  %.17g does not read back\n", values[i]);
    }
    /* a sweep of subnormals, one per binade */
    for (double v = DBL_MIN; v > 0; v /= 2) CHECK(round_trips(v));
    double x = 7;
    CHECK(gb_parse_finite("1e-400", &x) == GB_NUMBER_OK && x == 0); /* below the smallest subnormal */
    CHECK(gb_parse_finite("1e309", &x) == GB_NUMBER_INFINITE);
    CHECK(gb_parse_finite("-1e309", &x) == GB_NUMBER_INFINITE);
    CHECK(gb_parse_finite("inf", &x) == GB_NUMBER_INFINITE);
    CHECK(gb_parse_finite("nan", &x) == GB_NUMBER_INFINITE);
    CHECK(gb_parse_finite("", &x) == GB_NUMBER_SYNTAX);
    CHECK(gb_parse_finite("1.5x", &x) == GB_NUMBER_SYNTAX);
    CHECK(gb_parse_finite(" ", &x) == GB_NUMBER_SYNTAX);
    TEST_END();
}
