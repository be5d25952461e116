/* FIRE (Bitzek, Koskinen, Gaehler, Moseler and Gumbsch, Phys. Rev. Lett. 97, 170201, 2006): a
 * damped inertial descent of the energy of frictionless discs (linear normal springs pn = kn d, as
 * gembem's contact law, and a body force), to a state where every disc's force is below a
 * tolerance. Frictionless discs in equilibrium are in equilibrium with friction too (no tangential
 * force), so gembem's own solver starts from there. FIRE needs a number of iterations that grows
 * like the packing's side, where a Jacobi-like iteration needs its square (tools/packgen/README.md). */
#ifndef GB_PACK_FIRE_H
#define GB_PACK_FIRE_H

#include "contact/pairs.h"

typedef struct {
    gb_grain *g;               /* the discs: centres moved, radii as they are */
    int n;
    const gb_box *box;         /* walls held, or NULL */
    const gb_particles *bp;    /* boundary particles held, or NULL */
    double kn_gg, kn_gw, kn_gb; /* normal springs: grain-grain, grain-wall, grain-particle */
    double body[2];            /* body force per unit disc area */
} gb_fire_world;

typedef struct {
    long iterations;
    double max_force;  /* largest |F| of a disc at the end */
    double virial;     /* sum over contacts of pn times the centre's distance to the contact point(s): 2 A p */
    int contacts;      /* force-carrying */
    int wall_contacts; /* of them, with the box's walls */
    double wall[GB_N_WALLS]; /* the walls' normal forces */
    double largest_overlap; /* between discs, over the smaller radius */
} gb_fire_report;

/* Relaxes until every disc's |F| <= tol: GB_ENOCONV after max_iter iterations (the discs left where
 * they are, rep filled), GB_ENUMERIC if the forces stop being finite. */
gb_status gb_fire_relax(const gb_fire_world *w, double tol, long max_iter, gb_fire_report *rep, gb_error *err);

#endif
