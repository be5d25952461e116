/* Status codes and error reports. The library never prints or exits: every call that can fail
 * returns a gb_status and fills a gb_error; the command line decides what to do with it. */
#ifndef GEMBEM_STATUS_H
#define GEMBEM_STATUS_H

#include <stddef.h>

typedef enum {
    GB_OK = 0,
    GB_EINTERNAL = 1, /* a bug or an unexpected library failure */
    GB_EINPUT = 2,    /* bad input: scene, mesh, grains file, arguments */
    GB_ENOCONV = 3,   /* an iteration did not converge within its cap */
    GB_EIO = 4,       /* a file could not be written */
    GB_ENOMEM = 5,
    GB_ENUMERIC = 6,  /* a singular or non-finite system */
    GB_EINTERRUPTED = 7 /* stopped on request (gb_run_request_stop: a signal), a checkpoint written */
} gb_status;

#define GB_ERROR_MSG_MAX 1024

typedef struct {
    gb_status code;
    char msg[GB_ERROR_MSG_MAX]; /* "file:line:column: what was expected" where there is a place */
} gb_error;

/* Record an error (printf-style) and return its code, so that `return gb_fail(err, ...)` reads well. */
gb_status gb_fail(gb_error *err, gb_status code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

const char *gb_status_name(gb_status s);
const char *gb_version(void);

/* A stop asked for from outside a run (one flag for the process, which the run's loop and its
 * output both look at), e.g. by a signal handler (the library installs none; the gembem command
 * does, for SIGTERM, SIGINT and SIGHUP): async-signal-safe, it only records
 * `reason` (a signal number, > 0) in a volatile sig_atomic_t. A run (gb_run_program) with an output notices
 * it between two iterations of a relaxation or at the end of a step, writes a checkpoint there and
 * returns GB_EINTERRUPTED (gb_run_output_close then records status `interrupted`); without an
 * output, at the end of a step. The request stays until gb_run_stop_clear. */
void gb_run_request_stop(int reason);
/* The reason of the stop asked for, 0 if none. */
int gb_run_stop_requested(void);
void gb_run_stop_clear(void);
/* A signal's name for messages ("SIGTERM"), or "signal N" (buf: at least 16 bytes). */
const char *gb_run_signal_name(int signo, char *buf, size_t cap);

#endif
