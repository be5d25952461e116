#include "gembem/status.h"

#include <stdarg.h>
#include <stdio.h>

gb_status gb_fail(gb_error *err, gb_status code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
        err->code = code;
    }
    return code;
}

const char *gb_status_name(gb_status s)
{
    switch (s) {
    case GB_OK: return "ok";
    case GB_EINTERNAL: return "internal error";
    case GB_EINPUT: return "bad input";
    case GB_ENOCONV: return "not converged";
    case GB_EIO: return "i/o error";
    case GB_ENOMEM: return "out of memory";
    case GB_ENUMERIC: return "numerical failure";
    case GB_EINTERRUPTED: return "interrupted";
    }
    return "unknown status";
}

const char *gb_version(void) { return GB_VERSION; }
