/* Wall-clock seconds for the benchmark programs. */
#ifndef GB_BENCH_CLOCK_H
#define GB_BENCH_CLOCK_H

#include <time.h>

static inline double bench_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

#endif
