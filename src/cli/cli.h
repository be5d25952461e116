/* The gembem command: one file per subcommand, each a thin layer over the library.
 * Exit statuses: 0 ok, 2 bad input or usage, 3 not converged, 4 an output could not be written
 * (disk full), 1 anything else. */
#ifndef GB_CLI_H
#define GB_CLI_H

#include <stddef.h>

#include "gembem/status.h"

int gb_cli_run(int argc, char **argv); /* gembem run: a granular scene */
int gb_cli_bem(int argc, char **argv); /* gembem bem: a pure elastostatic scene */
int gb_cli_pack(int argc, char **argv); /* gembem pack: a packing in a box or a cavity */

/* Prints the error to stderr as "gembem: message" and returns the exit status for its code. */
int gb_cli_report(const gb_error *err);

/* "gembem" and the subcommand's arguments, for run_info.yaml and pack_info.yaml. */
void gb_cli_command_line(int argc, char **argv, char *out, size_t cap);

#endif
