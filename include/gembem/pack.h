/* Packings made by gembem (`gembem pack`, docs/packing.md): grains drawn from a size distribution,
 * placed at random in a box or a host's cavity, grown or settled by FIRE (frictionless, or with a
 * friction angle up to the scene's), then brought to equilibrium by gembem's own solver with the
 * scene's friction. */
#ifndef GEMBEM_PACK_H
#define GEMBEM_PACK_H

#include <stdint.h>

#include "gembem/gem.h"

typedef enum {
    GB_PACK_DEPOSITION = 0, /* placed loose, then they fall and settle under the scene's body force */
    GB_PACK_GROWTH = 1      /* radii grown to a target solid fraction or mean stress */
} gb_pack_protocol;

typedef enum { GB_SIZES_DISCRETE = 0, GB_SIZES_UNIFORM = 1, GB_SIZES_LOGNORMAL = 2 } gb_sizes_kind;

#define GB_PACK_MAX_SIZES 64
#define GB_PACK_MAX_COUNT 10000000L
/* The densest a protocol is asked for: growth beyond it would press grains into each other by more
 * than a few per cent of their radii (random close packing of discs is about 0.84), and a deposit
 * of frictionless discs holds about 0.80-0.84 of its region. */
#define GB_PACK_MAX_SOLID_FRACTION 0.90
#define GB_PACK_MAX_FILL 0.80

typedef struct {
    gb_sizes_kind kind;
    int n;                                 /* discrete: the sizes */
    double radius[GB_PACK_MAX_SIZES];
    double fraction[GB_PACK_MAX_SIZES];    /* summing to 1 */
    int by_number;                         /* fractions of the grains' number (else of their area) */
    double rmin, rmax;                     /* uniform, lognormal: the bounds of the radii */
    double median, sigma;                  /* lognormal: ln r normal (ln median, sigma), cut to the bounds */
} gb_pack_sizes;

typedef struct {
    gb_pack_protocol protocol;
    gb_pack_sizes sizes;
    long count;             /* grains; 0: from solid_fraction */
    double solid_fraction;  /* growth: the target; deposition: the grains' area over the region's; 0: none */
    double stress;          /* growth: the target mean stress [F/L]; 0: none */
    uint64_t seed;
    long max_iterations;    /* FIRE iterations per relaxation */
    double friction_deg;    /* the grains' friction angle while packing, at most the scene's; 0: frictionless, the
                             * scene's friction switched on at the end */
} gb_pack_def;

enum { GB_PACK_PLACE = 0, GB_PACK_GROW = 1, GB_PACK_SETTLE = 2, GB_PACK_EQUILIBRIUM = 3, GB_PACK_PHASES = 4 };

typedef struct {
    int n;                        /* grains */
    double area;                  /* the region's: the box, or the cavity's polygon (shoelace) */
    double grain_area;
    double solid_fraction;        /* grain_area / area */
    double radius_scale;          /* growth: the common factor of the drawn radii; deposition: 1 */
    double mean_stress;           /* (sxx + syy)/2 from the contacts (Love), compression positive [F/L] */
    long fire_iterations[GB_PACK_PHASES];
    double seconds[GB_PACK_PHASES];
    long equilibrium_iterations;  /* gembem's solver, friction on */
    gb_solver_work equilibrium_work; /* its smoother's steps and factorisations (global solver) */
    double equilibrium_linear_seconds; /* of them, the global system's assembly, analysis, factorisation and solve */
    double max_fixing_force;      /* largest |F| of the final state (K 14) */
    int contacts_grains, contacts_boundary; /* force-carrying: between grains, with walls or particles */
    double coordination;          /* (2 contacts_grains + contacts_boundary) / n */
    int rattlers;                 /* grains left with fewer than rattler_contacts contacts, removed repeatedly */
    int rattler_contacts;         /* 3 for frictionless discs (d + 1); 2 under a body force or with friction while packing */
    double coordination_nonrattlers;
    double largest_overlap;       /* between grains, over the smaller radius */
} gb_pack_result;

/* Reads a pack scene (the scene's units, materials, box or host, body_force, solver and `pack:`);
 * refused with file:line:column (GB_EINPUT). The host's mesh is kept in *mesh (gb_bem_mesh_free). */
gb_status gb_pack_scene_load(const char *path, gb_scene *scene, gb_bem_mesh *mesh, gb_pack_def *def,
                             gb_error *err);

/* Makes the packing into scene->grains, admits it (src/scene/admit.c) and brings it to equilibrium
 * by a relax stage of gembem's solver with the scene's friction (the host held rigid): *sim is the
 * simulation in that state (gb_sim_free; the scene must outlive it). GB_EINPUT: the grains do not
 * fit, or the target is out of the protocol's reach; GB_ENOCONV: a relaxation did not converge. */
gb_status gb_pack_make(gb_scene *scene, const gb_bem_mesh *mesh, const gb_pack_def *def, gb_pack_result *res,
                       gb_sim **sim, gb_error *err);

/* Writes dir/scene.yaml (a copy), the state (state.yaml, ...: gb_state_write) and pack_info.yaml. */
gb_status gb_pack_write(const char *dir, const char *command, const gb_sim *sim, const gb_pack_def *def,
                        const gb_pack_result *res, gb_error *err);

#endif
