/* Measures of one load step (private to the library): pure functions of the step's start and end
 * states, computed by the run's measure phase (src/run/program.c) and written by src/io. */
#ifndef GB_STEP_MEASURES_H
#define GB_STEP_MEASURES_H

#include "gem/sim.h"
#include "gembem/measure.h"
#include "gembem/strain_field.h"

/* A contact at the Coulomb limit (K 13). */
typedef struct {
    int i, j;     /* as in gb_contact: j < 0 a wall or a boundary particle */
    double pn, pt, limit, nx, ny;
} gb_sliding_contact;

/* The force-carrying contacts whose |pt| has reached the limit pn tan(phi) + c, to the relative
 * tolerance 1e-9 that the global solver uses for its tangents (src/solver/global.c): the contact
 * law clamps pt there when the contact slides. Contacts without friction (limit 0) or without a
 * tangential spring (kt = 0, e.g. against boundary particles) never count: they carry no shear.
 * They are taken from the m contacts c of sim (gb_sim_contacts: as numbered and ordered there) into
 * out (room for m); returns their number. */
int gb_measure_sliding(const gb_sim *sim, const gb_contact *c, int m, gb_sliding_contact *out);

/* The host around its cavity for the simulation's cavity displacements. Stresses tension
 * positive (the boundary element module's convention), strains from them by Hooke's law. */
typedef struct {
    int n_wall;          /* cavity elements, in the stiffness's order */
    int *elem;           /* their mesh elements */
    double *wall_xy;     /* midpoints at rest, 2 per element */
    double *hoop;        /* t.s.t at each cavity element's midpoint (t its tangent) */
    double *hoop_empty;  /* the same with the cavity empty (traction-free), all else alike */
    double *normal;      /* n.s.n: minus the grains' pressure on the wall */
    double s_ref;        /* the reference stress (see gb_host_measure) */
    const char *s_ref_kind; /* "remote", "boundary", "cavity_pressure" or "none" */
    double max_concentration; /* hoop / s_ref where |hoop| is largest; NaN when s_ref is within the
                                 noise of the stresses (the step's accuracy over a cavity element's
                                 mean length, or 1e-12 of the largest hoop stress) */
    int n_ring;
    double *ring_xy;     /* 2 per point */
    double *ring_stress; /* sxx, syy, sxy per point */
    double *ring_strain; /* exx, eyy, exy (tensor shear) per point */
} gb_host_measures;

/* Solves the host for its cavity displacements (and once more with the cavity empty) and
 * measures the hoop stress along the cavity wall and the stress and strain on a ring of interior
 * points: each cavity element's midpoint moved into the body, along its normal, by half the
 * cavity's equivalent radius sqrt(area / pi); points that fall outside the body or closer to its
 * boundary than a fifth of the mean element length are left out.
 * The reference stress s_ref is the stress that loads the body: the largest absolute principal
 * remote stress of an unbounded host; else the largest mean traction |sum t L| / sum L carried
 * by a boundary group with a non-zero prescribed value (a displaced or loaded side); else, a body
 * loaded by its grains alone, the mean pressure of the grains on the cavity wall. */
/* With wall_only, only what localisation.csv's row needs: the hoop and normal stress on the wall,
 * s_ref and the concentration (one solve); hoop_empty is zero and the ring empty. */
gb_status gb_host_measure(const gb_sim *sim, int wall_only, gb_host_measures *m, gb_error *err);
void gb_host_measures_free(gb_host_measures *m);

/* The step's dissipation as the paper computes it from the step's start and end states alone
 * (K 25-28): NaN-free, 0 without sliding. */
double gb_micro_step_dissipation(const gb_state *start, const gb_sim *end);

/* The granular zone's strain over a step: the grains' centres at the start triangulated, each
 * triangle's strain to the end, averaged at the grains, their D2min and the localisation index. */
typedef struct {
    int n;
    double *x0, *x1, *r;  /* the grains' centres at the start and the end (2 per grain), radii */
    gb_triangulation t;
    gb_strain *tri, *grain;
    int *grain_tri;
    gb_d2min *d2;
    gb_localisation loc;
    gb_strain mean;       /* of the triangulated zone */
    double d2_range;
    int tri_ok;           /* 0: too few or collinear grains, no triangles */
} gb_zone_measures;

/* Everything measured of one load step (or of the initial state, step 0, start = end), as
 * docs/measures.md lists: the micromechanics, the zone's strain, the sliding contacts and, with a
 * host, its stress around the cavity (on the wall only unless `fields`: the fields/ files are due).
 * The zone's strain and the host's stress only if `row` (localisation.csv's row) or `fields`. */
typedef struct {
    int step, fields, row;
    gb_micro micro;
    gb_zone_measures zone;
    gb_sliding_contact *sliding;
    int n_sliding;
    int has_host;
    gb_host_measures host;
} gb_step_measures;

gb_status gb_step_measure(const gb_state *start, const gb_sim *end, const gb_work_accounts *work, int step,
                          int fields, int row, gb_step_measures *m, gb_error *err);
void gb_step_measures_free(gb_step_measures *m);

#endif
