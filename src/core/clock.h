/* Wall-clock seconds (monotonic), for the solvers' own cost accounts. */
#ifndef GB_CORE_CLOCK_H
#define GB_CORE_CLOCK_H

double gb_clock_seconds(void);

#endif
