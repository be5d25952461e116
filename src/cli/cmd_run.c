/* gembem run SCENE.yaml -o RUNDIR: a granular scene through its loading program. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli/cli.h"
#include "gembem/run.h"
#include "io/file_util.h"

typedef struct {
    int progress;   /* stderr is a terminal */
    int quiet;
    struct timespec t0;
    int ran;        /* load steps (1, 2, ...) completed by this process: a resume runs fewer than the scene has */
} run_ctx;

static double elapsed(const struct timespec *t0)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)(t.tv_sec - t0->tv_sec) + 1e-9 * (double)(t.tv_nsec - t0->tv_nsec);
}

/* Progress on a terminal: the loop (gb_run_program) has written the step's files. */
static gb_status on_step(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)err;
    run_ctx *c = user;
    if (r->step >= 1) c->ran++;
    if (c->progress && !c->quiet) {
        /* a host has no box stresses: its steps show no stress ratio (steps.csv writes nan) */
        char ratio[48] = "";
        if (!gb_sim_scene(sim)->host.present && isfinite(r->stress_ratio))
            snprintf(ratio, sizeof ratio, "  stress ratio %.4f", r->stress_ratio);
        fprintf(stderr, "\rstep %d of %d%s  iterations %ld  elapsed %.1f s   ", r->step, r->total_steps, ratio,
                r->iterations, elapsed(&c->t0));
    }
    return GB_OK;
}

/* A step far longer than the run's others: a line every few seconds (a terminal's or a job's log). */
static void on_progress(void *user, const gb_step_progress *p)
{
    const run_ctx *c = user;
    if (c->quiet) return;
    char median[64] = "";
    if (p->median_seconds > 0) snprintf(median, sizeof median, " (the run's median step: %.3g s)", p->median_seconds);
    fprintf(stderr, "%sgembem: step %d (%d of %d in its stage) has run %.0f s%s: attempt %d, %ld iterations, %ld "
            "smoother steps, largest fixing force %.3g (accuracy %.3g)\n", c->progress ? "\r" : "", p->step,
            p->stage_step, p->stage_steps, p->seconds, median, p->attempt, p->iterations, p->sweeps,
            p->max_fixing_force, p->accuracy);
}

/* SIGTERM, SIGINT, SIGHUP (unless ignored at the start): the first asks the run to stop (it
 * checkpoints where it is, records `interrupted` and returns); a second while it finishes ends the
 * process at once, as without us. */
static void on_signal(int signo)
{
    if (gb_run_stop_requested()) {
        signal(signo, SIG_DFL);
        raise(signo);
        return;
    }
    gb_run_request_stop(signo);
}

static void catch_stop_signals(void)
{
    static const int sigs[] = {SIGTERM, SIGINT, SIGHUP};
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sa.sa_flags = SA_RESTART; /* the writes in progress go on; the run looks at the flag between them */
    sigemptyset(&sa.sa_mask);
    for (int k = 0; k < 3; k++) sigaddset(&sa.sa_mask, sigs[k]);
    for (int k = 0; k < 3; k++) {
        struct sigaction old;
        /* one ignored when we started stays so (nohup; a shell's background job and SIGINT) */
        if (sigaction(sigs[k], NULL, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        sigaction(sigs[k], &sa, NULL);
    }
}

static void usage(FILE *to)
{
    fprintf(to, "usage: gembem run SCENE.yaml -o RUNDIR [--overwrite] [--quiet]\n"
                "       gembem run --resume RUNDIR [SCENE.yaml] [--quiet]\n"
                "  Runs the scene's loading program with the scene's solver and writes RUNDIR/steps.csv,\n"
                "  RUNDIR/state.yaml (a scene can start from it), VTK snapshots and a copy of the scene.\n"
                "  RUNDIR/checkpoint.txt follows the run; --resume continues an interrupted run from it, with\n"
                "  the same scene (by default the path the run started with; refused if it changed).\n"
                "  Exit status: 0 done, 2 bad input (or RUNDIR in use by another gembem), 3 a step did not\n"
                "  converge (completed steps are kept), 4 an output could not be written (disk full, file size\n"
                "  limit: the last checkpoint is whole), 128+N stopped by signal N (SIGTERM 143, SIGINT 130,\n"
                "  SIGHUP 129: a checkpoint written where it stood, status interrupted; --resume continues).\n");
}

int gb_cli_run(int argc, char **argv)
{
    const char *scene_path = NULL, *dir = NULL, *resume = NULL;
    int overwrite = 0, quiet = 0;
    for (int k = 1; k < argc; k++) {
        if (!strcmp(argv[k], "-o") && k + 1 < argc) dir = argv[++k];
        else if (!strcmp(argv[k], "--resume") && k + 1 < argc) resume = argv[++k];
        else if (!strcmp(argv[k], "--overwrite")) overwrite = 1;
        else if (!strcmp(argv[k], "--quiet")) quiet = 1;
        else if (!strcmp(argv[k], "--help") || !strcmp(argv[k], "-h")) return usage(stdout), 0;
        else if (argv[k][0] != '-' && !scene_path) scene_path = argv[k];
        else {
            fprintf(stderr, "gembem run: unexpected argument '%s'\n", argv[k]);
            usage(stderr);
            return 2;
        }
    }
    if (resume ? dir || overwrite : !scene_path || !dir) {
        if (resume) fprintf(stderr, "gembem run: --resume continues in its own directory: no -o, no --overwrite\n");
        usage(stderr);
        return 2;
    }
    char command[1024];
    gb_cli_command_line(argc, argv, command, sizeof command);

    gb_error err = {0};
    char resume_scene[PATH_MAX];
    /* a directory in use (or too long a path) refused at once, before the scene is read */
    if (resume && gb_run_output_resume_scene(resume, resume_scene, sizeof resume_scene, &err))
        return gb_cli_report(&err);
    if (resume && !scene_path) scene_path = resume_scene;
    if (!resume && gb_output_dir_check(dir, overwrite, "run directory", &err)) return gb_cli_report(&err);
    if (resume) dir = resume;
    gb_scene scene;
    if (gb_scene_load(scene_path, &scene, &err)) return gb_cli_report(&err);
    if (scene.warning[0]) fprintf(stderr, "gembem: warning: %s\n", scene.warning);
    gb_sim *sim = NULL;
    gb_run *run = NULL;
    if (gb_sim_create(&scene, &sim, &err) || gb_run_create(sim, &run, &err)) {
        gb_sim_free(sim);
        gb_scene_free(&scene);
        return gb_cli_report(&err);
    }
    run_ctx ctx = {isatty(2), quiet, {0, 0}, 0};
    clock_gettime(CLOCK_MONOTONIC, &ctx.t0);
    gb_run_output *out = NULL;
    catch_stop_signals(); /* from here on the run directory records where a signal stopped it */
    if (resume ? gb_run_resume(run, dir, command, &out, &err)
               : gb_run_output_open(dir, sim, overwrite, command, &out, &err)) {
        gb_run_free(run);
        gb_sim_free(sim);
        gb_scene_free(&scene);
        return gb_cli_report(&err);
    }
    gb_run_on_progress(run, on_progress, &ctx);
    gb_status st = gb_run_program(run, out, on_step, &ctx, &err);
    if (ctx.progress && !quiet) fprintf(stderr, "\n");
    gb_error close_err = {0};
    gb_status cst = gb_run_output_close(out, sim, st, st ? err.msg : NULL, &close_err);
    int code = 0;
    if (st) {
        code = gb_cli_report(&err);
        if (st == GB_EINTERRUPTED) code = 128 + gb_run_stop_requested(); /* as a shell reports a signal's end */
    } else if (cst) code = gb_cli_report(&close_err);
    else if (!quiet) {
        /* the steps run here; a completed resume ran the scene's last ones, after the checkpoint's step */
        int total = gb_scene_total_steps(&scene);
        char from[64] = "";
        if (resume) snprintf(from, sizeof from, ", resumed after step %d of %d", total - ctx.ran, total);
        printf("gembem: %d steps done in %.2f s%s; results in %s\n", ctx.ran, elapsed(&ctx.t0), from, dir);
    }
    gb_run_free(run);
    gb_sim_free(sim);
    gb_scene_free(&scene);
    return code;
}
