/* The verdict of a run and the warnings where its result is noise, from its own tables. */
#include "io/run_verdict.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/number.h"
#include "scene/csv_read.h"

static void warn(gb_run_verdict *v, const char *fmt, ...)
{
    if (v->n_warnings == GB_VERDICT_WARNINGS) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(v->warning[v->n_warnings++], sizeof v->warning[0], fmt, ap);
    va_end(ap);
}

/* field k of the current row, NaN for "nan", an empty or a missing column */
static double value(const gb_csv *c, int k)
{
    if (k < 0 || k >= c->n_fields || !*c->field[k]) return NAN;
    char *end;
    double x = strtod(c->field[k], &end);
    return *end ? NAN : x;
}

/* What the warnings look at, step by step (steps >= 1). */
typedef struct {
    int accuracy_steps, accuracy_first, accuracy_worst_step;
    double accuracy_worst;
    int loose_steps, loose_first;
    double loose_z;
    int loose_rattlers;
    int swing_steps, swing_step, swing_from, swing_to;
    int last_contacts;
    double *secs;         /* each step's seconds (n_secs of them) */
    int n_secs, cap_secs, long_step, stalled_steps;
    double long_work, long_seconds; /* the longest step's iterations plus smoother steps, and seconds */
} watch;

/* A step far longer than the run's others, as a user waits for it: more than LONG_STEP times the
 * median step's seconds and more than LONG_STEP_SECONDS (the first step of a loose deposit's
 * compression is often ten times the others', but seconds long: not worth a warning). */
static const double LONG_STEP = 10, LONG_STEP_SECONDS = 60;

static void add_secs(watch *w, double seconds)
{
    if (w->n_secs == w->cap_secs) {
        int cap = w->cap_secs ? 2 * w->cap_secs : 64;
        double *a = realloc(w->secs, (size_t)cap * sizeof *a);
        if (!a) return; /* a warning less, not a failure */
        w->secs = a, w->cap_secs = cap;
    }
    w->secs[w->n_secs++] = seconds;
}

/* The longest step against the median (after read_steps): warns where it is far above. */
static void long_steps(gb_run_verdict *v, watch *w)
{
    if (w->n_secs < 3) return;
    double median = gb_median(w->secs, w->n_secs); /* sorted in place: the longest is known already */
    int far = 0;
    for (int k = 0; k < w->n_secs; k++) far += w->secs[k] > LONG_STEP * median && w->secs[k] > LONG_STEP_SECONDS;
    if (far)
        warn(v, "%d step(s) took more than %g times the median step's time (%.3g s): the longest, step %d, %.3g s "
                "(%.0f iterations and smoother steps). The packing rearranged there; smaller load steps share the "
                "rearrangement out, and solver.max_step_seconds bounds a step's time",
             far, LONG_STEP, median, w->long_step, w->long_seconds, w->long_work);
}

static void look_at_step(const gb_scene *sc, watch *w, int step, const double *x)
{
    enum { ACC, MEAN, Z, RATTLERS, CONTACTS };
    /* (a): a against the contact forces at the step's end */
    if (x[MEAN] > 0 && x[ACC] > GB_WARN_ACCURACY * x[MEAN]) {
        if (!w->accuracy_steps++) w->accuracy_first = step;
        if (x[ACC] / x[MEAN] > w->accuracy_worst) w->accuracy_worst = x[ACC] / x[MEAN], w->accuracy_worst_step = step;
    }
    if (sc->n_grains < GB_WARN_JAM_GRAINS) return;
    /* (b): few contacts per load-carrying grain, or a contact count that swings */
    if (x[Z] < GB_WARN_COORDINATION) {
        if (!w->loose_steps++) w->loose_first = step, w->loose_z = x[Z], w->loose_rattlers = (int)x[RATTLERS];
    }
    int n = (int)x[CONTACTS], prev = w->last_contacts;
    if (prev >= 0 && fabs((double)(n - prev)) > GB_WARN_SWING * fmax(n, prev)) {
        if (!w->swing_steps++ || abs(n - prev) > abs(w->swing_to - w->swing_from))
            w->swing_step = step, w->swing_from = prev, w->swing_to = n;
    }
    w->last_contacts = n;
}

static gb_status read_steps(const char *dir, const gb_scene *sc, gb_run_verdict *v, watch *w, gb_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/steps.csv", dir);
    gb_csv c;
    gb_status st = gb_csv_open(path, &c, err);
    if (st) return st;
    static const char *const err_cols[] = {"relative_residual", "relative_wall_residual", "host_balance"};
    static const char *const watch_cols[] = {"accuracy", "mean_normal_force", "coordination", "rattlers", "contacts"};
    int k_iter = gb_csv_column(&c, "iterations"), k_sweeps = gb_csv_column(&c, "sweeps"),
        k_secs = gb_csv_column(&c, "seconds"), k_stop = gb_csv_column(&c, "stop");
    int k_step = gb_csv_column(&c, "step"), k_err[3], k_watch[5];
    int k_coulomb = gb_csv_column(&c, "coulomb_excess"), k_acc = gb_csv_column(&c, "accuracy");
    int k_scale = gb_csv_column(&c, "force_scale");
    for (int q = 0; q < 3; q++) k_err[q] = gb_csv_column(&c, err_cols[q]);
    for (int q = 0; q < 5; q++) k_watch[q] = gb_csv_column(&c, watch_cols[q]);
    int has = 1;
    while (!(st = gb_csv_next(&c, &has, err)) && has) {
        int step = (int)value(&c, k_step);
        if (!(step >= 1)) continue;
        v->steps++;
        for (int q = 0; q < 3; q++) {
            double r = value(&c, k_err[q]);
            if (r > v->residual || (isnan(v->residual) && !isnan(r))) {
                v->residual = r, v->residual_step = step;
                v->residual_allowed = value(&c, k_acc) / value(&c, k_scale);
            }
        }
        double ce = value(&c, k_coulomb);
        if (ce > v->coulomb || (isnan(v->coulomb) && !isnan(ce))) v->coulomb = ce, v->coulomb_step = step;
        double x[5];
        for (int q = 0; q < 5; q++) x[q] = value(&c, k_watch[q]);
        look_at_step(sc, w, step, x);
        double secs = value(&c, k_secs);
        if (isfinite(secs)) {
            if (secs > w->long_seconds)
                w->long_seconds = secs, w->long_step = step,
                w->long_work = value(&c, k_iter) + (k_sweeps >= 0 ? value(&c, k_sweeps) : 0);
            add_secs(w, secs);
        }
        if (k_stop >= 0 && k_stop < c.n_fields && !strcmp(c.field[k_stop], "stalled")) w->stalled_steps++;
    }
    gb_csv_close(&c);
    return st;
}

/* (c): localisation.csv's ratios written as undefined (nan) at converged steps */
static void read_undefined(const char *dir, gb_run_verdict *v)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/localisation.csv", dir);
    gb_csv c;
    gb_error e = {0};
    if (gb_csv_open(path, &c, &e)) return;
    static const char *const cols[] = {"localisation_index", "max_concentration"};
    static const char *const why[] = {
        "the zone's shear increment is within the noise of the positions (a / kn over a diameter): nothing "
        "sheared the packing in the step; read mean_gamma instead, or load the packing",
        "the reference stress s_ref is within the noise of the host's stresses (the accuracy over a cavity "
        "element's length): nothing loads the host yet; read the hoop stress itself (fields/host_wall_*), or "
        "load the host before its concentration is read"};
    int k_step = gb_csv_column(&c, "step"), k_tri = gb_csv_column(&c, "triangles"), k[2], count[2] = {0, 0},
        first[2] = {0, 0}, has = 1;
    for (int q = 0; q < 2; q++) k[q] = gb_csv_column(&c, cols[q]);
    while (!gb_csv_next(&c, &has, &e) && has) {
        int step = (int)value(&c, k_step);
        /* a zone without triangles has no index at all: not a noise */
        for (int q = 0; q < 2; q++)
            if (step >= 1 && k[q] >= 0 && isnan(value(&c, k[q])) && (q || value(&c, k_tri) > 0) && !count[q]++)
                first[q] = step;
    }
    gb_csv_close(&c);
    for (int q = 0; q < 2; q++)
        if (count[q])
            warn(v, "localisation.csv: %s is undefined (nan) at %d step(s), the first step %d: %s", cols[q], count[q],
                 first[q], why[q]);
}

/* The host's cavity at the end: the largest principal strain (in magnitude) of the affine map that
 * fits its elements' displacements best (least squares over host_boundary.csv's midpoints: the
 * cavity's mean strain, its dilation and ovalisation; the hoop strain of a cylinder), against
 * GB_WARN_HOST_STRAIN. The dents under single contacts do not enter: they strain the material
 * locally under a nearly point load, not the body's shape. */
static void host_strain(const char *dir, const gb_scene *sc, gb_run_verdict *v)
{
    if (!sc->host.present || sc->host.rigid || sc->host.follow_every) return; /* a followed host is not linear */
    char path[1200];
    snprintf(path, sizeof path, "%s/host_boundary.csv", dir);
    gb_csv c;
    gb_error e = {0};
    if (gb_csv_open(path, &c, &e)) return;
    static const char *const names[4] = {"x", "y", "ux", "uy"};
    int k[4], k_g = gb_csv_column(&c, "group"), has = 1, n = 0, ok = k_g >= 0;
    for (int q = 0; q < 4; q++) ok &= (k[q] = gb_csv_column(&c, names[q])) >= 0;
    /* sums of 1, x, u, x x^t and u x^t, centred at the end */
    double s1 = 0, sx[2] = {0, 0}, su[2] = {0, 0}, sxx[3] = {0, 0, 0}, sux[4] = {0, 0, 0, 0};
    while (ok && !gb_csv_next(&c, &has, &e) && has) {
        if (strcmp(c.field[k_g], sc->host.cavity)) continue;
        double x = value(&c, k[0]), y = value(&c, k[1]), ux = value(&c, k[2]), uy = value(&c, k[3]);
        s1++, sx[0] += x, sx[1] += y, su[0] += ux, su[1] += uy;
        sxx[0] += x * x, sxx[1] += x * y, sxx[2] += y * y;
        sux[0] += ux * x, sux[1] += ux * y, sux[2] += uy * x, sux[3] += uy * y;
        n++;
    }
    gb_csv_close(&c);
    if (n < 3) return;
    double cxx = sxx[0] - sx[0] * sx[0] / s1, cxy = sxx[1] - sx[0] * sx[1] / s1, cyy = sxx[2] - sx[1] * sx[1] / s1;
    double m[4] = {sux[0] - su[0] * sx[0] / s1, sux[1] - su[0] * sx[1] / s1, sux[2] - su[1] * sx[0] / s1,
                   sux[3] - su[1] * sx[1] / s1};
    double det = cxx * cyy - cxy * cxy;
    if (!(det > 0)) return;
    /* A = M C^-1, row by row; its symmetric part's principal values */
    double a11 = (m[0] * cyy - m[1] * cxy) / det, a12 = (m[1] * cxx - m[0] * cxy) / det;
    double a21 = (m[2] * cyy - m[3] * cxy) / det, a22 = (m[3] * cxx - m[2] * cxy) / det;
    double mid = 0.5 * (a11 + a22), rad = hypot(0.5 * (a11 - a22), 0.5 * (a12 + a21));
    double worst = fmax(fabs(mid + rad), fabs(mid - rad));
    if (worst > GB_WARN_HOST_STRAIN)
        warn(v, "the host's cavity is strained by %.3g %% at the end (the largest principal strain of the affine "
                "map that fits its displacements in host_boundary.csv), more than the %g %% to which the host, "
                "linear on its geometry at rest, describes the body: its displacements and stresses, and the "
                "grains' confinement, are those of a body that did not change shape; load it less, or let the host "
                "follow its boundary (host.updated_lagrangian)",
             100 * worst, 100 * GB_WARN_HOST_STRAIN);
}

gb_status gb_run_verdict_read(const char *dir, const gb_scene *sc, gb_run_verdict *v, gb_error *err)
{
    memset(v, 0, sizeof *v);
    v->residual = v->coulomb = NAN;
    watch w;
    memset(&w, 0, sizeof w);
    w.last_contacts = -1;
    /* the scene's, said at the start, joined by "; also " (src/scene/admit.c): one item each */
    for (const char *w0 = sc->warning; *w0;) {
        const char *end = strstr(w0, "; also ");
        int len = end ? (int)(end - w0) : (int)strlen(w0);
        warn(v, "%.*s", len, w0);
        w0 += len + (end ? strlen("; also ") : 0);
    }
    gb_status st = read_steps(dir, sc, v, &w, err);
    if (st) {
        free(w.secs);
        return st;
    }
    if (w.accuracy_steps)
        warn(v, "the accuracy is not small against the contact forces: at %d of %d steps (the first step %d) a is "
                "more than %g of the mean normal contact force, up to %.3g of it at step %d, so the contact forces and "
                "every stress and measure made of them are known to that share at best; give a smaller "
                "solver.accuracy, e.g. {relative: 1e-4}",
             w.accuracy_steps, v->steps, w.accuracy_first, GB_WARN_ACCURACY, w.accuracy_worst, w.accuracy_worst_step);
    if (w.loose_steps)
        warn(v, "the packing is not jammed: at %d of %d steps (the first step %d: %.3g contacts per load-carrying "
                "grain, %d rattlers of %d grains) its grains have fewer than %g contacts on average, which a frictional "
                "packing needs to carry a load; its forces and measures are those of a loose assembly: pack it denser "
                "(gb_packgen, or a preparation stage under stress) before loading it",
             w.loose_steps, v->steps, w.loose_first, w.loose_z, w.loose_rattlers, sc->n_grains, GB_WARN_COORDINATION);
    if (w.swing_steps)
        warn(v, "the contact count swings from step to step: it changes by more than %g %% at %d step(s), from %d to %d "
                "at step %d; the packing rearranges within single steps, so each step's state is one of many: take "
                "smaller load steps (more steps per stage) or a jammed packing",
             100 * GB_WARN_SWING, w.swing_steps, w.swing_from, w.swing_to, w.swing_step);
    long_steps(v, &w);
    if (w.stalled_steps)
        warn(v, "%d step(s) stalled (their largest fixing force stopped falling) and converged only in sub-steps "
                "(steps.csv's stop): the packing rearranged there; smaller load steps share the rearrangement out",
             w.stalled_steps);
    free(w.secs);
    read_undefined(dir, v);
    host_strain(dir, sc, v);
    return GB_OK;
}

void gb_run_verdict_write(FILE *f, const gb_run_verdict *v)
{
    fprintf(f, "verdict:   # from steps.csv: every converged step's error, over its force scale\n");
    fprintf(f, "  steps: %d   # converged load steps\n", v->steps);
    if (v->steps && !isnan(v->residual))
        fprintf(f, "  largest_relative_residual: %.3e   # at step %d: the largest fixing force of a grain, a "
                   "boundary particle or the walls over the step's force scale; the accuracy allowed %.3e there\n",
                v->residual, v->residual_step, v->residual_allowed);
    if (v->steps && !isnan(v->coulomb))
        fprintf(f, "  largest_coulomb_excess: %.3e   # at step %d: max |pt| - (pn tan phi + c), at most 0\n",
                v->coulomb, v->coulomb_step);
    if (!v->n_warnings) fprintf(f, "warnings: []\n");
    else fprintf(f, "warnings:\n");
    for (int k = 0; k < v->n_warnings; k++) {
        fprintf(f, "  - \"");
        for (const char *c = v->warning[k]; *c; c++) fputc(*c == '"' ? '\'' : *c, f);
        fprintf(f, "\"\n");
    }
}
