#define _POSIX_C_SOURCE 200809L
#include "core/memory.h"

#include <stdio.h>
#include <unistd.h>

double gb_memory_physical(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    return pages > 0 && size > 0 ? (double)pages * (double)size : 0;
}

double gb_memory_available(void)
{
    FILE *f = fopen("/proc/meminfo", "r");
    double kb = -1;
    char line[256];
    while (f && kb < 0 && fgets(line, sizeof line, f))
        if (sscanf(line, "MemAvailable: %lf kB", &kb) != 1) kb = -1;
    if (f) fclose(f);
    return kb >= 0 ? kb * 1024 : gb_memory_physical();
}
