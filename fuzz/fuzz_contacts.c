/* The contacts CSV reader: the input is the contacts file of a fixed scene with four grains in a
 * box, or of a hybrid run's state when it names a boundary particle (",p" and a digit), which only
 * a host has. */
#include "fuzz.h"
#include "gembem/scene.h"

static int names_particle(const uint8_t *data, size_t size)
{
    for (size_t i = 0; i + 2 < size; i++)
        if (data[i] == ',' && data[i + 1] == 'p' && data[i + 2] >= '0' && data[i + 2] <= '9') return 1;
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    gb_scene s;
    gb_error err;
    gb_fuzz_write("input.csv", data, size);
    const char *scene = names_particle(data, size) ? "contacts_host_scene.yaml" : "contacts_scene.yaml";
    gb_status st = gb_scene_load(gb_fuzz_path(scene), &s, &err);
    gb_fuzz_show(st, &err);
    if (st == GB_OK) gb_scene_free(&s);
    return 0;
}
