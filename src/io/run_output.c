/* The run directory of `gembem run`. */
#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "core/clock.h"
#include "gem/sim.h"
#include "gembem/measure.h"
#include "io/host_output.h"
#include "io/checkpoint.h"
#include "io/dir_lock.h"
#include "io/file_util.h"
#include "io/measure_output.h"
#include "io/run_output.h"
#include "io/scene_report.h"
#include "io/run_record.h"
#include "io/run_verdict.h"
#include "io/steps_csv.h"
#include "io/vtk.h"

#define GB_STR_(x) #x
#define GB_STR(x) GB_STR_(x)

struct gb_run_output {
    char dir[GB_DIR_MAX + 1];
    gb_dir_lock lock;  /* dir/.lock, held while o lives */
    const gb_scene *scene;
    FILE *steps;
    FILE *micro;  /* micromechanics.csv */
    FILE *host;   /* host_steps.csv (hybrid scenes) */
    FILE *history; /* history.csv (solver.history) */
    int history_failed;
    char command[1024];
    char started[64];
    int *snap_steps, n_snaps; /* steps that were written, for the .pvd collection */
    int snap_cap;
    gb_checkpoint_meta ck;    /* the scene's hash and path; the appended files' marks at each checkpoint */
    const char *appended[GB_CHECKPOINT_MAX_FILES];
    int n_appended;
    double last_checkpoint;   /* gb_clock_seconds() */
    int interrupted;          /* earlier runs of the directory that stopped before they ended (killed, signalled) */
    char resumed[4096];       /* run_info.yaml's "resumed:" list items */
    double started_seconds;   /* gb_clock_seconds() when this process opened the directory */
    double close_seconds;     /* spent writing the final state */
    gb_run_profile phases;    /* the time split of the run written into it (gb_run_output_phases) */
};

/* The files a run appends to (or rewrites in place at their end), cut back to their checkpoint's
 * marks on a resume; the others are written whole at each step (atomically) and rewritten alike. */
static void list_appended(gb_run_output *o)
{
    static const char *const names[] = {"steps.csv", "micromechanics.csv", "localisation.csv",
                                        "fields/triangles.pvd", "host_steps.csv"};
    o->n_appended = 0;
    for (int k = 0; k < 5; k++) /* localisation.csv unless turned off, host_steps.csv with a host */
        if ((k != 2 || o->scene->localisation) && (k != 4 || o->scene->host.present))
            o->appended[o->n_appended++] = names[k];
    if (o->scene->solver.history) o->appended[o->n_appended++] = "history.csv";
}

/* sim: for the solver's times (may be NULL); verdict: at the end (else NULL). */
static gb_status write_info(const gb_run_output *o, const gb_sim *sim, const char *status, const char *message,
                            const gb_run_verdict *verdict, gb_error *err)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/run_info.yaml", o->dir);
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    fprintf(a.f, "# How this run directory was made.\n");
    gb_run_record_origin(a.f, o->command, o->scene->path, "started", o->started);
    const char *threads = getenv("OPENBLAS_NUM_THREADS");
    fprintf(a.f, "openblas_threads: \"%s\"\n", threads ? threads : "default");
    const gb_scene *sc = o->scene;
    fprintf(a.f, "measures_every: %d   # fields/ of the per-step measures (0: none)%s\n", sc->measures_every,
            sc->measures_every_given ? ""
            : sc->measures_every ? "; the default below " GB_STR(GB_MEASURES_DEFAULT_GRAINS) " grains"
                                 : "; the default from " GB_STR(GB_MEASURES_DEFAULT_GRAINS) " grains up");
    gb_scene_report_write(a.f, sc);
    gb_run_record_settings(a.f, sc);
    gb_run_record_machine(a.f);
    gb_run_record_times(a.f, sim, o->phases, gb_clock_seconds() - o->started_seconds, o->close_seconds);
    if (verdict) gb_run_verdict_write(a.f, verdict);
    fprintf(a.f, "status: %s\n", status);
    if (o->resumed[0])
        fprintf(a.f, "interrupted: %d   # runs of this directory killed or interrupted before they ended\nresumed:\n%s",
                o->interrupted, o->resumed);
    if (message) gb_info_quoted(a.f, "message", message);
    return gb_atomic_commit(&a, err);
}

/* An open or a resume (undo: the lock file put back as it was) that failed: o's files closed, the
 * lock let go, o freed. */
static gb_status open_failed(gb_run_output *o, gb_status st, int undo)
{
    FILE *files[4] = {o->steps, o->micro, o->host, o->history};
    for (int k = 0; k < 4; k++)
        if (files[k]) fclose(files[k]);
    if (undo) gb_dir_lock_undo(&o->lock);
    else gb_dir_lock_status(&o->lock, gb_status_name(st));
    gb_dir_lock_release(&o->lock);
    free(o->snap_steps);
    free(o);
    return st;
}

gb_status gb_run_output_open(const char *dir, const gb_sim *sim, int overwrite, const char *command,
                             gb_run_output **out, gb_error *err)
{
    *out = NULL;
    const gb_scene *scene = gb_sim_scene(sim);
    gb_status st1 = gb_output_dir_check(dir, overwrite, "run directory", err);
    if (st1) return st1;
    gb_checkpoint_meta ck;
    memset(&ck, 0, sizeof ck);
    if (!realpath(scene->path, ck.scene_path)) return gb_fail(err, GB_EINPUT, "%s: %s", scene->path, strerror(errno));
    gb_status st0 = gb_checkpoint_scene_hash(sim, &ck.scene_hash, err);
    if (st0) return st0;
    gb_run_output *o = calloc(1, sizeof *o);
    if (!o) return gb_fail(err, GB_ENOMEM, "out of memory");
    /* the directory this process's before anything in it is made or replaced */
    gb_status st = gb_dir_lock_take(&o->lock, dir, 1, overwrite, "run directory", err);
    if (st) {
        free(o);
        return st;
    }
    snprintf(o->dir, sizeof o->dir, "%s", dir);
    snprintf(o->command, sizeof o->command, "%s", command);
    o->scene = scene;
    o->ck = ck;
    o->last_checkpoint = gb_clock_seconds();
    list_appended(o);
    time_t now = time(NULL);
    strftime(o->started, sizeof o->started, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, GB_CHECKPOINT_NAME); /* an older run's, with --overwrite */
    if (remove(path) != 0 && errno != ENOENT) {
        st = gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno));
        return open_failed(o, st, 0);
    }
    snprintf(path, sizeof path, "%s/scene.yaml", dir);
    o->started_seconds = gb_clock_seconds();
    if ((st = gb_copy_file(scene->path, path, err)) || (st = write_info(o, sim, "running", NULL, NULL, err)))
        return open_failed(o, st, 0);
    snprintf(path, sizeof path, "%s/steps.csv", dir);
    if (!(o->steps = fopen(path, "w"))) return open_failed(o, gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno)), 0);
    gb_steps_csv_header(o->steps);
    fflush(o->steps);
    snprintf(path, sizeof path, "%s/micromechanics.csv", dir);
    if (!(o->micro = fopen(path, "w"))) return open_failed(o, gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno)), 0);
    /* Tensors in x (horizontal), y (vertical) components; energies absolute (force x length) and
     * since the start of the run; densities divide by the area. */
    fprintf(o->micro, "step,contacts,wall_contacts,coordination,C_xx,C_yy,C_xy,C_major,C_minor,C_angle_deg,"
                      "E_xx,E_yy,E_xy,E_major,E_minor,E_angle_deg,area,elastic_energy,work,work_walls,work_body,"
                      "dissipation,dissipation_step,dissipation_step_k28,balance,P_max,work_walls_iter,relaxation,"
                      "balance_iter\n");
    fflush(o->micro);
    if (scene->host.present) {
        snprintf(path, sizeof path, "%s/host_steps.csv", dir);
        if (!(o->host = fopen(path, "w")))
            return open_failed(o, gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno)), 0);
        gb_host_write_steps_header(o->host, scene);
    }
    if (scene->solver.history) {
        snprintf(path, sizeof path, "%s/history.csv", dir);
        if (!(o->history = fopen(path, "w")))
            return open_failed(o, gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno)), 0);
        fprintf(o->history, "step,attempt,iteration,max_fixing_force,wall_residual,largest_move,damping,length,sweeps,"
                             "smoother\n");
        fflush(o->history);
    }
    *out = o;
    return GB_OK;
}

void gb_run_output_iteration(void *user, const gb_iteration_report *r)
{
    gb_run_output *o = user;
    if (!o->history || o->history_failed) return;
    gb_test_kill_point(o->history);
    fprintf(o->history, "%d,%d,%ld,%.6e,%.6e,%.6e,%.6e,%.6e,%ld,%d\n", r->step, r->attempt, r->iteration,
            r->max_fixing_force, r->wall_residual, r->largest_move, r->damping, r->length, r->sweeps, r->smoother);
    if (fflush(o->history) != 0 || ferror(o->history)) o->history_failed = 1;
}

static int snapshot_due(const gb_scene *s, int step);
static gb_status add_snapshot(gb_run_output *o, int step, gb_error *err);


/* The value of "key: " on its line of run_info.yaml's text, quotes dropped, or "". */
static void info_value(const char *text, const char *key, char *out, size_t cap)
{
    out[0] = '\0';
    size_t n = strlen(key);
    for (const char *l = text; l && *l; l = strchr(l, '\n') ? strchr(l, '\n') + 1 : NULL) {
        if (strncmp(l, key, n) || l[n] != ':' || l[n + 1] != ' ') continue;
        const char *v = l + n + 2, *e = strchr(v, '\n');
        size_t len = e ? (size_t)(e - v) : strlen(v);
        if (len >= 2 && v[0] == '"' && v[len - 1] == '"') v++, len -= 2;
        if (len >= cap) len = cap - 1;
        memcpy(out, v, len), out[len] = '\0';
        return;
    }
}

/* The temporary files of atomic writes that an interruption left in dir/sub. */
static void remove_tmp(const char *dir, const char *sub)
{
    char path[1200];
    snprintf(path, sizeof path, "%s%s%s", dir, *sub ? "/" : "", sub);
    DIR *d = opendir(path);
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d))) {
        size_t n = strlen(e->d_name);
        if (n < 4 || strcmp(e->d_name + n - 4, ".tmp")) continue;
        char f[1500];
        snprintf(f, sizeof f, "%s/%s", path, e->d_name);
        remove(f);
    }
    closedir(d);
}

static gb_status open_append(gb_run_output *o, const char *name, FILE **f, gb_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", o->dir, name);
    if (!(*f = fopen(path, "a"))) return gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno));
    return GB_OK;
}

/* A directory with a run to resume, which no process writes: its run_info.yaml's text (may be
 * empty) and how its last run ended: run_info.yaml's status, but for a `running` there, which no
 * live process holds, the status its lock file recorded (a disk too full to rewrite run_info.yaml)
 * or else `killed` (docs/run-directory.md, "The morning after"). */
static gb_status resumable(const char *dir, char *info, size_t cap, char *status, size_t status_cap, gb_error *err)
{
    struct stat sb;
    gb_status st = gb_dir_length_check(dir, "run directory", err);
    if (st) return st;
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)) return gb_fail(err, GB_EINPUT, "%s: no such run directory", dir);
    char path[1200], holder[384], last[64];
    if (gb_dir_lock_probe(dir, holder, sizeof holder, last, sizeof last))
        return gb_fail(err, GB_EINPUT, "%s: its run is still going (%s; its %s/%s): a live run cannot be resumed; "
                       "stop it first (SIGTERM or Ctrl-C: it writes a checkpoint and says so)", dir, holder, dir,
                       GB_LOCK_NAME);
    snprintf(path, sizeof path, "%s/run_info.yaml", dir);
    FILE *f = fopen(path, "r");
    info[0] = '\0';
    if (f) {
        info[fread(info, 1, cap - 1, f)] = '\0';
        fclose(f);
    }
    info_value(info, "status", status, status_cap);
    if (!strcmp(status, "running"))
        snprintf(status, status_cap, "%s", last[0] && strcmp(last, "running") ? last : "killed");
    snprintf(path, sizeof path, "%s/%s", dir, GB_CHECKPOINT_NAME);
    if (!strcmp(status, "completed")) {
        remove(path); /* left if the run was killed just after saying it completed */
        return gb_fail(err, GB_EINPUT, "%s: the run completed (run_info.yaml); nothing to resume", dir);
    }
    if (stat(path, &sb) != 0)
        return gb_fail(err, GB_EINPUT, "%s: no %s to resume from: not a run directory, or its run stopped before its "
                       "first checkpoint (or output.checkpoint_every is 0); run the scene again", dir,
                       GB_CHECKPOINT_NAME);
    return GB_OK;
}

gb_status gb_run_output_resume(const char *dir, gb_sim *sim, gb_run_progress *p, const char *command,
                               gb_run_output **out, gb_error *err)
{
    *out = NULL;
    struct stat sb;
    char path[1200], info[16384], status[64], value[1024];
    gb_status st = resumable(dir, info, sizeof info, status, sizeof status, err);
    if (st) return st;
    /* the directory this process's before its files are cut back */
    gb_dir_lock lock;
    if ((st = gb_dir_lock_take(&lock, dir, 0, 1, "run directory", err))) return st;
    uint64_t hash;
    gb_checkpoint_meta ck;
    memset(&ck, 0, sizeof ck);
    st = gb_checkpoint_scene_hash(sim, &hash, err);
    if (!st) st = gb_checkpoint_read(dir, sim, p, hash, &ck, err);
    for (int k = 0; k < ck.n_files && !st; k++) { /* all checked before any is cut */
        snprintf(path, sizeof path, "%s/%s", dir, ck.file[k].name);
        if (ck.file[k].length >= 0 && (stat(path, &sb) != 0 || (long long)sb.st_size < ck.file[k].length))
            st = gb_fail(err, GB_EINPUT, "%s: missing or shorter than its checkpoint records (%lld bytes); the run "
                         "directory was changed", path, ck.file[k].length);
    }
    for (int k = 0; k < ck.n_files && !st; k++) st = gb_checkpoint_file_rewind(dir, &ck.file[k], err);
    if (st) {
        gb_dir_lock_undo(&lock); /* a refused resume leaves the directory as it was */
        return st;
    }
    static const char *const subs[] = {"", "snapshots", "contacts", "fields"};
    for (int k = 0; k < 4; k++) remove_tmp(dir, subs[k]);
    gb_run_output *o = calloc(1, sizeof *o);
    if (!o) {
        gb_dir_lock_release(&lock);
        return gb_fail(err, GB_ENOMEM, "out of memory");
    }
    o->lock = lock;
    snprintf(o->dir, sizeof o->dir, "%s", dir);
    o->scene = gb_sim_scene(sim);
    o->ck = ck;
    if (!realpath(o->scene->path, o->ck.scene_path)) /* the SCENE given, if it moved */
        snprintf(o->ck.scene_path, sizeof o->ck.scene_path, "%s", ck.scene_path);
    o->last_checkpoint = gb_clock_seconds();
    list_appended(o);
    info_value(info, "command", value, sizeof value);
    snprintf(o->command, sizeof o->command, "%s", value[0] ? value : "?");
    info_value(info, "started", o->started, sizeof o->started);
    info_value(info, "interrupted", value, sizeof value);
    o->interrupted = atoi(value) + (!strcmp(status, "killed") || !strcmp(status, "interrupted"));
    const char *items = strstr(info, "\nresumed:\n");
    size_t used = 0;
    for (const char *l = items ? items + 10 : NULL; l && !strncmp(l, "  - ", 4); l = strchr(l, '\n') + 1) {
        size_t n = strchr(l, '\n') ? (size_t)(strchr(l, '\n') - l + 1) : 0;
        if (!n || used + n >= sizeof o->resumed / 2) break;
        memcpy(o->resumed + used, l, n), used += n;
    }
    time_t now = time(NULL);
    char at[64];
    strftime(at, sizeof at, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
    const char *threads = getenv("OPENBLAS_NUM_THREADS");
    char within[96] = "";
    if (p->cur.active)
        snprintf(within, sizeof within, " within_step: true, iterations_done: %ld,", gb_run_step_iterations(&p->cur));
    snprintf(o->resumed + used, sizeof o->resumed - used,
             "  - {at: %s, after_step: %d,%s previous_status: %s, openblas_threads: \"%s\", command: \"%s\"}\n",
             at, p->pos.step, within, status[0] ? status : "unknown",
             threads ? threads : "default", command);
    for (int q = 0; q <= p->pos.step && !st; q++)
        if (snapshot_due(o->scene, q)) st = add_snapshot(o, q, err);
    if (!st) st = open_append(o, "steps.csv", &o->steps, err);
    if (!st) st = open_append(o, "micromechanics.csv", &o->micro, err);
    if (!st && o->scene->host.present) st = open_append(o, "host_steps.csv", &o->host, err);
    if (!st && o->scene->solver.history) st = open_append(o, "history.csv", &o->history, err);
    o->started_seconds = gb_clock_seconds();
    if (!st) st = write_info(o, sim, "running", NULL, NULL, err);
    if (st) return open_failed(o, st, 1);
    *out = o;
    return GB_OK;
}

static int snapshot_due(const gb_scene *s, int step)
{
    if (s->snapshot_every > 0 && step % s->snapshot_every == 0) return 1;
    for (int k = 0; k < s->n_snapshot_steps; k++)
        if (s->snapshot_steps[k] == step) return 1;
    return 0;
}

static gb_status add_snapshot(gb_run_output *o, int step, gb_error *err)
{
    if (o->n_snaps == o->snap_cap) {
        int cap = o->snap_cap ? 2 * o->snap_cap : 16;
        int *p = realloc(o->snap_steps, (size_t)cap * sizeof *p);
        if (!p) return gb_fail(err, GB_ENOMEM, "out of memory");
        o->snap_steps = p;
        o->snap_cap = cap;
    }
    o->snap_steps[o->n_snaps++] = step;
    return GB_OK;
}

static gb_status write_pvd(const gb_run_output *o, const char *what, gb_error *err)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.pvd", o->dir, what);
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    gb_vtk_pvd_head(a.f);
    for (int k = 0; k < o->n_snaps; k++) {
        char file[96];
        snprintf(file, sizeof file, "snapshots/%s_%06d.vtp", what, o->snap_steps[k]);
        gb_vtk_pvd_dataset(a.f, o->snap_steps[k], file);
    }
    fputs(GB_VTK_PVD_TAIL, a.f);
    return gb_atomic_commit(&a, err);
}

/* Contact normals by direction (K Figs. 11, 12), 36 sectors of 10 degrees. */
static gb_status write_rose_csv(const char *path, const gb_sim *sim, gb_error *err)
{
    enum { NB = 36 };
    double count[NB], energy[NB];
    gb_micro_rose(sim, NB, count, energy);
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    fprintf(a.f, "from_deg,to_deg,count,energy\n");
    for (int b = 0; b < NB; b++) fprintf(a.f, "%d,%d,%.0f,%.10e\n", 10 * b, 10 * (b + 1), count[b], energy[b]);
    return gb_atomic_commit(&a, err);
}

static gb_status write_snapshot(gb_run_output *o, const gb_sim *sim, int step, gb_error *err);

/* checkpoint.txt for the step just written, or within the step in progress: the appended files'
 * marks (within a step only history.csv has grown since the last step's rows), then the state. */
static gb_status checkpoint(gb_run_output *o, const gb_sim *sim, const gb_run_progress *p, gb_error *err)
{
    gb_status st = GB_OK;
    o->ck.n_files = o->n_appended;
    for (int k = 0; k < o->n_appended && !st; k++)
        st = gb_checkpoint_file_mark(o->dir, o->appended[k], &o->ck.file[k], err);
    if (!st) st = gb_checkpoint_write(o->dir, sim, p, &o->ck, err);
    o->last_checkpoint = gb_clock_seconds();
    return st;
}

/* A checkpoint is due when output.checkpoint_minutes have passed since the last one (checkpoints on). */
static int checkpoint_time(const gb_run_output *o)
{
    const gb_scene *sc = o->scene;
    return sc->checkpoint_every > 0 && gb_clock_seconds() - o->last_checkpoint >= 60 * sc->checkpoint_minutes;
}

/* An appended file's write failed (errno: why, e.g. a full disk or a file size limit). */
static gb_status write_failed(const gb_run_output *o, const char *name, gb_error *err)
{
    return gb_fail(err, GB_EIO, "%s/%s: write failed: %s", o->dir, name, strerror(errno));
}

/* A stop asked for (gembem/run.h): a checkpoint where the run is, unless one was just written for
 * it, then GB_EINTERRUPTED saying where (`where`: "after step 3", "in step 4, after iteration 120"). */
static gb_status stop_here(gb_run_output *o, const gb_sim *sim, const gb_run_progress *p, int reason, int written,
                           const char *where, gb_error *err)
{
    gb_status st = written ? GB_OK : checkpoint(o, sim, p, err);
    if (st) return st;
    char name[32];
    return gb_fail(err, GB_EINTERRUPTED, "interrupted by %s %s; its checkpoint is written: continue with gembem run "
                   "--resume %s", gb_run_signal_name(reason, name, sizeof name), where, o->dir);
}

gb_status gb_run_output_within_step(gb_run_output *o, const gb_sim *sim, const gb_run_progress *p, gb_error *err)
{
    int reason = gb_run_stop_requested();
    if (reason) {
        /* its mark would count rows that are not there */
        if (o->history_failed) return gb_fail(err, GB_EIO, "%s/history.csv: write failed", o->dir);
        char where[96];
        snprintf(where, sizeof where, "in step %d, after %ld iterations", p->cur.step,
                 gb_run_step_iterations(&p->cur));
        return stop_here(o, sim, p, reason, 0, where, err);
    }
    int test = o->scene->checkpoint_every > 0 && gb_test_checkpoint_due();
    if (!test && !checkpoint_time(o)) return GB_OK;
    /* its mark would count rows that are not there */
    if (o->history_failed) return gb_fail(err, GB_EIO, "%s/history.csv: write failed", o->dir);
    return checkpoint(o, sim, p, err);
}

void gb_run_output_phases(gb_run_output *o, const gb_run_profile *phases) { o->phases = *phases; }

int gb_run_output_fields_due(const gb_run_output *o, int step)
{
    return o->scene->measures_every > 0 && step % o->scene->measures_every == 0;
}

gb_status gb_run_output_step(gb_run_output *o, const gb_sim *sim, const gb_run_progress *p, const gb_step_report *r,
                             const gb_step_measures *ms, gb_error *err)
{
    gb_test_kill_point(o->steps);
    gb_steps_csv_row(o->steps, r);
    if (fflush(o->steps) != 0 || ferror(o->steps)) return write_failed(o, "steps.csv", err);
    if (o->history_failed) return gb_fail(err, GB_EIO, "%s/history.csv: write failed", o->dir);
    const gb_micro m = ms->micro;
    gb_test_kill_point(o->micro);
    fprintf(o->micro, "%d,%d,%d,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%.6f,%.10e,%.10e,%.10e,%.10e,%.10e,%.6f,%.17g,"
                      "%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%.6f,%.10e,%.10e,%.10e\n",
            r->step, m.n_contacts, m.n_wall_contacts, m.coordination, m.fabric.xx, m.fabric.yy, m.fabric.xy,
            m.fabric.major, m.fabric.minor, m.fabric.angle_deg, m.energy.xx, m.energy.yy, m.energy.xy,
            m.energy.major, m.energy.minor, m.energy.angle_deg, m.area, m.elastic_energy, m.work, m.work_walls,
            m.work_body, m.dissipation, m.dissipation_step, m.dissipation_step_k28, m.balance, m.p_max,
            m.work_walls_iter, m.relaxation, m.balance_iter);
    if (fflush(o->micro) != 0 || ferror(o->micro))
        return write_failed(o, "micromechanics.csv", err);
    gb_status st;
    const gb_scene *sc = o->scene;
    char path[1024];
    if (o->host) gb_test_kill_point(o->host);
    if (o->host && (st = gb_host_write_step(o->host, r->step, sim, err))) return st;
    if ((st = gb_measure_write_step(o->dir, ms, err))) return st;
    if ((sc->contacts_every > 0 && r->step % sc->contacts_every == 0) || snapshot_due(sc, r->step)) {
        snprintf(path, sizeof path, "%s/contacts", o->dir);
        if ((st = gb_make_dirs(path, err))) return st;
        snprintf(path, sizeof path, "%s/contacts/contacts_%06d.csv", o->dir, r->step);
        if ((st = gb_contacts_csv_write(path, sim, err))) return st;
        snprintf(path, sizeof path, "%s/contacts/grains_%06d.csv", o->dir, r->step);
        if ((st = gb_grains_csv_write(path, sim, err))) return st;
        snprintf(path, sizeof path, "%s/contacts/rose_%06d.csv", o->dir, r->step);
        if ((st = write_rose_csv(path, sim, err))) return st;
    }
    if (snapshot_due(sc, r->step) && (st = write_snapshot(o, sim, r->step, err))) return st;
    int due = (sc->checkpoint_every > 0 && r->step % sc->checkpoint_every == 0) || checkpoint_time(o);
    if (due && (st = checkpoint(o, sim, p, err))) return st;
    int reason = gb_run_stop_requested();
    if (!reason) return GB_OK;
    snprintf(path, sizeof path, "after step %d", r->step);
    return stop_here(o, sim, p, reason, due, path, err);
}

static gb_status write_snapshot(gb_run_output *o, const gb_sim *sim, int step, gb_error *err)
{
    char path[1024];
    gb_status st;
    snprintf(path, sizeof path, "%s/snapshots", o->dir);
    if ((st = gb_make_dirs(path, err))) return st;
    snprintf(path, sizeof path, "%s/snapshots/grains_%06d.vtp", o->dir, step);
    if ((st = gb_vtk_write_grains(path, sim, err))) return st;
    snprintf(path, sizeof path, "%s/snapshots/contacts_%06d.vtp", o->dir, step);
    if ((st = gb_vtk_write_contacts(path, sim, err)) || (st = add_snapshot(o, step, err))) return st;
    if ((st = write_pvd(o, "grains", err))) return st;
    return write_pvd(o, "contacts", err);
}

gb_status gb_run_output_close(gb_run_output *o, const gb_sim *sim, gb_status run_status, const char *message,
                              gb_error *err)
{
    gb_status st = GB_OK;
    if (o->steps && fclose(o->steps) != 0) st = write_failed(o, "steps.csv", err);
    if (o->micro && fclose(o->micro) != 0 && !st) st = write_failed(o, "micromechanics.csv", err);
    if (o->host && fclose(o->host) != 0 && !st) st = write_failed(o, "host_steps.csv", err);
    if (o->history && fclose(o->history) != 0 && !st) o->history_failed = 1;
    if ((o->history_failed) && !st) st = gb_fail(err, GB_EIO, "%s/history.csv: write failed", o->dir);
    o->steps = o->micro = o->host = o->history = NULL;
    double t0 = gb_clock_seconds();
    if (!st && sim) st = gb_state_write(o->dir, sim, err);
    if (!st && sim && sim->host) st = gb_host_write_outputs(o->dir, sim, err);
    o->close_seconds += gb_clock_seconds() - t0;
    /* The verdict of every step the directory holds (a resumed run's earlier ones too), and the
     * warnings where the result is noise (docs/run-directory.md#warnings): said once more on stderr. */
    gb_run_verdict verdict;
    if (!st) st = gb_run_verdict_read(o->dir, o->scene, &verdict, err);
    for (int k = o->scene->warning[0] ? 1 : 0; !st && k < verdict.n_warnings; k++)
        fprintf(stderr, "gembem: warning: %s\n", verdict.warning[k]);
    /* How the run ended: its own failure, else the final files' (written where it still can be) */
    gb_status end = run_status ? run_status : st;
    char why[GB_ERROR_MSG_MAX];
    snprintf(why, sizeof why, "%s", run_status ? (message ? message : "") : st ? err->msg : "");
    gb_error info_err = {0};
    gb_status ist = write_info(o, sim, end ? gb_status_name(end) : "completed", why[0] ? why : NULL,
                               st ? NULL : &verdict, &info_err);
    if (!st && ist) st = ist, *err = info_err;
    /* where run_info.yaml could not say it (a full disk), the lock file, rewritten in place, does */
    gb_dir_lock_status(&o->lock, end ? gb_status_name(end) : "completed");
    /* A completed run has nothing to resume; any other keeps its last checkpoint. */
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", o->dir, GB_CHECKPOINT_NAME);
    if (!st && run_status == GB_OK) remove(path);
    gb_dir_lock_release(&o->lock);
    free(o->snap_steps);
    free(o);
    return st;
}

gb_status gb_run_output_resume_scene(const char *dir, char *path, size_t cap, gb_error *err)
{
    gb_checkpoint_meta ck;
    char info[16384], status[64];
    gb_status st = resumable(dir, info, sizeof info, status, sizeof status, err);
    if (!st) st = gb_checkpoint_read_meta(dir, &ck, err);
    if (!st) snprintf(path, cap, "%s", ck.scene_path);
    return st;
}
