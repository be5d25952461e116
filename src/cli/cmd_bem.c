#include <stdio.h>

#include "cli/cli.h"

/* Placeholder until the boundary element module lands (issue 3). */
int gb_cli_bem(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "gembem bem: the boundary element module is not built yet\n");
    return 1;
}
