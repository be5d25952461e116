/* Status codes and error reports. The library never prints or exits: every call that can fail
 * returns a gb_status and fills a gb_error; the command line decides what to do with it. */
#ifndef GEMBEM_STATUS_H
#define GEMBEM_STATUS_H

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

#endif
