#define _POSIX_C_SOURCE 200809L
#include "core/memory.h"

#include <unistd.h>

double gb_memory_physical(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    return pages > 0 && size > 0 ? (double)pages * (double)size : 0;
}
