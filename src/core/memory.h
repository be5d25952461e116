/* The machine's memory, for refusing a run that cannot fit before allocating it. */
#ifndef GB_CORE_MEMORY_H
#define GB_CORE_MEMORY_H

/* Physical memory of the machine in bytes (sysconf), or 0 if unknown. */
double gb_memory_physical(void);

#endif
