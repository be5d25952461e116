/* A granular scene too large for the machine is refused before allocation: its
 * grain count is set past what the machine's available memory holds at the documented lower bound of the
 * simulation's need (a few hundred bytes a grain; 5 kB more with the global solver), and
 * gb_sim_create must fail with GB_EINPUT and the estimate, allocating nothing (the grains array
 * holds two grains: a simulation that read it would run past its end, which ASan would report). A
 * scene that fits is created. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "core/memory.h"
#include "gembem/run.h"
#include "scene_fixture.h"

int main(void)
{
    gb_grain g[2] = {{1, 1, 1, 0}, {3, 1, 1, 0}};
    gb_box box = {0, 4, 0, 4};
    gb_scene s = fixture_scene(g, 2, box, 1e8, 7e7, 25);
    gb_sim *sim = NULL;
    gb_error err = {0};
    CHECK(gb_sim_create(&s, &sim, &err) == GB_OK);
    gb_sim_free(sim);
    double have = gb_memory_physical();
    CHECK(have > 0);
    for (int method = GB_METHOD_REFERENCE; method <= GB_METHOD_GLOBAL; method++) {
        /* 1e3 bytes a grain is above the bound without the factor: this count cannot fit either way. */
        double n = have / 1e2 < 2e9 ? have / 1e2 : 2e9;
        s.n_grains = (int)n;
        s.solver.method = method;
        sim = NULL;
        memset(&err, 0, sizeof err);
        gb_status st = gb_sim_create(&s, &sim, &err);
        printf("%d grains, %s: %s\n", s.n_grains, method ? "global" : "reference", err.msg);
        CHECK(st == GB_EINPUT);
        CHECK(sim == NULL);
        CHECK(strstr(err.msg, "GB") != NULL && strstr(err.msg, "this machine has available") != NULL);
    }
    TEST_END();
}
