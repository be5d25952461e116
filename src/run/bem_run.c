/* `gembem bem`: an elastic body alone, solved and written to a run directory (its files:
 * docs/run-directory.md and `gembem bem --help`). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "gembem/run.h"
#include "io/bem_output.h"
#include "io/dir_lock.h"
#include "io/file_util.h"
#include "io/run_record.h"

typedef struct {
    gb_bem_scene sc;
    gb_bem_system sys;
    gb_bem_solution sol;
    gb_bem_stiffness k;
    double *u, *s, *bs;
    int has_k;
} bem_run;

static void bem_run_free(bem_run *r)
{
    gb_bem_stiffness_free(&r->k);
    gb_bem_solution_free(&r->sol);
    gb_bem_system_free(&r->sys);
    gb_bem_scene_free(&r->sc);
    free(r->u), free(r->s), free(r->bs);
}

/* The body that follows its deformed boundary: the interior points inside the body are material
 * points, followed to their current places (written there), with their summed displacements and
 * stresses. */
static gb_status compute_updated(bem_run *r, const gb_bem_guard *guard, gb_error *err)
{
    gb_bem_scene *sc = &r->sc;
    int n = 0;
    for (int i = 0; i < sc->npts; i++) n += sc->pt_inside[i];
    gb_bem_follow f = {n, malloc(sizeof(double) * 2 * (size_t)(n ? n : 1)),
                       malloc(sizeof(double) * 2 * (size_t)(n ? n : 1)),
                       malloc(sizeof(double) * 3 * (size_t)(n ? n : 1)), r->bs};
    gb_status st = (!f.xy || !f.u || !f.stress) ? gb_fail(err, GB_ENOMEM, "out of memory") : GB_OK;
    for (int i = 0, q = 0; !st && i < sc->npts; i++)
        if (sc->pt_inside[i]) memcpy(f.xy + 2 * q++, sc->pts + 2 * i, sizeof(double) * 2);
    if (!st) st = gb_bem_solve_updated(&sc->mesh, &sc->material, &sc->problem, sc->increments, guard, &f, &r->sol, err);
    for (int i = 0, q = 0; !st && i < sc->npts; i++)
        if (sc->pt_inside[i]) {
            memcpy(sc->pts + 2 * i, f.xy + 2 * q, sizeof(double) * 2);
            memcpy(r->u + 2 * i, f.u + 2 * q, sizeof(double) * 2);
            memcpy(r->s + 3 * i, f.stress + 3 * q, sizeof(double) * 3);
            q++;
        }
    free(f.xy), free(f.u), free(f.stress);
    return st;
}

/* Today's linear solve on the undeformed mesh, its interior points and its condensed stiffness. */
static gb_status compute_linear(bem_run *r, const gb_bem_guard *guard, gb_error *err)
{
    gb_bem_scene *sc = &r->sc;
    gb_status st;
    if ((st = gb_bem_assemble(&sc->mesh, &sc->material, &r->sys, err))) return st;
    if ((st = gb_bem_solve(&sc->mesh, &r->sys, &sc->problem, guard, &r->sol, err))) return st;
    if ((st = gb_bem_boundary_stress(&sc->mesh, &sc->material, &r->sol, r->bs, err))) return st;
    for (int i = 0; i < sc->npts && !st; i++) /* point by point: the grid may hold points outside the body */
        if (sc->pt_inside[i])
            st = gb_bem_interior(&sc->mesh, &sc->material, &sc->problem, &r->sol, 1, sc->pts + 2 * i, r->u + 2 * i,
                                 r->s + 3 * i, err);
    if (st) return st;
    if (sc->stiffness_group[0]) {
        int g = gb_bem_mesh_group(&sc->mesh, sc->stiffness_group);
        if ((st = gb_bem_condense(&sc->mesh, &r->sys, &sc->problem, g, guard, &r->k, err))) return st;
        r->has_k = 1;
    }
    return GB_OK;
}

static gb_status compute(const char *scene, bem_run *r, gb_error *err)
{
    gb_status st = gb_bem_scene_load(scene, &r->sc, err);
    if (st) return st;
    gb_bem_guard guard = gb_bem_guard_default();
    int n = r->sc.npts, m = r->sc.mesh.n;
    r->u = calloc(2 * (size_t)(n ? n : 1), sizeof(double));
    r->s = calloc(3 * (size_t)(n ? n : 1), sizeof(double));
    r->bs = calloc(3 * (size_t)m, sizeof(double));
    if (!r->u || !r->s || !r->bs) return gb_fail(err, GB_ENOMEM, "out of memory");
    return r->sc.increments ? compute_updated(r, &guard, err) : compute_linear(r, &guard, err);
}

/* What `gembem bem` prints: the solve's numbers in a few lines. */
static void summary_text(const bem_run *r, char *text, size_t cap)
{
    const gb_bem_scene *sc = &r->sc;
    int used = snprintf(text, cap,
                        "gembem %s\nscene: %s\nmesh: %s (%d elements, %d loop(s), %s)\nunits: length %s, force %s\n"
                        "system rcond: %.6e (at the scene's own lengths: %.6e), length scale used: %.6g\n",
                        gb_version(), sc->path, sc->mesh_path, sc->mesh.n, sc->mesh.n_loops,
                        sc->mesh.unbounded ? "unbounded" : "bounded", sc->length_unit, sc->force_unit, r->sol.rcond,
                        r->sol.rcond_first, r->sol.scale);
    if (sc->increments && used > 0 && (size_t)used < cap)
        used += snprintf(text + used, cap - (size_t)used,
                         "updated Lagrangian: %d increments, each on the mesh the previous ones moved; the files "
                         "describe the deformed body\n",
                         sc->increments);
    if (r->has_k && used > 0 && (size_t)used < cap)
        snprintf(text + used, cap - (size_t)used,
                 "stiffness on '%s': %d x %d, ||K - K^t||_F / ||K||_F = %.6e, rcond %.6e, length scale %.6g\n",
                 sc->stiffness_group, r->k.m, r->k.m, r->k.asymmetry, r->k.rcond, r->k.scale);
}

/* run_info.yaml: how the directory was made (the keys of a run's, io/run_record.h), the settings
 * the solve used and, as keys, the numbers it measured (docs/run-directory.md). */
static gb_status write_info(const char *path, const char *command, const bem_run *r, double started, gb_error *err)
{
    const gb_bem_scene *sc = &r->sc;
    const gb_bem_material *mat = &sc->material;
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    FILE *f = a.f;
    fprintf(f, "# How this run directory was made.\n");
    gb_run_record_origin(f, command, sc->path, "started", NULL);
    fprintf(f, "settings:   # as the solve used them\n  units: {length: %s, force: %s}\n", sc->length_unit,
            sc->force_unit);
    fprintf(f, "  material: {shear_modulus: %.17g, poisson: %.17g, plane: %s}\n", mat->shear_modulus, mat->poisson,
            mat->plane == GB_BEM_PLANE_STRESS ? "stress" : "strain");
    fprintf(f, "  mesh: {file: \"%s\", elements: %d, loops: %d, unbounded: %s}\n", sc->mesh_path, sc->mesh.n,
            sc->mesh.n_loops, sc->mesh.unbounded ? "true" : "false");
    if (sc->increments)
        fprintf(f, "  updated_lagrangian: {increments: %d}   # the body followed its deformed boundary\n",
                sc->increments);
    gb_run_record_machine(f);
    fprintf(f, "solve:   # what the boundary element solve measured\n"
               "  system_rcond: %.6e   # the system's reciprocal condition number, at the length scale used\n"
               "  system_rcond_scene_lengths: %.6e   # the same at the scene's own lengths\n"
               "  length_scale: %.6g\n",
            r->sol.rcond, r->sol.rcond_first, r->sol.scale);
    if (r->has_k)
        fprintf(f, "  stiffness:   # the condensed stiffness K on the group\n    group: %s\n"
                   "    size: %d   # K is size x size\n    asymmetry: %.6e   # ||K - K^t||_F / ||K||_F\n    rcond: %.6e\n    length_scale: %.6g\n",
                sc->stiffness_group, r->k.m, r->k.asymmetry, r->k.rcond, r->k.scale);
    fprintf(f, "time:   # seconds: reading, solving and writing\n  total: %.3f\nstatus: completed\n",
            gb_clock_seconds() - started);
    return gb_atomic_commit(&a, err);
}

static gb_status write_all(const char *dir, const char *command, const bem_run *r, double started, gb_error *err)
{
    char path[1200];
    gb_status st = GB_OK;
#define OUT(name) (snprintf(path, sizeof path, "%s/%s", dir, name), path)
    if (!st) st = gb_copy_file(r->sc.path, OUT("scene.yaml"), err);
    if (!st && r->sc.write_boundary_csv)
        st = gb_bem_write_boundary_csv(OUT("boundary.csv"), &r->sc.mesh, &r->sol, r->bs, err);
    if (!st && r->sc.write_boundary_vtp) st = gb_bem_write_boundary_vtp(OUT("boundary.vtp"), &r->sc.mesh, &r->sol, err);
    if (!st && r->sc.write_interior_vtu) st = gb_bem_write_interior_vtu(OUT("interior.vtu"), &r->sc, r->u, r->s, err);
    if (!st && r->sc.write_interior_csv) st = gb_bem_write_interior_csv(OUT("interior.csv"), &r->sc, r->u, r->s, err);
    if (!st && r->has_k && r->sc.stiffness_write)
        st = gb_bem_write_stiffness_csv(OUT("stiffness.csv"), &r->sc.mesh, &r->k, err);
    if (!st) st = write_info(OUT("run_info.yaml"), command, r, started, err);
#undef OUT
    return st;
}

gb_status gb_bem_run(const char *scene, const char *dir, int overwrite, const char *command, char *summary, size_t cap,
                     gb_error *err)
{
    double started = gb_clock_seconds();
    bem_run r;
    memset(&r, 0, sizeof r);
    /* the directory first: a refusal costs no solve */
    gb_status st = gb_output_dir_check(dir, overwrite, "output directory", err);
    if (!st) st = compute(scene, &r, err);
    gb_dir_lock lock;
    lock.fd = -1;
    if (!st) st = gb_dir_lock_take(&lock, dir, 1, overwrite, "output directory", err); /* one writer */
    if (!st) st = write_all(dir, command, &r, started, err);
    if (lock.fd >= 0) gb_dir_lock_status(&lock, st ? gb_status_name(st) : "completed");
    gb_dir_lock_release(&lock);
    if (!st && summary) summary_text(&r, summary, cap);
    bem_run_free(&r);
    return st;
}
