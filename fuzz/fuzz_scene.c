/* The granular scene reader (gb_scene_load, as `gembem run`), box and host scenes: the input is the
 * scene; the files it names (grains, contacts, state, meshes) are the fixtures'. */
#include "fuzz.h"
#include "gembem/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    gb_scene s;
    gb_error err;
    gb_status st = gb_scene_load(gb_fuzz_write("input.yaml", data, size), &s, &err);
    gb_fuzz_show(st, &err);
    if (st == GB_OK) gb_scene_free(&s);
    return 0;
}
