/* The accuracy a of a benchmark run: a number in the scene's force unit, or "target" for the
 * tight accuracy 1e-6 kn r_mean (kn between grains, r_mean the grains' mean radius); NULL keeps the scene's. */
#ifndef GB_BENCH_ACCURACY_H
#define GB_BENCH_ACCURACY_H

#include <stdlib.h>
#include <string.h>

#include "gembem/scene.h"

static inline void bench_set_accuracy(gb_scene *sc, const char *arg)
{
    if (!arg) return;
    if (strcmp(arg, "target")) {
        sc->solver.accuracy = atof(arg);
        return;
    }
    double r = 0;
    for (int i = 0; i < sc->n_grains; i++) r += sc->grains[i].r;
    sc->solver.accuracy = 1e-6 * sc->grain_grain.kn * r / (sc->n_grains ? sc->n_grains : 1);
}

#endif
