/* The `gembem bem` scene reader (gb_bem_scene_load): the input is the scene; its mesh is a
 * fixture (the project's meshes). */
#include "fuzz.h"
#include "gembem/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    gb_bem_scene s;
    gb_error err;
    gb_status st = gb_bem_scene_load(gb_fuzz_write("input.yaml", data, size), &s, &err);
    gb_fuzz_show(st, &err);
    if (st == GB_OK) gb_bem_scene_free(&s);
    return 0;
}
