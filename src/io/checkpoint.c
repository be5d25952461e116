/* checkpoint.txt: a text file of hex floats (%a reads back bit for bit), in a fixed order, ending
 * with "end" and the FNV-1a 64 of everything before it, so that a damaged file is refused. */
#define _POSIX_C_SOURCE 200809L
#include "io/checkpoint.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/number.h"
#include "io/file_util.h"
#include "solver/solver.h"

/* 2: the load step in progress (a checkpoint within a step) and its states; 1 (before): between
 * steps only, not read. */
/* 3: each pair's rolling moment; 4: the line search's smoother-first state; 5: grains in the
 * simulation's order by cell (gb_sim.grain_order); 6: the stall window; 7: a host's rebases
 * ("followed"; 6 is 7 with a host at rest, and is read) */
enum { FORMAT = 7, FORMAT_READ_FROM = 6 };

static uint64_t fnv(uint64_t h, const void *data, size_t n)
{
    const unsigned char *b = data;
    for (size_t k = 0; k < n; k++) h = (h ^ b[k]) * 0x100000001b3ULL;
    return h;
}
#define FNV0 0xcbf29ce484222325ULL

gb_status gb_checkpoint_scene_hash(const gb_sim *sim, uint64_t *hash, gb_error *err)
{
    const gb_scene *sc = sim->scene;
    FILE *f = fopen(sc->path, "rb");
    if (!f) return gb_fail(err, GB_EINPUT, "%s: %s", sc->path, strerror(errno));
    uint64_t h = FNV0;
    char buf[65536];
    size_t k;
    while ((k = fread(buf, 1, sizeof buf, f)) > 0) h = fnv(h, buf, k);
    int bad = ferror(f);
    fclose(f);
    if (bad) return gb_fail(err, GB_EINPUT, "%s: read failed", sc->path);
    /* What the run starts from, as the simulation holds it (files the scene names included); not
     * the host's condensed stiffness, whose last digits may follow the BLAS's threads. */
    h = fnv(h, &sim->state.n, sizeof sim->state.n);
    for (int i = 0; i < sim->state.n; i++) h = fnv(h, &sim->state.g[i], sizeof sim->state.g[i]);
    for (int q = 0; q < sim->state.pairs.n; q++) {
        const gb_pair *p = &sim->state.pairs.p[q];
        double v[4] = {p->d, p->pn, p->pt, p->mr};
        h = fnv(h, &p->i, sizeof p->i), h = fnv(h, &p->j, sizeof p->j), h = fnv(h, v, sizeof v);
    }
    double box[4] = {sim->state.box.left, sim->state.box.right, sim->state.box.bottom, sim->state.box.top};
    h = fnv(h, box, sizeof box);
    const gb_solver_damping *d = gb_solver_damping_of(sim);
    h = fnv(h, &d->mu, sizeof d->mu), h = fnv(h, d->history, sizeof d->history);
    if (sim->host) {
        const gb_host *hw = sim->host;
        h = fnv(h, &hw->mesh.n, sizeof hw->mesh.n);
        h = fnv(h, hw->mesh.mid, 2 * (size_t)hw->mesh.n * sizeof(double));
        h = fnv(h, hw->mesh.length, (size_t)hw->mesh.n * sizeof(double));
        h = fnv(h, hw->mesh.group, (size_t)hw->mesh.n * sizeof(int));
        const gb_host_vars *v = &sim->state.host;
        h = fnv(h, v->u, (size_t)hw->m * sizeof(double));
        for (int g = 0; g < GB_BEM_MAX_GROUPS; g++) h = fnv(h, v->bc[g], sizeof v->bc[g]);
        h = fnv(h, v->remote, sizeof v->remote);
    }
    *hash = h;
    return GB_OK;
}

/* ---- writing ---- */

/* The decimal digits of k >= 0. */
static char *put_digits(char *p, unsigned long k)
{
    char d[24];
    int n = 0;
    do d[n++] = (char)('0' + k % 10);
    while (k /= 10);
    while (n) *p++ = d[--n];
    return p;
}

static char *put_int(char *p, int i)
{
    if (i < 0) *p++ = '-';
    return put_digits(p, i < 0 ? (unsigned long)-(long)i : (unsigned long)i);
}

/* A finite double as a C99 hex float of all its 52 fraction bits ("0x1.<13 digits>p<e>", subnormals
 * "0x0.<13 digits>p-1022"), which strtod reads back bit for bit as it does %a's; anything else by %a.
 * The rows of grains and pairs are most of a checkpoint, and glibc's %a was most of its cost (about
 * a tenth of a 1e4 oedometric path with a checkpoint at every step). */
static char *put_hex(char *p, double v)
{
    if (!isfinite(v)) return p + sprintf(p, "%a", v);
    static const char digit[] = "0123456789abcdef";
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    int e = (int)((b >> 52) & 0x7ff);
    uint64_t m = b & ((UINT64_C(1) << 52) - 1);
    if (b >> 63) *p++ = '-';
    *p++ = '0', *p++ = 'x', *p++ = e ? '1' : '0';
    if (m) {
        *p++ = '.';
        for (int s = 48; s >= 0; s -= 4) *p++ = digit[(m >> s) & 15];
    }
    int x = e ? e - 1023 : m ? -1022 : 0;
    *p++ = 'p', *p++ = x < 0 ? '-' : '+';
    return put_digits(p, (unsigned long)(x < 0 ? -x : x));
}

/* A row: the ints lead[0..nl), the doubles v[0..nv) (put_hex), the ints tail[0..nt). */
static void put_row(FILE *f, const int *lead, int nl, const double *v, int nv, const int *tail, int nt)
{
    char line[64 * 16], *p = line; /* at most 25 characters a number, rows of at most 10 */
    for (int k = 0; k < nl; k++) p = put_int(p, lead[k]), *p++ = ' ';
    for (int k = 0; k < nv; k++) p = put_hex(p, v[k]), *p++ = ' ';
    for (int k = 0; k < nt; k++) p = put_int(p, tail[k]), *p++ = ' ';
    p[-1] = '\n';
    fwrite(line, 1, (size_t)(p - line), f);
}

static void put(FILE *f, const char *label, const double *v, int n)
{
    fputs(label, f);
    for (int k = 0; k < n; k++) fprintf(f, " %a", v[k]);
    fputc('\n', f);
}

/* A state of the simulation (gb_state, src/gem/sim.h) as a block: the current one, the step's start
 * and the sub-step's start are all written by this; un: the global solver's unloading flags of its
 * pairs, or NULL. */
static void put_state(FILE *f, const char *name, const gb_sim *sim, const gb_state *st, const unsigned char *un)
{
    int np = sim->bp.n, hm = sim->host ? sim->host->m : 0;
    fprintf(f, "state %s %d %ld %ld %d\n", name, st->pairs.n, st->pairs.generation, st->pairs.rebuilds,
            st->acc.half_pending);
    double box[4] = {st->box.left, st->box.right, st->box.bottom, st->box.top};
    double box0[4] = {st->pairs.box0.left, st->pairs.box0.right, st->pairs.box0.bottom, st->pairs.box0.top};
    put(f, "box", box, 4);
    put(f, "box0", box0, 4);
    put(f, "wall_force", st->wall_force, GB_N_WALLS);
    double e[4] = {st->acc.work_walls_iter, st->acc.dissipation, st->acc.dissipation_step, st->acc.relaxation};
    put(f, "energies", e, 4);
    if (hm) {
        double v[2 * GB_BEM_MAX_GROUPS + 3];
        for (int g = 0; g < GB_BEM_MAX_GROUPS; g++) v[2 * g] = st->host.bc[g][0], v[2 * g + 1] = st->host.bc[g][1];
        memcpy(&v[2 * GB_BEM_MAX_GROUPS], st->host.remote, 3 * sizeof(double));
        put(f, "host_values", v, 2 * GB_BEM_MAX_GROUPS + 3);
    }
    fprintf(f, "grains\n");
    for (int i = 0; i < sim->state.n; i++) {
        const gb_grain *g = &st->g[i];
        const double v[6] = {g->x, g->y, g->r, g->rot, st->pairs.x0[2 * i], st->pairs.x0[2 * i + 1]};
        put_row(f, NULL, 0, v, 6, NULL, 0);
    }
    fprintf(f, "pairs %d\n", un != NULL);
    for (int q = 0; q < st->pairs.n; q++) {
        const gb_pair *p = &st->pairs.p[q];
        const int ij[2] = {p->i, p->j}, u = un ? un[q] : 0;
        const double v[7] = {p->nx, p->ny, p->d, p->pn, p->pt, p->mr, p->diss};
        put_row(f, ij, 2, v, 7, &u, 1);
    }
    fprintf(f, "particles\n");
    for (int e2 = 0; e2 < np; e2++)
        fprintf(f, "%a %a %a %a\n", st->bp_x[e2], st->bp_y[e2], st->pairs.px0[2 * e2],
                st->pairs.px0[2 * e2 + 1]);
    fprintf(f, "host\n");
    for (int k = 0; k < hm; k++) fprintf(f, "%a %a\n", st->host.u[k], st->host.f0[k]);
}

/* The load step in progress (p->cur), for a checkpoint within it: its place and cut-back
 * bookkeeping, the solver's work and stall detection so far, the last move (its fixing forces'
 * work is half accounted: half_pending), and the states its failure would go back to. */
static void put_step(FILE *f, const gb_sim *sim, const gb_run_progress *p)
{
    const gb_run_step *c = &p->cur;
    fprintf(f, "step %d %d %d %a %a %a %a %a\n", c->stage, c->stage_step, c->step, c->start[0], c->start[1], c->t,
            c->h, c->finest);
    fprintf(f, "progress %d %d %ld %d %ld %ld %d\n", c->cuts, c->substeps, c->iters, (int)c->phase, c->phase_iters,
            c->relax_iters, c->attempt);
    gb_solver_work w = gb_solver_work_plus(c->work, gb_solver_relaxation_work(sim));
    fprintf(f, "work %ld %ld %ld\n", w.trials, w.factorisations, w.sweeps);
    const gb_solver_damping *d = gb_solver_damping_of(sim);
    fprintf(f, "stall %ld %a %d\n", d->since, d->best, d->newton_failures); /* "inf" before the solver's first move */
    fprintf(f, "window %a %ld %ld %d\n", d->stall_ref, d->stall_at, d->relax_work0, (int)c->cut_by);
    fprintf(f, "moves\n");
    for (int i = 0; i < sim->state.n; i++)
        put_row(f, NULL, 0, &sim->scratch.dX[3 * i], 3, NULL, 0);
    put_state(f, "step_start", sim, &p->saved, NULL);
    if (c->cuts > 0) put_state(f, "substep", sim, &p->substep, NULL);
}

/* A host that followed its boundary: what its rebases left (gb_host_followed), from which a resumed
 * run recomputes G, H and K bit for bit; "followed 0 0" for a host at rest. */
static void put_followed(FILE *f, const gb_host *h)
{
    gb_host_followed r = gb_host_followed_of(h);
    fprintf(f, "followed %d %d\n", r.rebases, r.rebase_step);
    if (!r.rebases) return;
    double v[2 * GB_BEM_MAX_GROUPS + 3];
    for (int g = 0; g < GB_BEM_MAX_GROUPS; g++) v[2 * g] = r.bc[g][0], v[2 * g + 1] = r.bc[g][1];
    memcpy(&v[2 * GB_BEM_MAX_GROUPS], r.remote, 3 * sizeof(double));
    put(f, "followed_values", v, 2 * GB_BEM_MAX_GROUPS + 3);
    put(f, "followed_f0", r.f0, h->m);
    put(f, "followed_resultants", r.resultant, 4 * h->mesh.n_groups);
    fprintf(f, "followed_elements\n");
    for (int e = 0; e < h->mesh.n; e++) {
        const double row[8] = {r.p0[2 * e],    r.p0[2 * e + 1],    r.p1[2 * e],    r.p1[2 * e + 1],
                               r.u_acc[2 * e], r.u_acc[2 * e + 1], r.t_acc[2 * e], r.t_acc[2 * e + 1]};
        put_row(f, NULL, 0, row, 8, NULL, 0);
    }
}

static void write_body(FILE *f, const gb_sim *sim, const gb_run_progress *p, const gb_checkpoint_meta *m)
{
    fprintf(f, "gembem_checkpoint %d\nversion %s\nscene %s\nscene_hash %016" PRIx64 "\nfiles %d\n", FORMAT,
            gb_version(), m->scene_path, m->scene_hash, m->n_files);
    for (int k = 0; k < m->n_files; k++) {
        const gb_checkpoint_file *cf = &m->file[k];
        fprintf(f, "file %s %lld ", cf->name, cf->length);
        for (int b = 0; b < cf->n_tail; b++) fprintf(f, "%02x", cf->tail[b]);
        fprintf(f, "%s\n", cf->n_tail ? "" : "-");
    }
    const gb_run_position *pos = &p->pos;
    fprintf(f, "position %d %d %d %a %a\n", pos->stage, pos->stage_step, pos->step, pos->start[0], pos->start[1]);
    fprintf(f, "counts %d %d %d\n", sim->state.n, sim->bp.n, sim->host ? sim->host->m : 0);
    if (sim->host) put_followed(f, sim->host);
    double ref[2] = {sim->ref_width, sim->ref_height}, acc[3] = {p->work.walls, p->work.body, p->work.energy0};
    put(f, "reference", ref, 2);
    put(f, "accounts", acc, 3);
    const gb_solver_damping *d = gb_solver_damping_of(sim);
    fprintf(f, "counters %ld %d\n", p->iterations_total, d->next);
    put(f, "damping", &d->mu, 1);
    put(f, "damping_history", d->history, GB_SOLVER_HISTORY);
    fprintf(f, "line_search %a %d\n", d->smoother_first, d->newton_due);
    put_state(f, "current", sim, &sim->state, gb_solver_unloading(sim));
    fprintf(f, "within_step %d\n", p->cur.active);
    if (p->cur.active) put_step(f, sim, p);
}

/* The line of the first non-finite number written (%a's "inf", "-inf", "nan", "-nan"), or 0. The
 * reader takes finite numbers only (but the solver's "inf" on the stall line, before its first
 * move), and a checkpoint is written to be read back: one that holds a non-finite value is not
 * written, so that the last one, of a finite state, is what --resume finds. Hex floats, integers
 * and the labels never spell these words; the scene's path and the files' names are skipped. */
static int nonfinite_line(const char *buf, size_t len)
{
    int line = 1;
    for (size_t k = 0; k < len;) {
        size_t end = k;
        while (end < len && buf[end] != '\n') end++;
        int skip = !strncmp(buf + k, "scene ", 6) || !strncmp(buf + k, "file ", 5) || !strncmp(buf + k, "stall ", 6);
        for (size_t w = k; !skip && w < end;) {
            size_t n = 0;
            while (w + n < end && buf[w + n] != ' ') n++;
            const char *q = buf + w + (buf[w] == '-');
            size_t m = n - (buf[w] == '-');
            if (m == 3 && (!strncmp(q, "inf", 3) || !strncmp(q, "nan", 3))) return line;
            w += n + 1;
        }
        k = end + 1, line++;
    }
    return 0;
}

gb_status gb_checkpoint_write(const char *dir, const gb_sim *sim, const gb_run_progress *p, const gb_checkpoint_meta *m,
                              gb_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", dir, GB_CHECKPOINT_NAME);
    /* Written to memory first: the trailer's hash covers the bytes as written. */
    char *buf = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&buf, &len);
    if (!mem) return gb_fail(err, GB_ENOMEM, "out of memory for a checkpoint");
    write_body(mem, sim, p, m);
    gb_status st = GB_OK;
    if (fclose(mem) != 0 || !buf) st = gb_fail(err, GB_ENOMEM, "out of memory for a checkpoint");
    int bad = st ? 0 : nonfinite_line(buf, len);
    if (bad)
        st = gb_fail(err, GB_ENUMERIC, "%s: the state holds a non-finite value (it would be line %d), which no run "
                     "can continue from: not written, the last checkpoint of a finite state is kept", path, bad);
    if (st) {
        free(buf);
        return st;
    }
    gb_atomic_file a;
    st = gb_atomic_open(&a, path, err);
    if (!st) {
        fwrite(buf, 1, len, a.f);
        fprintf(a.f, "end %016" PRIx64 "\n", fnv(FNV0, buf, len));
        st = gb_atomic_commit_durable(&a, err);
    }
    free(buf);
    return st;
}

/* ---- reading ---- */

typedef struct {
    char *p;         /* next unread byte */
    int line;
    const char *path;
    gb_error *err;
    gb_status st;
    char w[2 * GB_CHECKPOINT_TAIL + 8]; /* the last word read */
    int format;
} cursor;

static void fail(cursor *c, const char *what)
{
    if (!c->st) c->st = gb_fail(c->err, GB_EINPUT, "%s:%d: %s", c->path, c->line, what);
}

/* The next space-separated word ("" at the end or after a failure). */
static const char *word(cursor *c)
{
    c->w[0] = '\0';
    if (c->st) return c->w;
    for (; *c->p == ' ' || *c->p == '\n'; c->p++) c->line += *c->p == '\n';
    size_t n = strcspn(c->p, " \n");
    if (n >= sizeof c->w) fail(c, "a word too long");
    else memcpy(c->w, c->p, n), c->w[n] = '\0';
    c->p += n;
    return c->w;
}

static void expect(cursor *c, const char *label)
{
    const char *w = word(c);
    char what[96];
    snprintf(what, sizeof what, "expected '%s'", label);
    if (strcmp(w, label)) fail(c, what);
}

static double num(cursor *c)
{
    double v = 0;
    if (gb_parse_finite(word(c), &v) != GB_NUMBER_OK) fail(c, "expected a finite number");
    return v;
}

static void nums(cursor *c, const char *label, double *v, int n)
{
    expect(c, label);
    for (int k = 0; k < n; k++) v[k] = num(c);
}

static long long integer(cursor *c, long long lo, long long hi)
{
    const char *w = word(c);
    char *end;
    errno = 0;
    long long v = strtoll(w, &end, 10);
    if (end == w || *end || errno || v < lo || v > hi) fail(c, "expected an integer in range");
    return v;
}

/* The rest of the line, without its newline. */
static char *rest_of_line(cursor *c)
{
    while (*c->p == ' ') c->p++;
    char *s = c->p, *nl = strchr(s, '\n');
    if (!nl) {
        fail(c, "unexpected end");
        return c->p;
    }
    *nl = '\0';
    c->p = nl + 1, c->line++;
    return s;
}

static int hexval(char ch) { return ch >= '0' && ch <= '9' ? ch - '0' : ch >= 'a' && ch <= 'f' ? ch - 'a' + 10 : -1; }

/* Reads dir/checkpoint.txt whole and checks its trailer. */
static gb_status load(const char *dir, char *path, size_t cap, char **text, gb_error *err)
{
    snprintf(path, cap, "%s/%s", dir, GB_CHECKPOINT_NAME);
    *text = NULL;
    FILE *f = fopen(path, "rb");
    if (!f) return gb_fail(err, GB_EINPUT, "%s: %s", path, strerror(errno));
    char *buf = NULL;
    size_t len = 0, k;
    char chunk[65536];
    gb_status st = GB_OK;
    while (!st && (k = fread(chunk, 1, sizeof chunk, f)) > 0) {
        char *b = realloc(buf, len + k + 1);
        if (!b) st = gb_fail(err, GB_ENOMEM, "out of memory for %s", path);
        else memcpy(b + len, chunk, k), buf = b, len += k;
    }
    if (!st && ferror(f)) st = gb_fail(err, GB_EIO, "%s: read failed", path);
    fclose(f);
    if (!st && !buf) st = gb_fail(err, GB_EINPUT, "%s: empty", path);
    if (st) {
        free(buf);
        return st;
    }
    buf[len] = '\0';
    /* "end <16 hex digits>\n" */
    size_t t = len >= 21 ? len - 21 : 0;
    uint64_t want = 0;
    int ok = len >= 21 && (t == 0 || buf[t - 1] == '\n') && !strncmp(buf + t, "end ", 4) && buf[len - 1] == '\n';
    for (int d = 0; ok && d < 16; d++) {
        int v = hexval(buf[t + 4 + d]);
        ok = v >= 0;
        want = want << 4 | (uint64_t)(v < 0 ? 0 : v);
    }
    if (!ok || fnv(FNV0, buf, t) != want || strncmp(buf, "gembem_checkpoint ", 18)) {
        free(buf);
        return gb_fail(err, GB_EINPUT, "%s: not a complete gembem checkpoint (damaged or cut short)", path);
    }
    buf[t] = '\0';
    *text = buf;
    return GB_OK;
}

static void read_meta(cursor *c, gb_checkpoint_meta *m)
{
    expect(c, "gembem_checkpoint");
    long long format = integer(c, 0, 1000);
    c->format = (int)format;
    if (!c->st && (format < FORMAT_READ_FROM || format > FORMAT)) {
        char what[160];
        snprintf(what, sizeof what, "a checkpoint of format %lld, this gembem reads formats %d to %d; resume it "
                 "with the gembem that wrote it", format, FORMAT_READ_FROM, FORMAT);
        fail(c, what);
    }
    expect(c, "version");
    word(c);
    expect(c, "scene");
    snprintf(m->scene_path, sizeof m->scene_path, "%s", rest_of_line(c));
    expect(c, "scene_hash");
    const char *w = word(c);
    m->scene_hash = 0;
    for (int d = 0; d < 16; d++) {
        int v = strlen(w) == 16 ? hexval(w[d]) : -1;
        if (v < 0) fail(c, "expected 16 hexadecimal digits");
        m->scene_hash = m->scene_hash << 4 | (uint64_t)(v < 0 ? 0 : v);
    }
    expect(c, "files");
    m->n_files = (int)integer(c, 0, GB_CHECKPOINT_MAX_FILES);
    for (int k = 0; k < m->n_files && !c->st; k++) {
        gb_checkpoint_file *f = &m->file[k];
        expect(c, "file");
        w = word(c);
        if (strlen(w) >= sizeof f->name || strstr(w, "..")) fail(c, "expected a file of the run directory");
        snprintf(f->name, sizeof f->name, "%s", w);
        f->length = integer(c, -1, (long long)1 << 60);
        w = word(c);
        size_t n = strcmp(w, "-") ? strlen(w) / 2 : 0;
        if (n > GB_CHECKPOINT_TAIL || (long long)n > (f->length < 0 ? 0 : f->length) || (n == 0 && strcmp(w, "-")))
            fail(c, "expected the file's last bytes in hexadecimal");
        for (size_t b = 0; b < n && !c->st; b++) {
            int hi = hexval(w[2 * b]), lo = hexval(w[2 * b + 1]);
            if (hi < 0 || lo < 0) fail(c, "expected the file's last bytes in hexadecimal");
            f->tail[b] = (unsigned char)(16 * hi + lo);
        }
        f->n_tail = (int)n;
    }
}

gb_status gb_checkpoint_read_meta(const char *dir, gb_checkpoint_meta *m, gb_error *err)
{
    char path[1200], *text;
    gb_status st = load(dir, path, sizeof path, &text, err);
    if (st) return st;
    cursor c = {text, 1, path, err, GB_OK, "", 0};
    read_meta(&c, m);
    free(text);
    return c.st;
}

/* What a checkpoint holds beyond its header, read whole before any of it goes into the simulation. */
typedef struct {
    gb_run_progress p;     /* the run's place, work and counters; within a step, the step and the states
                              its failure would go back to (saved, substep) */
    double ref[2];
    gb_solver_damping damping; /* since and best: within a step only */
    gb_state now;          /* the current state */
    unsigned char *unloading;  /* the global solver's flags of its pairs, or NULL */
    /* a checkpoint within a step: the solver's work in it, the last move */
    gb_solver_work work;
    double *dX;
    long gen[3];               /* the lists' generations as written: now, start, sub */
    gb_host_followed followed; /* its arrays allocated here */
} extras;

static void *alloc(cursor *c, size_t n, size_t size)
{
    void *p = c->st ? NULL : malloc((n > 0 ? n : 1) * size);
    if (!p && !c->st) c->st = gb_fail(c->err, GB_ENOMEM, "out of memory for a checkpoint");
    return p;
}

/* A state block (put_state) into st (gb_state_alloc); *gen: its list's
 * generation as written; un (may be NULL): the unloading flags, allocated if the block has them. */
static void get_state(cursor *c, const gb_sim *sim, const char *name, gb_state *st, long *gen, unsigned char **un)
{
    int n = sim->state.n, np = sim->bp.n, hm = sim->host ? sim->host->m : 0;
    expect(c, "state");
    expect(c, name);
    int n_pairs = (int)integer(c, 0, 1 << 30);
    *gen = (long)integer(c, 0, (long long)1 << 62);
    long rebuilds = (long)integer(c, 0, (long long)1 << 62);
    int half_pending = (int)integer(c, 0, 1);
    if (c->st || (c->st = gb_state_alloc(st, n, np, hm, n_pairs, c->err))) return;
    st->pairs.n = n_pairs, st->pairs.rebuilds = rebuilds, st->acc.half_pending = half_pending;
    double box[4], box0[4], e[4];
    nums(c, "box", box, 4);
    nums(c, "box0", box0, 4);
    gb_box b = {box[0], box[1], box[2], box[3]}, b0 = {box0[0], box0[1], box0[2], box0[3]};
    st->box = b, st->pairs.box0 = b0;
    nums(c, "wall_force", st->wall_force, GB_N_WALLS);
    nums(c, "energies", e, 4);
    st->acc.work_walls_iter = e[0], st->acc.dissipation = e[1], st->acc.dissipation_step = e[2], st->acc.relaxation = e[3];
    if (hm) {
        double v[2 * GB_BEM_MAX_GROUPS + 3];
        nums(c, "host_values", v, 2 * GB_BEM_MAX_GROUPS + 3);
        for (int g = 0; g < GB_BEM_MAX_GROUPS; g++) st->host.bc[g][0] = v[2 * g], st->host.bc[g][1] = v[2 * g + 1];
        memcpy(st->host.remote, &v[2 * GB_BEM_MAX_GROUPS], sizeof st->host.remote);
    }
    expect(c, "grains");
    for (int i = 0; i < n && !c->st; i++) {
        gb_grain *g = &st->g[i];
        g->x = num(c), g->y = num(c), g->r = num(c), g->rot = num(c);
        st->pairs.x0[2 * i] = num(c), st->pairs.x0[2 * i + 1] = num(c);
        if (g->r != sim->state.g[i].r) fail(c, "a grain's radius differs from the scene's");
    }
    expect(c, "pairs");
    if (integer(c, 0, 1) && un) *un = alloc(c, (size_t)n_pairs, 1);
    for (int q = 0; q < n_pairs && !c->st; q++) {
        gb_pair *p = &st->pairs.p[q];
        p->i = (int)integer(c, 0, n - 1);
        p->j = (int)integer(c, np > 0 ? GB_PARTICLE_J(np - 1) : -GB_N_WALLS, n - 1);
        p->nx = num(c), p->ny = num(c), p->d = num(c), p->pn = num(c), p->pt = num(c), p->mr = num(c);
        p->diss = num(c);
        unsigned char flag = (unsigned char)integer(c, 0, 1);
        if (un && *un) (*un)[q] = flag;
    }
    expect(c, "particles");
    for (int k = 0; k < np && !c->st; k++)
        st->bp_x[k] = num(c), st->bp_y[k] = num(c), st->pairs.px0[2 * k] = num(c), st->pairs.px0[2 * k + 1] = num(c);
    expect(c, "host");
    for (int k = 0; k < hm && !c->st; k++) st->host.u[k] = num(c), st->host.f0[k] = num(c);
}

/* The step in progress (put_step); checked against the scene and the last completed step. */
static void get_step(cursor *c, const gb_sim *sim, extras *x)
{
    const gb_scene *sc = sim->scene;
    gb_run_step *s = &x->p.cur;
    s->active = 1;
    expect(c, "step");
    s->stage = (int)integer(c, 0, sc->n_stages > 0 ? sc->n_stages - 1 : 0);
    const gb_stage *sg = c->st || !sc->n_stages ? NULL : &sc->stages[s->stage];
    s->stage_step = (int)integer(c, 1, sg ? sg->steps : 1);
    s->step = (int)integer(c, 1, gb_scene_total_steps(sc));
    s->start[0] = num(c), s->start[1] = num(c), s->t = num(c), s->h = num(c), s->finest = num(c);
    if (!c->st && (!sg || s->step != x->p.pos.step + 1 || !(s->t >= 0 && s->t < 1) || !(s->h > 0 && s->t + s->h <= 1)))
        fail(c, "the step in progress does not follow the checkpoint's last step");
    expect(c, "progress");
    s->cuts = (int)integer(c, 0, sc->solver.cutbacks);
    s->substeps = (int)integer(c, 0, 1 << 30);
    s->iters = (long)integer(c, 0, (long long)1 << 62);
    s->phase = (gb_step_phase)integer(c, GB_PHASE_RELAX, sg && sg->kind == GB_STAGE_SHEAR_MEAN ? GB_PHASE_MEAN
                                                                                               : GB_PHASE_RELAX);
    s->phase_iters = (long)integer(c, 0, s->phase == GB_PHASE_MEAN ? sc->solver.max_iterations : 0);
    s->relax_iters = (long)integer(c, 1, sc->solver.max_iterations - s->phase_iters);
    s->attempt = (int)integer(c, 1, 2147483647LL);
    expect(c, "work");
    x->work.trials = (long)integer(c, 0, (long long)1 << 62);
    x->work.factorisations = (long)integer(c, 0, (long long)1 << 62);
    x->work.sweeps = (long)integer(c, 0, (long long)1 << 62);
    expect(c, "stall");
    x->damping.since = (long)integer(c, 0, (long long)1 << 62);
    const char *w = word(c);
    if (!strcmp(w, "inf")) x->damping.best = INFINITY;
    else if (gb_parse_finite(w, &x->damping.best) != GB_NUMBER_OK) fail(c, "expected a number or inf");
    x->damping.newton_failures = (int)integer(c, 0, 2147483647LL);
    expect(c, "window");
    w = word(c);
    if (!strcmp(w, "inf")) x->damping.stall_ref = INFINITY;
    else if (gb_parse_finite(w, &x->damping.stall_ref) != GB_NUMBER_OK) fail(c, "expected a number or inf");
    x->damping.stall_at = (long)integer(c, 0, (long long)1 << 62);
    x->damping.relax_work0 = (long)integer(c, 0, (long long)1 << 62);
    s->cut_by = (gb_solve_stop)integer(c, GB_STOP_CONVERGED, GB_STOP_ERROR);
    expect(c, "moves");
    x->dX = alloc(c, 3 * (size_t)sim->state.n, sizeof(double));
    for (int k = 0; k < 3 * sim->state.n && !c->st; k++) x->dX[k] = num(c);
    get_state(c, sim, "step_start", &x->p.saved, &x->gen[1], NULL);
    if (s->cuts > 0) get_state(c, sim, "substep", &x->p.substep, &x->gen[2], NULL);
}

/* put_followed's block, checked against the host the scene makes. */
static void get_followed(cursor *c, const gb_sim *sim, gb_host_followed *r)
{
    const gb_host *h = sim->host;
    int n = h->mesh.n, no = 4 * h->mesh.n_groups;
    expect(c, "followed");
    r->rebases = (int)integer(c, 0, 2147483647LL);
    r->rebase_step = (int)integer(c, 0, gb_scene_total_steps(sim->scene));
    if (!c->st && r->rebases && !sim->scene->host.follow_every) fail(c, "a followed host, where the scene's is at rest");
    if (c->st || !r->rebases) return;
    double v[2 * GB_BEM_MAX_GROUPS + 3];
    nums(c, "followed_values", v, 2 * GB_BEM_MAX_GROUPS + 3);
    for (int g = 0; g < GB_BEM_MAX_GROUPS; g++) r->bc[g][0] = v[2 * g], r->bc[g][1] = v[2 * g + 1];
    memcpy(r->remote, &v[2 * GB_BEM_MAX_GROUPS], sizeof r->remote);
    r->f0 = alloc(c, (size_t)h->m, sizeof(double));
    r->resultant = alloc(c, (size_t)no, sizeof(double));
    r->p0 = alloc(c, 2 * (size_t)n, sizeof(double)), r->p1 = alloc(c, 2 * (size_t)n, sizeof(double));
    r->u_acc = alloc(c, 2 * (size_t)n, sizeof(double)), r->t_acc = alloc(c, 2 * (size_t)n, sizeof(double));
    if (c->st) return;
    nums(c, "followed_f0", r->f0, h->m);
    nums(c, "followed_resultants", r->resultant, no);
    expect(c, "followed_elements");
    for (int e = 0; e < n && !c->st; e++) {
        r->p0[2 * e] = num(c), r->p0[2 * e + 1] = num(c), r->p1[2 * e] = num(c), r->p1[2 * e + 1] = num(c);
        r->u_acc[2 * e] = num(c), r->u_acc[2 * e + 1] = num(c), r->t_acc[2 * e] = num(c), r->t_acc[2 * e + 1] = num(c);
    }
}

static void followed_free(gb_host_followed *r)
{
    free(r->f0), free(r->resultant), free(r->p0), free(r->p1), free(r->u_acc), free(r->t_acc);
}

static void read_body(cursor *c, const gb_sim *sim, extras *x)
{
    const gb_scene *sc = sim->scene;
    gb_run_position *pos = &x->p.pos;
    expect(c, "position");
    pos->stage = (int)integer(c, 0, sc->n_stages > 0 ? sc->n_stages - 1 : 0);
    int steps = c->st || !sc->n_stages ? 0 : sc->stages[pos->stage].steps;
    pos->stage_step = (int)integer(c, 0, steps);
    pos->step = (int)integer(c, 0, gb_scene_total_steps(sc));
    pos->start[0] = num(c), pos->start[1] = num(c);
    pos->resume = 1;
    expect(c, "counts");
    long long n_grains = integer(c, 0, 1 << 30), n_particles = integer(c, 0, 1 << 30), n_host = integer(c, 0, 1 << 30);
    if (n_grains != sim->state.n || n_particles != sim->bp.n || n_host != (sim->host ? sim->host->m : 0))
        fail(c, "the checkpoint's grains or host differ from the scene's");
    if (sim->host && c->format >= 7) get_followed(c, sim, &x->followed);
    double acc[3];
    nums(c, "reference", x->ref, 2);
    nums(c, "accounts", acc, 3);
    x->p.work.walls = acc[0], x->p.work.body = acc[1], x->p.work.energy0 = acc[2];
    expect(c, "counters");
    x->p.iterations_total = (long)integer(c, 0, (long long)1 << 62);
    x->damping.next = (int)integer(c, 0, 2147483647LL);
    nums(c, "damping", &x->damping.mu, 1);
    nums(c, "damping_history", x->damping.history, GB_SOLVER_HISTORY);
    expect(c, "line_search");
    x->damping.smoother_first = num(c);
    x->damping.newton_due = (int)integer(c, 0, 1);
    if (!c->st && !(x->damping.smoother_first >= 0)) fail(c, "expected a smoother-first stretch of 0 or more");
    get_state(c, sim, "current", &x->now, &x->gen[0], &x->unloading);
    expect(c, "within_step");
    if (integer(c, 0, 1)) get_step(c, sim, x);
    if (!c->st && *word(c)) fail(c, "expected the end of the checkpoint");
}

/* New generations for the pair lists read (src/contact/pairs.h: a list this process did not build),
 * equal where the checkpoint's were: whether a restored list is the one the global solver's pattern
 * was built for decides whether the pattern and its flags are kept. */
static void new_generations(gb_sim *sim, extras *x)
{
    gb_state *st[3] = {&x->now, &x->p.saved, &x->p.substep};
    for (int a = 0; a < 3; a++) {
        if (!st[a]->g) continue; /* not in the checkpoint */
        st[a]->pairs.generation = 0;
        for (int b = 0; b < a; b++)
            if (x->gen[b] == x->gen[a] && st[b]->g) st[a]->pairs.generation = st[b]->pairs.generation;
        if (!st[a]->pairs.generation) st[a]->pairs.generation = ++sim->search.generations;
    }
}

gb_status gb_checkpoint_read(const char *dir, gb_sim *sim, gb_run_progress *p, uint64_t scene_hash,
                             gb_checkpoint_meta *m, gb_error *err)
{
    char path[1200], *text;
    gb_status st = load(dir, path, sizeof path, &text, err);
    if (st) return st;
    cursor c = {text, 1, path, err, GB_OK, "", 0};
    read_meta(&c, m);
    if (!c.st && m->scene_hash != scene_hash)
        c.st = gb_fail(err, GB_EINPUT, "%s: the scene %s (or a file it reads: grains, initial state, host mesh) "
                       "has changed since the run started; a run resumes only with the scene it started with",
                       dir, sim->scene->path);
    extras x;
    memset(&x, 0, sizeof x);
    if (!c.st) read_body(&c, sim, &x);
    /* Everything read: now into the simulation (the pair list grown first to hold every state's
     * list, so that restoring any of them needs no memory). */
    int need = x.now.pairs.n > x.p.saved.pairs.n ? x.now.pairs.n : x.p.saved.pairs.n;
    if (x.p.substep.pairs.n > need) need = x.p.substep.pairs.n;
    if (!c.st && need > sim->state.pairs.cap) {
        gb_pair *grown = realloc(sim->state.pairs.p, (size_t)need * sizeof *grown);
        if (!grown) c.st = gb_fail(err, GB_ENOMEM, "out of memory for %d pairs", need);
        else sim->state.pairs.p = grown, sim->state.pairs.cap = need;
    }
    /* the host where its rebases left it, before any state of it is restored */
    if (!c.st && sim->host) c.st = gb_host_follow_again(sim->host, &x.followed, err);
    if (!c.st) {
        new_generations(sim, &x);
        gb_sim_state_restore(sim, &x.now);
        sim->ref_width = x.ref[0], sim->ref_height = x.ref[1];
        gb_solver_damping *d = gb_solver_damping_of(sim);
        d->mu = x.damping.mu, d->next = x.damping.next;
        d->smoother_first = x.damping.smoother_first, d->newton_due = x.damping.newton_due;
        memcpy(d->history, x.damping.history, sizeof d->history);
        if (x.p.cur.active) {
            memcpy(sim->scratch.dX, x.dX, 3 * (size_t)sim->state.n * sizeof(double));
            x.p.cur.work = x.work; /* the resumed relaxation counts its work from here */
            d->since = x.damping.since, d->best = x.damping.best;
            d->newton_failures = x.damping.newton_failures;
            d->stall_ref = x.damping.stall_ref, d->stall_at = x.damping.stall_at;
            d->relax_work0 = x.damping.relax_work0;
        }
        gb_state_free(&p->saved), gb_state_free(&p->substep);
        *p = x.p; /* the states its own */
        memset(&x.p, 0, sizeof x.p);
        /* for the restored pair list (its count and rebuilds) */
        c.st = gb_solver_resume(sim, x.unloading, err);
    }
    gb_state_free(&x.now), gb_state_free(&x.p.saved), gb_state_free(&x.p.substep);
    free(x.unloading), free(x.dX);
    followed_free(&x.followed);
    free(text);
    return c.st;
}
