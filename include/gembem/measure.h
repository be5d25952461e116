/* Micromechanics of a granular state (Kishino 1989, section 4): fabric and energy tensors, work,
 * dissipation and the energy balance. Only force-carrying contacts count; a grain-wall contact
 * counts once where a grain-grain contact counts twice (once from each grain), so that walls carry
 * "the other half" (K 23, 24, 29). Tensors are in x (horizontal), y (vertical) components. */
#ifndef GEMBEM_MEASURE_H
#define GEMBEM_MEASURE_H

#include "gembem/gem.h"

typedef struct {
    double xx, yy, xy;
    double major, minor;  /* principal values */
    double angle_deg;     /* direction of the major axis, from the x axis, in (-90, 90] */
} gb_tensor2;

typedef struct {
    int n_contacts;          /* force-carrying contacts (grain-grain and grain-wall) */
    int n_wall_contacts;
    double coordination;     /* (2 N_gg + N_gw) / N, equal to the trace of the fabric tensor */
    gb_tensor2 fabric;       /* C_ij = sum_grains sum_contacts n_i n_j / N (K 23) */
    gb_tensor2 energy;       /* E_ij = sum_grains sum_contacts e_c n_i n_j / 2A (K 24) */
    double area;             /* A: the box */
    double elastic_energy;   /* all springs, walls' included in full */
    double work;             /* external work since the start: walls + body forces */
    double work_walls, work_body;
    double dissipation;      /* since the start (K 28, summed over iterations) */
    double dissipation_step; /* of the last load step */
    double dissipation_step_k28; /* the same from the step's start and end states alone (K 25-28): NaN
                                    from gb_micro_measure (a state), the run's measures fill it */
    double p_max;            /* largest single-contact share of the last step's dissipation */
    double balance;          /* W - D - (elastic energy - its initial value): the paper's check */
    /* The iteration's own books: the walls' work as they are moved (instant strain increments and
     * stress-control moves), the energy absorbed by the fixing forces (-sum F.dX: what a dynamic
     * system would damp), and W_iter - D - L - dE, zero to the accuracy of the trapezoid rule. */
    double work_walls_iter;
    double relaxation;
    double balance_iter;
} gb_micro;

/* The external work a run has done on its simulation since its start (quasi-static: from converged
 * steps' forces), and the elastic energy the simulation had then (gb_run, gembem/run.h). */
typedef struct {
    double walls;     /* by the walls */
    double body;      /* by the body forces */
    double energy0;   /* elastic energy of the initial state */
} gb_work_accounts;

/* The micromechanics of sim's state; the work and the balances from `work` (NULL: a state outside a
 * run, whose work is not known: they are NaN). */
void gb_micro_measure(const gb_sim *sim, const gb_work_accounts *work, gb_micro *m);

/* Contact normals by direction, from the grains' side (K Figs. 11, 12): nbins sectors over
 * [0, 360) degrees; a grain-grain contact counts in the direction of n and of -n, a grain-wall
 * contact once, towards the wall, so the counts add up to N times the coordination number.
 * `energy` is the same weighted by the contact's elastic energy (K 22). */
void gb_micro_rose(const gb_sim *sim, int nbins, double *count, double *energy);

/* Which of the m contacts c (as gb_sim_contacts gives them) slide: |pt| at the Coulomb limit
 * pn tan(phi) + c (K 13), as the run's sliding contacts count them (docs/measures.md); 1 or 0 into
 * sliding[k]. */
void gb_contacts_sliding(const gb_sim *sim, const gb_contact *c, int m, int *sliding);

/* Principal values and direction of a symmetric 2x2 tensor. */
void gb_tensor2_principal(gb_tensor2 *t);

#endif
