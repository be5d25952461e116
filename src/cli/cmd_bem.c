/* gembem bem SCENE.yaml -o OUTDIR: a pure elastostatic scene through the boundary element module.
 * Everything is read, meshed and solved before OUTDIR is created: bad input leaves no output. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "gembem/run.h"

static void usage(FILE *to)
{
    fprintf(to, "usage: gembem bem SCENE.yaml -o OUTDIR [--overwrite]\n"
                "Solves a 2D elastostatic scene by boundary elements and writes to OUTDIR (refused if it\n"
                "exists and is not empty, unless --overwrite: its files are then replaced):\n"
                "  boundary.csv   displacement, traction and stress at each boundary element\n"
                "  boundary.vtp   the boundary with displacement and traction (ParaView)\n"
                "  interior.vtu   displacement and stress at the scene's interior points (ParaView)\n"
                "  interior.csv   the same as a table\n"
                "  stiffness.csv  the condensed stiffness, when the scene asks for it\n"
                "  scene.yaml     a copy of the scene\n"
                "  run_info.yaml  how it was made; rcond, the length scale used, K's asymmetry\n");
}

int gb_cli_bem(int argc, char **argv)
{
    const char *scene = NULL, *out = NULL;
    int overwrite = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            usage(stdout);
            return 0;
        }
        if (!strcmp(argv[i], "-o") && i + 1 < argc)
            out = argv[++i];
        else if (!strcmp(argv[i], "--overwrite"))
            overwrite = 1;
        else if (argv[i][0] != '-' && !scene)
            scene = argv[i];
        else {
            fprintf(stderr, "gembem bem: unexpected argument '%s'\n", argv[i]);
            usage(stderr);
            return 2;
        }
    }
    if (!scene || !out) {
        usage(stderr);
        return 2;
    }
    gb_error err = {0};
    char summary[4096], command[1024];
    gb_cli_command_line(argc, argv, command, sizeof command);
    gb_status st = gb_bem_run(scene, out, overwrite, command, summary, sizeof summary, &err);
    if (st) return gb_cli_report(&err);
    fputs(summary, stdout);
    return 0;
}
