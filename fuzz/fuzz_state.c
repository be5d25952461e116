/* The state reader (a scene's initial_state: a previous run's state.yaml): the input is the state
 * of a fixed box scene, or of a fixed host scene when it says "host" (a hybrid run's state). */
#include "fuzz.h"
#include "gembem/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    gb_scene s;
    gb_error err;
    gb_fuzz_write("input.yaml", data, size);
    const char *scene = gb_fuzz_contains(data, size, "host") ? "state_host_scene.yaml" : "state_scene.yaml";
    gb_status st = gb_scene_load(gb_fuzz_path(scene), &s, &err);
    gb_fuzz_show(st, &err);
    if (st == GB_OK) gb_scene_free(&s);
    return 0;
}
