/* The mesh reader (gb_bem_mesh_load) on a .msh file, the input: gmsh reads it, gembem chains its
 * line elements into loops and checks them. Not .geo files: gmsh's .geo language runs commands
 * (System) and includes files, a script rather than data. */
#include "fuzz.h"
#include "gembem/bem.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    gb_bem_mesh m;
    gb_error err;
    gb_status st = gb_bem_mesh_load(gb_fuzz_write("input.msh", data, size), NULL, &m, &err);
    gb_fuzz_show(st, &err);
    if (st == GB_OK) gb_bem_mesh_free(&m);
    return 0;
}
