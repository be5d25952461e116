/* gembem bem SCENE.yaml -o OUTDIR: a pure elastostatic scene through the boundary element module.
 * Everything is read, meshed and solved before OUTDIR is created: bad input leaves no output. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bem/output.h"
#include "cli/cli.h"
#include "gembem/bem.h"

static void usage(FILE *to)
{
    fprintf(to, "usage: gembem bem SCENE.yaml -o OUTDIR [--overwrite]\n"
                "Solves a 2D elastostatic scene by boundary elements and writes to OUTDIR (refused if it\n"
                "exists and is not empty, unless --overwrite: its files are then replaced):\n"
                "  boundary.csv   displacement, traction and stress at each boundary element\n"
                "  boundary.vtp   the boundary with displacement and traction (ParaView)\n"
                "  interior.vtu   displacement and stress at the scene's interior points (ParaView)\n"
                "  interior.csv   the same as a table\n"
                "  stiffness.csv  the condensed stiffness, when the scene asks for it\n"
                "  scene.yaml, version.txt, summary.txt\n");
}

static gb_status copy_file(const char *from, const char *to, gb_error *err)
{
    FILE *a = fopen(from, "rb");
    if (!a) return gb_fail(err, GB_EIO, "%s: cannot read: %s", from, strerror(errno));
    FILE *b = fopen(to, "wb");
    if (!b) {
        fclose(a);
        return gb_fail(err, GB_EIO, "%s: cannot write: %s", to, strerror(errno));
    }
    char buf[8192];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, a)) > 0)
        if (fwrite(buf, 1, n, b) != n) break;
    int bad = ferror(a) || ferror(b);
    fclose(a);
    if (fclose(b) || bad) return gb_fail(err, GB_EIO, "%s: write failed", to);
    return GB_OK;
}

/* OUTDIR may be new or empty; a non-empty one only with --overwrite (as for gembem run). */
static gb_status check_outdir(const char *dir, int overwrite, gb_error *err)
{
    struct stat sb;
    if (stat(dir, &sb) != 0) return GB_OK;
    if (!S_ISDIR(sb.st_mode)) return gb_fail(err, GB_EINPUT, "%s exists and is not a directory", dir);
    DIR *d = opendir(dir);
    if (!d) return gb_fail(err, GB_EIO, "%s: %s", dir, strerror(errno));
    struct dirent *e;
    int empty = 1;
    while (empty && (e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) empty = 0;
    closedir(d);
    if (!empty && !overwrite)
        return gb_fail(err, GB_EINPUT, "output directory %s exists and is not empty; choose another or pass "
                                       "--overwrite", dir);
    return GB_OK;
}

static gb_status write_text(const char *path, const char *text, gb_error *err)
{
    FILE *f = fopen(path, "w");
    if (!f) return gb_fail(err, GB_EIO, "%s: cannot write: %s", path, strerror(errno));
    fputs(text, f);
    if (fclose(f)) return gb_fail(err, GB_EIO, "%s: write failed", path);
    return GB_OK;
}

typedef struct {
    gb_bem_scene sc;
    gb_bem_system sys;
    gb_bem_solution sol;
    gb_bem_stiffness k;
    double *u, *s, *bs;
    int has_k;
} run;

static gb_status compute(const char *scene, run *r, gb_error *err)
{
    gb_status st = gb_bem_scene_load(scene, &r->sc, err);
    if (st) return st;
    gb_bem_guard guard = gb_bem_guard_default();
    if ((st = gb_bem_assemble(&r->sc.mesh, &r->sc.material, &r->sys, err))) return st;
    if ((st = gb_bem_solve(&r->sc.mesh, &r->sys, &r->sc.problem, &guard, &r->sol, err))) return st;
    int n = r->sc.npts, m = r->sc.mesh.n;
    r->u = calloc(2 * (size_t)(n ? n : 1), sizeof(double));
    r->s = calloc(3 * (size_t)(n ? n : 1), sizeof(double));
    r->bs = calloc(3 * (size_t)m, sizeof(double));
    if (!r->u || !r->s || !r->bs) return gb_fail(err, GB_ENOMEM, "out of memory");
    if ((st = gb_bem_boundary_stress(&r->sc.mesh, &r->sc.material, &r->sol, r->bs, err))) return st;
    for (int i = 0; i < n && !st; i++) /* point by point: the grid may hold points outside the body */
        if (r->sc.pt_inside[i])
            st = gb_bem_interior(&r->sc.mesh, &r->sc.material, &r->sc.problem, &r->sol, 1, r->sc.pts + 2 * i,
                                 r->u + 2 * i, r->s + 3 * i, err);
    if (st) return st;
    if (r->sc.stiffness_group[0]) {
        int g = gb_bem_mesh_group(&r->sc.mesh, r->sc.stiffness_group);
        if ((st = gb_bem_condense(&r->sc.mesh, &r->sys, &r->sc.problem, g, &guard, &r->k, err))) return st;
        r->has_k = 1;
    }
    return GB_OK;
}

static gb_status write_all(const char *dir, run *r, gb_error *err)
{
    char path[1200];
    gb_status st = GB_OK;
#define OUT(name) (snprintf(path, sizeof path, "%s/%s", dir, name), path)
    if (!st) st = copy_file(r->sc.path, OUT("scene.yaml"), err);
    char text[4096];
    snprintf(text, sizeof text, "gembem %s\n", gb_version());
    if (!st) st = write_text(OUT("version.txt"), text, err);
    if (!st && r->sc.write_boundary_csv)
        st = gb_bem_write_boundary_csv(OUT("boundary.csv"), &r->sc.mesh, &r->sol, r->bs, err);
    if (!st && r->sc.write_boundary_vtp) st = gb_bem_write_boundary_vtp(OUT("boundary.vtp"), &r->sc.mesh, &r->sol, err);
    if (!st && r->sc.write_interior_vtu) st = gb_bem_write_interior_vtu(OUT("interior.vtu"), &r->sc, r->u, r->s, err);
    if (!st && r->sc.write_interior_csv) st = gb_bem_write_interior_csv(OUT("interior.csv"), &r->sc, r->u, r->s, err);
    if (!st && r->has_k && r->sc.stiffness_write)
        st = gb_bem_write_stiffness_csv(OUT("stiffness.csv"), &r->sc.mesh, &r->k, err);
    int used = snprintf(text, sizeof text,
                        "gembem %s\nscene: %s\nmesh: %s (%d elements, %d loop(s), %s)\nunits: length %s, force %s\n"
                        "system rcond: %.6e (at the scene's own lengths: %.6e), length scale used: %.6g\n",
                        gb_version(), r->sc.path, r->sc.mesh_path, r->sc.mesh.n, r->sc.mesh.n_loops,
                        r->sc.mesh.unbounded ? "unbounded" : "bounded", r->sc.length_unit, r->sc.force_unit,
                        r->sol.rcond, r->sol.rcond_first, r->sol.scale);
    if (r->has_k && used > 0 && used < (int)sizeof text)
        snprintf(text + used, sizeof text - (size_t)used,
                 "stiffness on '%s': %d x %d, ||K - K^t||_F / ||K||_F = %.6e, rcond %.6e, length scale %.6g\n",
                 r->sc.stiffness_group, r->k.m, r->k.m, r->k.asymmetry, r->k.rcond, r->k.scale);
    if (!st) st = write_text(OUT("summary.txt"), text, err);
    if (!st) fputs(text, stdout);
#undef OUT
    return st;
}

int gb_cli_bem(int argc, char **argv)
{
    const char *scene = NULL, *out = NULL;
    int overwrite = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            usage(stdout);
            return 0;
        }
        if (!strcmp(argv[i], "-o") && i + 1 < argc)
            out = argv[++i];
        else if (!strcmp(argv[i], "--overwrite"))
            overwrite = 1;
        else if (argv[i][0] != '-' && !scene)
            scene = argv[i];
        else {
            fprintf(stderr, "gembem bem: unexpected argument '%s'\n", argv[i]);
            usage(stderr);
            return 2;
        }
    }
    if (!scene || !out) {
        usage(stderr);
        return 2;
    }
    gb_error err = {0};
    run r;
    memset(&r, 0, sizeof r);
    /* the directory first: a refusal costs no solve */
    gb_status st = check_outdir(out, overwrite, &err);
    if (!st) st = compute(scene, &r, &err);
    if (!st && mkdir(out, 0777) != 0 && errno != EEXIST)
        st = gb_fail(&err, GB_EIO, "%s: cannot create the output directory: %s", out, strerror(errno));
    if (!st) st = write_all(out, &r, &err);
    int rc = st ? gb_cli_report(&err) : 0;
    gb_bem_stiffness_free(&r.k);
    gb_bem_solution_free(&r.sol);
    gb_bem_system_free(&r.sys);
    gb_bem_scene_free(&r.sc);
    free(r.u);
    free(r.s);
    free(r.bs);
    return rc;
}
