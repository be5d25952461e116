/* A scene built in code for unit tests: grains in a box, one material for both contact types. */
#ifndef GB_TEST_SCENE_FIXTURE_H
#define GB_TEST_SCENE_FIXTURE_H

#include "gembem/scene.h"

static inline gb_scene fixture_scene(gb_grain *grains, int n, gb_box box, double kn, double kt, double phi_deg)
{
    gb_scene s = gb_scene_default();
    gb_material m = {kn, kt, phi_deg, 0, 0, 0};
    s.grain_grain = s.grain_wall = m;
    s.grains = grains;
    s.n_grains = n;
    s.box = box;
    s.solver.accuracy = 1e-6;
    return s;
}

/* Deterministic pseudo-random numbers in [0, 1) (splitmix64). */
static inline double fixture_random(unsigned long long *state)
{
    unsigned long long z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0;
}

#endif
