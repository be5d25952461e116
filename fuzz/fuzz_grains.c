/* The grains CSV reader: the input is the grains file of a fixed scene (fixtures/grains_scene.yaml). */
#include "fuzz.h"
#include "gembem/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    gb_scene s;
    gb_error err;
    gb_fuzz_write("input.csv", data, size);
    gb_status st = gb_scene_load(gb_fuzz_path("grains_scene.yaml"), &s, &err);
    gb_fuzz_show(st, &err);
    if (st == GB_OK) gb_scene_free(&s);
    return 0;
}
