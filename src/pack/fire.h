/* FIRE 2.0 (Bitzek, Koskinen, Gaehler, Moseler and Gumbsch, Phys. Rev. Lett. 97, 170201, 2006, with
 * the semi-implicit Euler step, the delay and the half step back of Guenole, Noehring, Vaid et al.,
 * Comput. Mater. Sci. 175, 109584, 2020): a damped inertial descent of the energy of frictionless
 * discs (linear normal springs pn = kn d, as gembem's contact law, and a body force), to a state
 * where every disc's force is below a tolerance. Frictionless discs in equilibrium are in
 * equilibrium with friction too (no tangential force), so gembem's own solver starts from there.
 * With friction (a world with `pairs`), every contact follows gembem's own law (gb_pair_update_forces:
 * incremental tangential springs capped by Coulomb, rolling springs), each disc's rotation is a
 * degree of freedom, and the damped dynamics is the explicit-DEM route to a frictional static
 * state (as LAMMPS's and YADE's packings are made), its tangential forces kept in the pairs.
 * The radii, a common factor `scale` times the drawn ones, may grow while the discs relax: ramped
 * to a target, or free under a target mean stress (the enthalpy below). */
#ifndef GB_PACK_FIRE_H
#define GB_PACK_FIRE_H

#include "contact/pairs.h"

typedef struct {
    gb_grain *g;               /* the discs: centres moved, radii scale r0[i] (as they are without r0) */
    int n;
    const gb_box *box;         /* walls held, or NULL */
    const gb_particles *bp;    /* boundary particles held, or NULL */
    double kn_gg, kn_gw, kn_gb; /* normal springs: grain-grain, grain-wall, grain-particle */
    double body[2];            /* body force per unit disc area */
    const double *r0;          /* the drawn radii, or NULL: the radii are held as they are */
    double area;               /* the region's, for the mean stress */
    int threads;               /* OpenMP threads of the passes (the scene's solver.threads) */
    /* Friction, or NULL: the pairs, which then keep their tangential forces from one relaxation to
     * the next (the caller frees them), and the laws of the grain-grain, grain-wall and
     * grain-particle contacts, indexed by gb_pair_end (their kn as the kn_ above), with their
     * tan(friction angle). */
    gb_pair_set *pairs;
    const gb_material *mat[3];
    double tan_phi[3];
} gb_fire_world;

/* What a relaxation must reach. With r0: either the scale ramps to scale_to, growing at most `ramp`
 * in ln(scale) per iteration, or (stress > 0) the scale is one more degree of freedom and FIRE
 * minimises the enthalpy H = U - 2 A stress ln(scale), whose stationary points have a mean stress
 * (sum of pn (ri + rj) over 2 A, Love's virial with the radii as branch lengths) equal to `stress`
 * (Dagois-Bohy, Tighe, Simon, Henkes and van Hecke, Phys. Rev. Lett. 109, 095703, 2012, minimise
 * U + pV with the box free; here the radii grow instead, the same up to the length unit). */
typedef struct {
    double tol;         /* every disc's |F| at most this */
    int free;           /* the scale free under `stress`, else ramped */
    double stress;      /* > 0: the target mean stress; ramped, the ramp stops once it is passed */
    double stress_tol;  /* relative: |virial / 2A - stress| at most stress_tol stress */
    double scale_max;   /* with a stress: the scale may not pass it (rep->capped) */
    double scale_to;    /* without: the scale ramps to this */
    double ramp;        /* the largest change of ln(scale) in one iteration */
    double hold;        /* ramped: the radii grow only while every |F| is below it */
    long max_iter;
} gb_fire_goal;

typedef struct {
    long iterations;
    long rebuilds;     /* of the pair list, in this relaxation */
    double max_force;  /* largest |F| of a disc at the end (with friction: |(Fx, Fy, M / r)|) */
    double virial;     /* sum over contacts of pn times the centre's distance to the contact point(s): 2 A p */
    int contacts;      /* force-carrying */
    int wall_contacts; /* of them, with the box's walls */
    double wall[GB_N_WALLS]; /* the walls' normal forces */
    double largest_overlap; /* between discs, over the smaller radius */
    int capped;        /* the stress needs a scale beyond scale_max: stopped there */
} gb_fire_report;

/* Relaxes at the given radii until every disc's |F| <= tol: GB_ENOCONV after max_iter iterations
 * (the discs left where they are, rep filled), GB_ENUMERIC if the forces stop being finite. */
gb_status gb_fire_relax(const gb_fire_world *w, double tol, long max_iter, gb_fire_report *rep, gb_error *err);

/* The same with the radii scale w->r0[i], *scale from where it is, to the goal; *scale and the
 * radii are left at the end state. */
gb_status gb_fire_relax_scaled(const gb_fire_world *w, const gb_fire_goal *goal, double *scale,
                               gb_fire_report *rep, gb_error *err);

#endif
