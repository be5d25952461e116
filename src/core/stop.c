/* A stop asked for from outside a run (gembem/status.h): one flag for the process, since a signal is
 * the process's; a handler may only store into a volatile sig_atomic_t. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>

#include "gembem/status.h"

static volatile sig_atomic_t stop_reason = 0;

void gb_run_request_stop(int reason) { stop_reason = reason > 0 ? reason : 1; }

int gb_run_stop_requested(void) { return stop_reason; }

void gb_run_stop_clear(void) { stop_reason = 0; }

const char *gb_run_signal_name(int signo, char *buf, size_t cap)
{
    switch (signo) {
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGHUP: return "SIGHUP";
    default: snprintf(buf, cap, "signal %d", signo); return buf;
    }
}
