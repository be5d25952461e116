/* push.h - the solver benchmark's packing protocol: random sequential addition, then push-apart.
 *
 * Every disc's centre is drawn uniformly in the box inset by its radius (overlaps allowed), then
 * sweeps over the overlapping pairs, found on a cell grid, move both discs of a pair apart along
 * their line of centres, and discs that cross a wall back inside it, until every disc-disc overlap
 * is at most max_overlap times the smaller radius of the pair and every disc-wall overlap at most
 * max_overlap times the disc's radius. Only + - * / and sqrt are used, in a fixed order, so a seed
 * gives bit-identical positions on every IEEE-754 machine (compiled with -ffp-contract=off). */
#ifndef PG_PUSH_H
#define PG_PUSH_H

#include <stddef.h>

#include "deposit.h"
#include "gembem/rng.h"

typedef enum { PG_PUSH_OK = 0, PG_PUSH_NOMEM = 1, PG_PUSH_CAPPED = 2 } pg_push_status;

typedef struct {
    long sweeps;       /* sweeps made, the last one (which moved nothing) included */
    double worst_pair; /* largest disc-disc overlap / smaller radius in the last sweep */
    double worst_wall; /* largest disc-wall overlap / radius in the last sweep */
} pg_push_stats;

/* Centres of d[0..n-1] (r set by the caller) uniform in [r, width - r] x [r, height - r], x then
 * y for each disc in array order. Requires width, height >= 2 max r. */
void pg_rsa_place(pg_disc *d, size_t n, double width, double height, gb_rng *rng);

/* Push-apart sweeps in the box [0, width] x [0, height] until the bounds above hold or
 * max_sweeps sweeps have been made (PG_PUSH_CAPPED; *stats then describes the last sweep). */
pg_push_status pg_push_apart(pg_disc *d, size_t n, double width, double height,
                             double max_overlap, long max_sweeps, pg_push_stats *stats);

#endif
