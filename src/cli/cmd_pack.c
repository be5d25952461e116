/* gembem pack SCENE.yaml -o RUNDIR: a packing made and brought to equilibrium (docs/packing.md). */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "gembem/pack.h"
#include "gembem/run.h"
#include "io/file_util.h"

static void usage(FILE *to)
{
    fprintf(to, "usage: gembem pack SCENE.yaml -o RUNDIR [--overwrite] [--quiet]\n"
                "  Fills the scene's box or host cavity with grains (its pack: section: sizes, count or solid\n"
                "  fraction, protocol deposition or growth, seed, friction_deg while packing), brings them to\n"
                "  equilibrium with gembem's solver and writes RUNDIR/state.yaml (a run scene starts from it with\n"
                "  initial_state:), pack_info.yaml (solid fraction, coordination, largest force, times) and a copy\n"
                "  of the scene.\n"
                "  Exit status: 0 done, 2 bad input (nothing written), 3 a relaxation did not converge, 4 an output\n"
                "  could not be written.\n");
}

/* What the packing did to the radii drawn from sizes: (growth) they take a common scale to reach the
 * target, which a user reads as the sizes asked for unless told. Empty when they were kept. */
static void scale_note(char *out, size_t cap, double scale)
{
    out[0] = 0;
    if (scale < 1)
        snprintf(out, cap, "; the drawn radii shrunk to %.3g of their size to reach the target (radius_scale)", scale);
    else if (scale > 1)
        snprintf(out, cap, "; the drawn radii grown %.3g times to reach the target (radius_scale)", scale);
}

int gb_cli_pack(int argc, char **argv)
{
    const char *scene_path = NULL, *dir = NULL;
    int overwrite = 0, quiet = 0;
    for (int k = 1; k < argc; k++) {
        if (!strcmp(argv[k], "-o") && k + 1 < argc) dir = argv[++k];
        else if (!strcmp(argv[k], "--overwrite")) overwrite = 1;
        else if (!strcmp(argv[k], "--quiet")) quiet = 1;
        else if (!strcmp(argv[k], "--help") || !strcmp(argv[k], "-h")) return usage(stdout), 0;
        else if (argv[k][0] != '-' && !scene_path) scene_path = argv[k];
        else {
            fprintf(stderr, "gembem pack: unexpected argument '%s'\n", argv[k]);
            usage(stderr);
            return 2;
        }
    }
    if (!scene_path || !dir) {
        usage(stderr);
        return 2;
    }
    char command[1024];
    gb_cli_command_line(argc, argv, command, sizeof command);
    gb_error err = {0};
    gb_scene scene;
    gb_bem_mesh mesh;
    gb_pack_def def;
    if (gb_output_dir_check(dir, overwrite, "pack directory", &err)) return gb_cli_report(&err);
    if (gb_pack_scene_load(scene_path, &scene, &mesh, &def, &err)) return gb_cli_report(&err);
    gb_pack_result res;
    gb_sim *sim = NULL;
    int code = 0;
    if (gb_pack_make(&scene, scene.host.present ? &mesh : NULL, &def, &res, &sim, &err) ||
        gb_pack_write(dir, command, sim, &def, &res, &err))
        code = gb_cli_report(&err);
    else if (!quiet) {
        char note[160];
        scale_note(note, sizeof note, res.radius_scale);
        printf("gembem: %d grains packed in %.2f s: solid fraction %.4f, coordination %.3f (%.3f without %d "
               "rattlers), largest fixing force %.3g%s; results in %s\n", res.n,
               res.seconds[0] + res.seconds[1] + res.seconds[2] + res.seconds[3], res.solid_fraction,
               res.coordination, res.coordination_nonrattlers, res.rattlers, res.max_fixing_force, note, dir);
    }
    gb_sim_free(sim);
    gb_bem_mesh_free(&mesh);
    gb_scene_free(&scene);
    return code;
}
