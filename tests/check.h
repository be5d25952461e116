/* Minimal assertions for gembem's test programs: each failed check prints where and why, and the
 * program's exit status is the number of failed checks (0: passed). */
#ifndef GB_TEST_CHECK_H
#define GB_TEST_CHECK_H

#include <math.h>
#include <stdio.h>
#include <string.h>

static int gb_test_failures = 0;

#define CHECK(cond)                                                                                  \
    do {                                                                                             \
        if (!(cond)) {                                                                               \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);                \
            gb_test_failures++;                                                                      \
        }                                                                                            \
    } while (0)

/* |got - want| <= tol, printing both values when it fails. */
#define CHECK_NEAR(got, want, tol)                                                                   \
    do {                                                                                             \
        double g_ = (got), w_ = (want), t_ = (tol);                                                  \
        if (!(fabs(g_ - w_) <= t_)) {                                                                \
            fprintf(stderr, "%s:%d: %s = %.10g, expected %.10g within %.3g (off by %.3g)\n",         \
                    __FILE__, __LINE__, #got, g_, w_, t_, fabs(g_ - w_));                            \
            gb_test_failures++;                                                                      \
        }                                                                                            \
    } while (0)

/* Writes text to /tmp/gb_test_<name> and returns that path (until the next call): an input file
 * made by the test itself. */
static inline const char *gb_test_file(const char *name, const char *text)
{
    static char path[256];
    snprintf(path, sizeof path, "/tmp/gb_test_%s", name);
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    return path;
}

#define TEST_END()                                                                                   \
    do {                                                                                             \
        if (gb_test_failures) fprintf(stderr, "%d check(s) failed\n", gb_test_failures);             \
        return gb_test_failures ? 1 : 0;                                                             \
    } while (0)

#endif
