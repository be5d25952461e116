/* The directory of `gembem pack`: the scene's copy, the state a run scene starts from
 * (initial_state:) and pack_info.yaml (docs/packing.md, "Outputs"). */
#include <stdio.h>

#include "gembem/output.h"
#include "gembem/pack.h"
#include "io/dir_lock.h"
#include "io/file_util.h"
#include "io/run_record.h"

static const char *sizes_name(const gb_pack_sizes *z)
{
    if (z->kind == GB_SIZES_UNIFORM) return "uniform";
    if (z->kind == GB_SIZES_LOGNORMAL) return "lognormal";
    return z->by_number ? "discrete, fractions of the number" : "discrete, fractions of the area";
}

static void write_info(FILE *f, const char *command, const gb_scene *s, const gb_pack_def *d, const gb_pack_result *r)
{
    fprintf(f, "# How this packing was made (docs/packing.md). A run scene starts from it with\n"
               "#   initial_state: <this directory>/state.yaml%s\n",
            s->host.present ? "\n# and the same host: section (the same mesh)" : "");
    gb_run_record_origin(f, command, s->path, "made", NULL);
    fprintf(f, "protocol: %s\nfriction_deg: %.17g   # %s\nseed: %llu\nsizes: %s\n",
            d->protocol == GB_PACK_GROWTH ? "growth" : "deposition", d->friction_deg,
            d->friction_deg > 0 ? "the grains' friction angle while packing, the walls' and boundary's the scene's"
                                : "packed frictionless, the scene's friction switched on at the end",
            (unsigned long long)d->seed, sizes_name(&d->sizes));
    if (d->protocol == GB_PACK_GROWTH)
        fprintf(f, "target: {%s: %.17g}\n", d->stress ? "stress" : "solid_fraction",
                d->stress ? d->stress : d->solid_fraction);
    fprintf(f, "region: {kind: %s, area: %.17g}   # %s\n", s->host.present ? "cavity" : "box", r->area,
            s->host.present ? "the cavity's polygon (its elements' end points), boundary particles not taken off"
                            : "the box");
    fprintf(f, "grains: %d\ngrain_area: %.17g\nsolid_fraction: %.17g\nporosity: %.17g\n", r->n, r->grain_area,
            r->solid_fraction, 1 - r->solid_fraction);
    fprintf(f, "radius_scale: %.17g   # the drawn radii were multiplied by it (growth)\n", r->radius_scale);
    fprintf(f, "mean_stress: %.17g   # (sxx + syy)/2 from the contacts over the region's area [%s/%s]\n",
            r->mean_stress, s->force_unit, s->length_unit);
    fprintf(f, "contacts: {grain_grain: %d, boundary: %d}   # force-carrying; boundary: walls or boundary particles\n",
            r->contacts_grains, r->contacts_boundary);
    fprintf(f, "coordination: %.17g   # (2 grain_grain + boundary) / grains\n", r->coordination);
    fprintf(f, "rattlers: %d   # grains left with fewer than %d contacts, removed repeatedly\n", r->rattlers,
            r->rattler_contacts);
    fprintf(f, "coordination_without_rattlers: %.17g\n", r->coordination_nonrattlers);
    fprintf(f, "largest_overlap: %.17g   # between grains, over the smaller radius\n", r->largest_overlap);
    fprintf(f, "max_fixing_force: %.17g   # largest |F| of the final state (K 14)\naccuracy: %.17g\n",
            r->max_fixing_force, s->solver.accuracy);
    fprintf(f, "fire_iterations: {grow: %ld, settle: %ld}\nequilibrium_iterations: %ld   # gembem's solver, "
               "the scene's friction\n", r->fire_iterations[GB_PACK_GROW], r->fire_iterations[GB_PACK_SETTLE],
            r->equilibrium_iterations);
    fprintf(f, "equilibrium_work: {smoother_steps: %ld, factorisations: %ld, linear_seconds: %.3f}   # the global "
               "solver's; linear: its system's assembly, analysis, factorisation and solve\n",
            r->equilibrium_work.sweeps, r->equilibrium_work.factorisations, r->equilibrium_linear_seconds);
    double total = 0;
    for (int k = 0; k < GB_PACK_PHASES; k++) total += r->seconds[k];
    fprintf(f, "seconds: {place: %.3f, grow: %.3f, settle: %.3f, equilibrium: %.3f, total: %.3f}\n",
            r->seconds[GB_PACK_PLACE], r->seconds[GB_PACK_GROW], r->seconds[GB_PACK_SETTLE],
            r->seconds[GB_PACK_EQUILIBRIUM], total);
}

gb_status gb_pack_write(const char *dir, const char *command, const gb_sim *sim, const gb_pack_def *def,
                        const gb_pack_result *res, gb_error *err)
{
    const gb_scene *s = gb_sim_scene(sim);
    char path[1024];
    /* one writer at a time (the directory was checked before the packing: gembem pack) */
    gb_dir_lock lock;
    gb_status st = gb_dir_lock_take(&lock, dir, 1, 1, "pack directory", err);
    if (st) return st;
    snprintf(path, sizeof path, "%s/scene.yaml", dir);
    if (!(st = gb_copy_file(s->path, path, err)) && !(st = gb_state_write(dir, sim, err))) {
        snprintf(path, sizeof path, "%s/pack_info.yaml", dir);
        gb_atomic_file a;
        if (!(st = gb_atomic_open(&a, path, err))) {
            write_info(a.f, command, s, def, res);
            st = gb_atomic_commit(&a, err);
        }
    }
    gb_dir_lock_status(&lock, st ? gb_status_name(st) : "completed");
    gb_dir_lock_release(&lock);
    return st;
}
