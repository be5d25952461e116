/* The machine's memory, for refusing a run that cannot fit before allocating it. */
#ifndef GB_CORE_MEMORY_H
#define GB_CORE_MEMORY_H

/* Physical memory of the machine in bytes (sysconf), or 0 if unknown. */
double gb_memory_physical(void);

/* The memory a new allocation can have without swapping, in bytes: the kernel's MemAvailable
 * (/proc/meminfo: free memory plus the caches it can drop), or the physical memory where the
 * kernel does not say; 0 if neither is known. What other processes hold is not ours to take. */
double gb_memory_available(void);

#endif
