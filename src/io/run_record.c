/* run_info.yaml's settings, machine and time: what a reader needs to tell how the answer was made
 * and what it cost without opening the code. */
#define _POSIX_C_SOURCE 200809L
#include "io/run_record.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/clock.h"
#include "core/memory.h"
#include "gembem/petsc.h"
#include "io/scene_report.h"
#include "solver/linear.h"
#include "solver/solver.h"

void gb_run_record_origin(FILE *f, const char *command, const char *scene, const char *when_key, const char *when)
{
    char now[64];
    time_t t = time(NULL);
    strftime(now, sizeof now, "%Y-%m-%dT%H:%M:%SZ", gmtime(&t));
    fprintf(f, "gembem_version: %s\ncommand: \"%s\"\nscene: \"%s\"\n%s: %s\n", gb_version(), command, scene,
            when_key, when ? when : now);
}

static void material(FILE *f, const char *name, const gb_material *m)
{
    fprintf(f, "    %s: {kn: %.17g, kt: %.17g, friction_deg: %.17g, cohesion: %.17g", name, m->kn, m->kt,
            m->friction_deg, m->cohesion);
    if (m->kr > 0) fprintf(f, ", rolling: {kr: %.17g, eta: %.17g}", m->kr, m->eta);
    fprintf(f, "}\n");
}

static void stage(FILE *f, const gb_stage *sg)
{
    fprintf(f, "    - %s: {steps: %d", gb_stage_name(sg->kind), sg->steps);
    switch (sg->kind) {
    case GB_STAGE_ISOTROPIC: fprintf(f, ", stress: %.17g", sg->stress); break;
    case GB_STAGE_BIAXIAL_STRESS: fprintf(f, ", s1: %.17g, s2: %.17g", sg->s1, sg->s2); break;
    case GB_STAGE_STRAIN: fprintf(f, ", de1: %.17g, de2: %.17g", sg->de1, sg->de2); break;
    case GB_STAGE_SHEAR_MEAN:
        fprintf(f, ", d_e1_minus_e2: %.17g, mean_stress: %.17g", sg->d_shear, sg->mean_stress);
        break;
    case GB_STAGE_HOST_DISPLACEMENT:
    case GB_STAGE_HOST_LOAD:
        fprintf(f, ", increments: {");
        for (int q = 0; q < sg->n_host_groups; q++)
            fprintf(f, "%s%s: [%.17g, %.17g]", q ? ", " : "", sg->host_group[q], sg->host_increment[q][0],
                    sg->host_increment[q][1]);
        fprintf(f, "}, remote_stress: [%.17g, %.17g, %.17g]", sg->host_remote_increment[0],
                sg->host_remote_increment[1], sg->host_remote_increment[2]);
        break;
    default: break;
    }
    fprintf(f, ", reset_strain: %s}\n", sg->reset_strain ? "true" : "false");
}

void gb_run_record_settings(FILE *f, const gb_scene *sc)
{
    const gb_solver_settings *sv = &sc->solver;
    fprintf(f, "settings:   # every setting as the run used it, defaults spelled out\n");
    fprintf(f, "  units: {length: %s, force: %s}\n  materials:\n", sc->length_unit, sc->force_unit);
    material(f, "grain_grain", &sc->grain_grain);
    material(f, "grain_wall", &sc->grain_wall);
    material(f, "grain_boundary", &sc->grain_boundary);
    fprintf(f, "  grains: %d\n  body_force_per_area: [%.17g, %.17g]\n", sc->n_grains, sc->body_force_per_area[0],
            sc->body_force_per_area[1]);
    fprintf(f, "  solver:\n    method: %s\n", sv->method == GB_METHOD_GLOBAL ? "global" : "reference");
    if (sv->method == GB_METHOD_GLOBAL)
        fprintf(f, "    linear: %s\n    newton: %s\n    global_alpha: %.17g\n    max_move: %.17g\n",
                gb_linear_backend_of(sv->linear)->name,
                sv->newton == GB_NEWTON_LINE_SEARCH ? "line_search" : "damped", sv->global_alpha, sv->max_move);
    if (sv->method == GB_METHOD_GLOBAL && sv->linear == GB_LINEAR_PETSC) {
        const gb_petsc_settings *p = &sv->petsc;
        fprintf(f, "    petsc:\n      ranks: %d   # MPI processes in the solves\n      ksp: %s\n      pc: %s\n"
                   "      factor: %s\n      rtol: %.17g\n      ", gb_petsc_ranks(), p->ksp,
                p->pc[0] ? p->pc : sv->newton == GB_NEWTON_LINE_SEARCH ? "lu" : "cholesky", p->factor, p->rtol);
        gb_info_quoted(f, "options", p->options);
    }
    if (sv->accuracy_relative > 0)
        fprintf(f, "    accuracy: {relative: %.17g}%s\n", sv->accuracy_relative,
                sv->accuracy_default ? "   # the default: the scene gives none" : "");
    else
        fprintf(f, "    accuracy: %.17g   # [%s]\n", sv->accuracy, sc->force_unit);
    fprintf(f, "    alpha: %.17g\n    alpha1: %.17g\n    beta: %.17g\n    beta1: %.17g\n", sv->alpha, sv->alpha1,
            sv->beta, sv->beta1);
    fprintf(f, "    max_iterations: %ld\n    cutbacks: %d\n    history: %s\n    threads: %d\n", sv->max_iterations,
            sv->cutbacks, sv->history ? "true" : "false", sv->threads);
    fprintf(f, "  loading:\n");
    for (int k = 0; k < sc->n_stages; k++) stage(f, &sc->stages[k]);
    fprintf(f, "  output:\n    snapshot_every: %d\n    snapshot_steps: [", sc->snapshot_every);
    for (int k = 0; k < sc->n_snapshot_steps; k++) fprintf(f, "%s%d", k ? ", " : "", sc->snapshot_steps[k]);
    fprintf(f, "]\n    contacts_every: %d\n    measures_every: %d\n    localisation: %s\n    checkpoint_every: %d\n"
               "    checkpoint_minutes: %.17g\n",
            sc->contacts_every, sc->measures_every, sc->localisation ? "true" : "false", sc->checkpoint_every,
            sc->checkpoint_minutes);
}

void gb_run_record_machine(FILE *f)
{
    char model[256] = "unknown", line[512];
    FILE *in = fopen("/proc/cpuinfo", "r");
    while (in && fgets(line, sizeof line, in))
        if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
            const char *v = strchr(line, ':') + 1;
            while (*v == ' ' || *v == '\t') v++;
            snprintf(model, sizeof model, "%.*s", (int)strcspn(v, "\n\""), v);
            break;
        }
    if (in) fclose(in);
    const char *blas = getenv("OPENBLAS_NUM_THREADS"), *omp = getenv("OMP_NUM_THREADS");
    fprintf(f, "machine:\n  cpu: \"%s\"\n  cores: %ld   # online\n  memory_gb: %.1f\n", model,
            sysconf(_SC_NPROCESSORS_ONLN), gb_memory_physical() / 1e9);
    fprintf(f, "  blas_threads: \"%s\"   # OPENBLAS_NUM_THREADS; default: OpenBLAS's, one per core\n",
            blas ? blas : "default");
    fprintf(f, "  omp_threads: \"%s\"   # OMP_NUM_THREADS\n", omp ? omp : "default");
}

void gb_run_record_times(FILE *f, const gb_sim *sim, gb_run_profile p, double total, double close)
{
    fprintf(f, "time:   # seconds of this process (after a resume: since it), by phase\n  total: %.3f\n", total);
    fprintf(f, "  control: %.3f   # the steps' loads, saved states, cut-backs\n", p.control);
    fprintf(f, "  solve: %.3f   # relaxations (checkpoints within a step included)\n", p.solve);
    if (sim) {
        fprintf(f, "  contact_detection: %.3f   # within solve\n", sim->detect_seconds);
        const gb_global_stats *g = gb_solver_statistics(sim);
        if (g) {
            fprintf(f, "  assembly: %.3f   # within solve\n  analysis: %.3f   # within solve, %ld symbolic analyses\n"
                       "  factorisation: %.3f   # within solve, %ld factorisations",
                    g->assemble, g->analyse, g->analyses, g->factorise, g->factorisations);
            /* the last one's flops, as the solver counts them (0: not counted, PETSc), against
             * which the line search weighs a factorisation in smoother steps (line_search.c) */
            if (g->factor_flops > 0) fprintf(f, ", the last %.3g flops", g->factor_flops);
            fprintf(f, "\n  linear_solve: %.3f   # within solve\n", g->solve);
        }
    }
    fprintf(f, "  measure: %.3f   # steps.csv's errors, micromechanics.csv, localisation.csv, fields/\n", p.measure);
    fprintf(f, "  output: %.3f   # the steps' other files, checkpoints, and the final state (%.3f)\n", p.output + close,
            close);
}
