/* deposit.h - sequential deposition of discs under gravity (drop and roll).
 *
 * Box: floor y = 0, walls x = 0 and x = width, no lid. Each disc, in array order, is dropped at a
 * random x from above, falls vertically, rolls down over the discs it meets and stops where it is
 * stable: on the floor, in the pocket of two discs, or between a disc and a wall (Visscher and
 * Bolsterli 1972, Nature 239, 504; here without friction). Neighbours come from a uniform grid, so
 * one disc costs O(1) on average. Only + - * / and sqrt are used (no libm trigonometry), so a
 * given input and random stream give bit-identical positions on every IEEE-754 machine. */
#ifndef PG_DEPOSIT_H
#define PG_DEPOSIT_H

#include <stddef.h>

#include "gembem/rng.h"

typedef struct {
    double x, y, r;
} pg_disc;

typedef enum { PG_DEP_OK = 0, PG_DEP_NOMEM = 1, PG_DEP_STUCK = 2 } pg_dep_status;

/* Deposit discs d[0..n-1] (r set by the caller; x, y written) in a box of the given width.
 * Contacts use the radius r + pad_i where pad_i = r * rel_pad + abs_pad: with abs_pad = g / 2
 * every pair ends at least g apart and every disc at least g / 2 from the walls and the floor.
 * *height gets max(y + r + pad): the top of the pile. Requires width >= 2 * max(r + pad). */
pg_dep_status pg_deposit(pg_disc *d, size_t n, double width, double rel_pad, double abs_pad,
                         gb_rng *rng, double *height);

#endif
