#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "gembem/petsc.h"

static void usage(FILE *to)
{
    fprintf(to, "usage: gembem <command> [options]\n"
                "commands:\n"
                "  run SCENE.yaml -o RUNDIR   run a granular scene (reference or global solver)\n"
                "  bem SCENE.yaml -o OUTDIR   solve a pure elastostatic scene (boundary elements)\n"
                "  pack SCENE.yaml -o RUNDIR  fill a box or a host's cavity with grains in equilibrium\n"
                "  version                    print the version\n"
                "Run 'gembem <command> --help' for the options of a command.\n");
}

int gb_cli_report(const gb_error *err)
{
    fprintf(stderr, "gembem: %s\n", err->msg);
    switch (err->code) {
    case GB_OK: return 0;
    case GB_EINPUT: return 2;
    case GB_ENOCONV: return 3;
    case GB_EIO: return 4;
    case GB_EINTERRUPTED: return 130; /* the caller knows the signal (gembem run: 128 + its number) */
    default: return 1;
    }
}

void gb_cli_command_line(int argc, char **argv, char *out, size_t cap)
{
    snprintf(out, cap, "gembem");
    for (int k = 0; k < argc; k++) {
        size_t used = strlen(out);
        snprintf(out + used, cap - used, " %s", argv[k]);
    }
}

int main(int argc, char **argv)
{
    int code;
    if (gb_petsc_serve(&code)) return code; /* an MPI worker of the linear solves (solver.linear: petsc) */
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    /* a file size limit (ulimit -f) fails the write (EFBIG) instead of killing the process: gembem
     * then says which file, removes its temporary files and records the run's status (exit 4) */
    signal(SIGXFSZ, SIG_IGN);
    const char *cmd = argv[1];
    if (!strcmp(cmd, "run")) return gb_cli_run(argc - 1, argv + 1);
    if (!strcmp(cmd, "bem")) return gb_cli_bem(argc - 1, argv + 1);
    if (!strcmp(cmd, "pack")) return gb_cli_pack(argc - 1, argv + 1);
    if (!strcmp(cmd, "version") || !strcmp(cmd, "--version")) {
        printf("gembem %s\n", gb_version());
        return 0;
    }
    if (!strcmp(cmd, "help") || !strcmp(cmd, "--help") || !strcmp(cmd, "-h")) {
        usage(stdout);
        return 0;
    }
    fprintf(stderr, "gembem: unknown command '%s'\n", cmd);
    usage(stderr);
    return 2;
}
