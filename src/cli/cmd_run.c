#include <stdio.h>

#include "cli/cli.h"

int gb_cli_run(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "gembem run: not built yet\n");
    return 1;
}
