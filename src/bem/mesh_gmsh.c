/* Boundary meshes through the gmsh C API: a .geo meshed to 1D with the requested sizes, or a .msh
 * read as it is. The one place where gmsh is initialised and finalised. */
#define _POSIX_C_SOURCE 200809L /* strdup, setenv, fork */
#include <errno.h>
#include <gmshc.h>
#include <locale.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gembem/bem.h"

typedef struct {
    size_t n0, n1; /* node tags */
    int group;
} seg;

typedef struct {
    const char *path;
    int n_groups;
    char names[GB_BEM_MAX_GROUPS][GB_BEM_NAME_MAX];
    int tags[GB_BEM_MAX_GROUPS];
    seg *segs;
    size_t nseg, capseg;
    double *coord; /* by node (read_nodes): 3 per node */
    size_t *tag;   /* by node: its gmsh tag */
    size_t n_nodes;
} extract;

/* gmsh's first error since it started (its logger keeps every message, gmsh_start), into
 * msg[0..size): a .geo's parser recovers and goes on, so its last error is often a consequence
 * of the first, lines later. Empty if there is none. */
static void first_error(char *msg, size_t size)
{
    char **log = NULL;
    size_t n = 0;
    int ierr = 0;
    msg[0] = '\0';
    gmshLoggerGet(&log, &n, &ierr);
    for (size_t k = 0; k < n; k++) {
        if (!msg[0] && !strncmp(log[k], "Error: ", 7)) snprintf(msg, size, "%s", log[k] + 7);
        gmshFree(log[k]);
    }
    if (log) gmshFree(log);
    if (msg[0]) return;
    char *last = NULL; /* a message the logger did not keep */
    gmshLoggerGetLastError(&last, &ierr);
    if (last) snprintf(msg, size, "%s", last), gmshFree(last);
}

static gb_status gmsh_error(const char *path, const char *what, gb_error *err)
{
    char msg[GB_ERROR_MSG_MAX / 2];
    first_error(msg, sizeof msg);
    return gb_fail(err, GB_EINPUT, "%s: gmsh could not %s%s%s", path, what, msg[0] ? ": " : "", msg);
}

/* With General.AbortOnError = 0 gmsh reports parse and meshing errors through its logger only
 * (ierr stays 0), and its parser recovers: with the default (an exception at the first error)
 * the parser keeps the rest of a bad file in its buffer and fails every later file. */
static gb_status gmsh_check(const char *path, const char *what, int ierr, gb_error *err)
{
    char *msg = NULL;
    int e2 = 0;
    gmshLoggerGetLastError(&msg, &e2);
    int bad = ierr || (msg && msg[0]);
    if (msg) gmshFree(msg);
    return bad ? gmsh_error(path, what, err) : GB_OK;
}

static int ends_with(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && !strcmp(s + a - b, suffix);
}

int gb_bem_mesh_file_is_msh(const char *path) { return ends_with(path, ".msh"); }

/* Physical groups of dimension 1, their names and tags. */
static gb_status read_groups(extract *x, gb_error *err)
{
    int *dt = NULL, ierr = 0;
    size_t ndt = 0;
    gmshModelGetPhysicalGroups(&dt, &ndt, 1, &ierr);
    if (ierr) return gmsh_error(x->path, "list the physical groups", err);
    gb_status st = GB_OK;
    if (ndt == 0)
        st = gb_fail(err, GB_EINPUT,
                     "%s: no physical curve groups; name the boundary parts, e.g. Physical Curve(\"outer\") = {...};",
                     x->path);
    if (!st && ndt / 2 > GB_BEM_MAX_GROUPS)
        st = gb_fail(err, GB_EINPUT, "%s: %zu physical curve groups; at most %d", x->path, ndt / 2, GB_BEM_MAX_GROUPS);
    for (size_t i = 0; !st && i < ndt / 2; i++) {
        char *name = NULL;
        x->tags[i] = dt[2 * i + 1];
        gmshModelGetPhysicalName(1, x->tags[i], &name, &ierr);
        if (name && name[0])
            snprintf(x->names[i], GB_BEM_NAME_MAX, "%s", name);
        else
            snprintf(x->names[i], GB_BEM_NAME_MAX, "physical%d", x->tags[i]);
        if (name) gmshFree(name);
        x->n_groups++;
    }
    if (dt) gmshFree(dt);
    return st;
}

static int find_group(const extract *x, const char *name)
{
    for (int g = 0; g < x->n_groups; g++)
        if (!strcmp(x->names[g], name)) return g;
    return -1;
}

/* Curves of group g (gmsh arrays, freed by the caller with gmshFree). */
static gb_status group_curves(extract *x, int g, int **tags, size_t *n, gb_error *err)
{
    int ierr = 0;
    *tags = NULL;
    *n = 0;
    gmshModelGetEntitiesForPhysicalGroup(1, x->tags[g], tags, n, &ierr);
    if (ierr) return gmsh_error(x->path, "list the curves of a physical group", err);
    return GB_OK;
}

static int cmp_size(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return x < y ? -1 : x > y;
}

/* Length of the current 1D mesh of one curve (node tags sorted once, then looked up). */
static double curve_mesh_length(int curve)
{
    size_t *et = NULL, net = 0, *nt = NULL, nnt = 0, *ntag = NULL, nntag = 0;
    double *xyz = NULL, *par = NULL;
    size_t nxyz = 0, npar = 0;
    int ierr = 0;
    double len = 0;
    gmshModelMeshGetElementsByType(1, &et, &net, &nt, &nnt, curve, 0, 1, &ierr);
    gmshModelMeshGetNodes(&ntag, &nntag, &xyz, &nxyz, &par, &npar, 1, curve, 1, 0, &ierr);
    size_t *order = malloc(sizeof(size_t) * 2 * (nntag ? nntag : 1));
    if (order) {
        for (size_t i = 0; i < nntag; i++) order[2 * i] = ntag[i], order[2 * i + 1] = i;
        qsort(order, nntag, 2 * sizeof(size_t), cmp_size);
        for (size_t e = 0; e < nnt / 2; e++) {
            const double *p[2] = {NULL, NULL};
            for (int k = 0; k < 2; k++) {
                size_t key[2] = {nt[2 * e + k], 0};
                size_t *hit = bsearch(key, order, nntag, 2 * sizeof(size_t), cmp_size);
                if (hit) p[k] = xyz + 3 * hit[1];
            }
            if (p[0] && p[1]) len += hypot(p[1][0] - p[0][0], p[1][1] - p[0][1]);
        }
        free(order);
    }
    if (et) gmshFree(et);
    if (nt) gmshFree(nt);
    if (ntag) gmshFree(ntag);
    if (xyz) gmshFree(xyz);
    if (par) gmshFree(par);
    return len;
}

/* Total length of the current 1D mesh of all curves. */
static double mesh_length(void)
{
    int *dt = NULL, ierr = 0;
    size_t ndt = 0;
    double total = 0;
    gmshModelGetEntities(&dt, &ndt, 1, &ierr);
    for (size_t i = 0; i + 1 < ndt; i += 2) total += curve_mesh_length(dt[i + 1]);
    if (dt) gmshFree(dt);
    return total;
}

/* A size that asks for more elements than a count may (GB_BEM_MAX_COUNT) is refused before gmsh
 * meshes with it: a tiny size would mesh for hours and fill the memory. */
static gb_status check_size(const extract *x, const char *what, double length, double size, gb_error *err)
{
    if (!(length / size <= GB_BEM_MAX_COUNT))
        return gb_fail(err, GB_EINPUT, "%s: an element size of %g on %s (length %g) gives %.3g elements; at most %d",
                       x->path, size, what, length, length / size, GB_BEM_MAX_COUNT);
    return GB_OK;
}

/* Sizes and counts: global size through the mesh size options; per-group size or count through
 * transfinite curves, distributing a count over a group's curves by their lengths. Lengths come
 * from a first mesh with the file's own sizes. */
static gb_status mesh_geo(extract *x, const gb_bem_mesh_opts *o, gb_error *err)
{
    int ierr = 0;
    gmshModelMeshGenerate(1, &ierr);
    gb_status st0 = gmsh_check(x->path, "mesh the boundary", ierr, err);
    if (!st0 && o->size > 0 && !(st0 = check_size(x, "the whole boundary", mesh_length(), o->size, err))) {
        gmshOptionSetNumber("Mesh.MeshSizeFromPoints", 0, &ierr);
        gmshOptionSetNumber("Mesh.MeshSizeFromCurvature", 0, &ierr);
        gmshOptionSetNumber("Mesh.MeshSizeExtendFromBoundary", 0, &ierr);
        gmshOptionSetNumber("Mesh.MeshSizeMin", o->size, &ierr);
        gmshOptionSetNumber("Mesh.MeshSizeMax", o->size, &ierr);
        gmshModelMeshClear(NULL, 0, &ierr);
        gmshModelMeshGenerate(1, &ierr);
        st0 = gmsh_check(x->path, "mesh the boundary", ierr, err);
    }
    if (st0 || o->n_group_sizes == 0) return st0;
    for (int i = 0; i < o->n_group_sizes; i++) {
        const gb_bem_group_size *gs = &o->group_sizes[i];
        int g = find_group(x, gs->group);
        if (g < 0) return gb_fail(err, GB_EINPUT, "%s: no physical curve group named '%s'", x->path, gs->group);
        int *curves = NULL;
        size_t nc = 0;
        gb_status st = group_curves(x, g, &curves, &nc, err);
        if (st) return st;
        double total = 0, *len = malloc(sizeof(double) * (nc ? nc : 1));
        if (!len) {
            if (curves) gmshFree(curves);
            return gb_fail(err, GB_ENOMEM, "out of memory");
        }
        for (size_t c = 0; c < nc; c++) total += len[c] = curve_mesh_length(curves[c]);
        char what[GB_BEM_NAME_MAX + 16];
        snprintf(what, sizeof what, "group '%s'", gs->group);
        if (gs->count <= 0) st = check_size(x, what, total, gs->size, err);
        int left = gs->count;
        double left_len = total;
        for (size_t c = 0; c < nc && !st; c++) {
            int ne;
            if (gs->count > 0) { /* largest-remainder share of what is left, at least 1 */
                ne = c + 1 == nc ? left : left_len > 0 ? (int)lround(left * len[c] / left_len) : left / (int)(nc - c);
                if (ne < 1) ne = 1;
                if (c + 1 < nc && left - ne < (int)(nc - c - 1)) ne = left - (int)(nc - c - 1);
                left -= ne;
                left_len -= len[c];
            } else {
                ne = (int)lround(len[c] / gs->size);
            }
            if (ne < 1) ne = 1;
            if (ne < 1 || (gs->count > 0 && gs->count < (int)nc))
                st = gb_fail(err, GB_EINPUT, "%s: group '%s' has %zu curves; it needs at least that many elements",
                             x->path, gs->group, nc);
            else
                gmshModelMeshSetTransfiniteCurve(curves[c], ne + 1, "Progression", 1.0, &ierr);
        }
        free(len);
        if (curves) gmshFree(curves);
        if (st) return st;
    }
    gmshModelMeshClear(NULL, 0, &ierr);
    gmshModelMeshGenerate(1, &ierr);
    return gmsh_check(x->path, "mesh the boundary", ierr, err);
}

static gb_status push_seg(extract *x, size_t a, size_t b, int g, gb_error *err)
{
    if (x->nseg == x->capseg) {
        size_t cap = x->capseg ? 2 * x->capseg : 256;
        seg *s = realloc(x->segs, cap * sizeof *s);
        if (!s) return gb_fail(err, GB_ENOMEM, "out of memory");
        x->segs = s;
        x->capseg = cap;
    }
    x->segs[x->nseg++] = (seg){a, b, g};
    return GB_OK;
}

/* The 2-node line elements of every group's curves; a curve in two groups is refused. */
static gb_status read_segments(extract *x, gb_error *err)
{
    int ierr = 0;
    gb_status st = GB_OK;
    int seen_cap = 64, nseen = 0, *seen = malloc(sizeof(int) * (size_t)seen_cap), *seen_g = malloc(sizeof(int) * 64);
    if (!seen || !seen_g) {
        free(seen);
        free(seen_g);
        return gb_fail(err, GB_ENOMEM, "out of memory");
    }
    for (int g = 0; g < x->n_groups && !st; g++) {
        int *curves = NULL;
        size_t nc = 0;
        if ((st = group_curves(x, g, &curves, &nc, err))) break;
        for (size_t c = 0; c < nc && !st; c++) {
            for (int i = 0; i < nseen; i++)
                if (seen[i] == curves[c]) {
                    st = gb_fail(err, GB_EINPUT, "%s: curve %d is in two physical groups, '%s' and '%s'", x->path,
                                 curves[c], x->names[seen_g[i]], x->names[g]);
                    break;
                }
            if (st) break;
            if (nseen == seen_cap) {
                seen_cap *= 2;
                int *a = realloc(seen, sizeof(int) * (size_t)seen_cap),
                    *b = a ? realloc(seen_g, sizeof(int) * (size_t)seen_cap) : NULL;
                if (a) seen = a;
                if (b) seen_g = b;
                if (!a || !b) {
                    st = gb_fail(err, GB_ENOMEM, "out of memory");
                    break;
                }
            }
            seen[nseen] = curves[c];
            seen_g[nseen++] = g;
            int *types = NULL;
            size_t ntypes = 0;
            gmshModelMeshGetElementTypes(&types, &ntypes, 1, curves[c], &ierr);
            for (size_t k = 0; k < ntypes && !st; k++)
                if (types[k] != 1)
                    st = gb_fail(err, GB_EINPUT,
                                 "%s: curve %d of group '%s' has elements of gmsh type %d (%s); expected 2-node lines: "
                                 "gembem's boundary elements are straight, so it refuses second-order meshes rather "
                                 "than drop their middle nodes (mesh with gmsh -1 -order 1, or Mesh.ElementOrder = 1)",
                                 x->path, curves[c], x->names[g], types[k],
                                 types[k] == 8 ? "3-node second-order lines" : "not lines");
            if (types) gmshFree(types);
            size_t *et = NULL, net = 0, *nt = NULL, nnt = 0;
            gmshModelMeshGetElementsByType(1, &et, &net, &nt, &nnt, curves[c], 0, 1, &ierr);
            if (ierr && !st) st = gmsh_error(x->path, "read the boundary elements", err);
            if (!st && nnt == 0)
                st = gb_fail(err, GB_EINPUT, "%s: curve %d of group '%s' has no elements", x->path, curves[c],
                             x->names[g]);
            for (size_t e = 0; e < nnt / 2 && !st; e++) st = push_seg(x, nt[2 * e], nt[2 * e + 1], g, err);
            if (et) gmshFree(et);
            if (nt) gmshFree(nt);
        }
        if (curves) gmshFree(curves);
    }
    free(seen);
    free(seen_g);
    return st;
}

/* A body in the plane z = 0: a boundary node elsewhere is a 3D mesh (or a tilted one), refused. */
static gb_status check_planar(const extract *x, gb_error *err)
{
    double extent = 0;
    for (size_t k = 0; k < x->n_nodes; k++) extent = fmax(extent, fmax(fabs(x->coord[3 * k]), fabs(x->coord[3 * k + 1])));
    for (size_t k = 0; k < x->n_nodes; k++)
        if (!(fabs(x->coord[3 * k + 2]) <= 1e-9 * extent))
            return gb_fail(err, GB_EINPUT, "%s: node %zu lies at z = %g; expected a 2D body, meshed in the plane z = 0",
                           x->path, x->tag[k], x->coord[3 * k + 2]);
    return GB_OK;
}

/* A mesh of a 3D body: refused before its curves are read as a boundary. */
static gb_status check_dimension(const extract *x, gb_error *err)
{
    int ierr = 0, dim = gmshModelGetDimension(&ierr);
    if (!ierr && dim == 3)
        return gb_fail(err, GB_EINPUT, "%s: a 3D model (volumes); expected a 2D body, its boundary curves grouped by "
                                       "Physical Curve", x->path);
    return GB_OK;
}

/* The nodes, numbered densely in the order of their tags (x->tag[k] is node k's gmsh tag), and the
 * segments renumbered so: a .msh may give any tags (a tag of 2e8 took 5 GB when nodes were
 * indexed by tag, one near 2^64 / 24 overflowed the allocation). */
static gb_status read_nodes(extract *x, gb_error *err)
{
    size_t *tags = NULL, ntags = 0, ncoord = 0, npar = 0;
    double *xyz = NULL, *par = NULL;
    int ierr = 0;
    gmshModelMeshGetNodes(&tags, &ntags, &xyz, &ncoord, &par, &npar, -1, -1, 0, 0, &ierr);
    gb_status st = ierr ? gmsh_error(x->path, "read the mesh nodes", err) : GB_OK;
    size_t *order = NULL;
    if (!st) {
        order = malloc(sizeof(size_t) * 2 * (ntags ? ntags : 1));
        x->coord = malloc(sizeof(double) * 3 * (ntags ? ntags : 1));
        x->tag = malloc(sizeof(size_t) * (ntags ? ntags : 1));
        if (!order || !x->coord || !x->tag) st = gb_fail(err, GB_ENOMEM, "out of memory");
    }
    if (!st) {
        for (size_t i = 0; i < ntags; i++) order[2 * i] = tags[i], order[2 * i + 1] = i;
        qsort(order, ntags, 2 * sizeof(size_t), cmp_size);
        for (size_t k = 0; k < ntags; k++) {
            x->tag[k] = order[2 * k];
            memcpy(x->coord + 3 * k, xyz + 3 * order[2 * k + 1], 3 * sizeof(double));
        }
        x->n_nodes = ntags;
        st = check_planar(x, err);
        for (size_t s = 0; s < x->nseg && !st; s++) {
            size_t *ends[2] = {&x->segs[s].n0, &x->segs[s].n1};
            for (int k = 0; k < 2 && !st; k++) {
                size_t key[2] = {*ends[k], 0};
                size_t *hit = bsearch(key, order, ntags, 2 * sizeof(size_t), cmp_size);
                if (!hit) st = gb_fail(err, GB_EINPUT, "%s: an element refers to an unknown node %zu", x->path, *ends[k]);
                else *ends[k] = (size_t)(hit - order) / 2;
            }
        }
    }
    free(order);
    if (tags) gmshFree(tags);
    if (xyz) gmshFree(xyz);
    if (par) gmshFree(par);
    return st;
}

/* Chains segments into closed loops: every node must join exactly two segments. */
static gb_status chain_loops(extract *x, const gb_bem_mesh_opts *o, gb_bem_mesh *mesh, gb_error *err)
{
    size_t nt = x->n_nodes, n = x->nseg;
    int *deg = calloc(nt, sizeof(int));
    size_t *adj = malloc(sizeof(size_t) * 2 * nt);
    int *used = calloc(n ? n : 1, sizeof(int));
    double *xy = malloc(sizeof(double) * 2 * (n ? n : 1));
    int *grp = malloc(sizeof(int) * (n ? n : 1));
    int *loop_n = malloc(sizeof(int) * (n ? n : 1));
    gb_status st = GB_OK;
    if (!deg || !adj || !used || !xy || !grp || !loop_n) st = gb_fail(err, GB_ENOMEM, "out of memory");
    for (size_t s = 0; s < n && !st; s++) {
        size_t ends[2] = {x->segs[s].n0, x->segs[s].n1};
        for (int k = 0; k < 2 && !st; k++) {
            size_t v = ends[k];
            if (deg[v] < 2) adj[2 * v + (size_t)deg[v]] = s;
            deg[v]++;
        }
    }
    for (size_t s = 0; s < n && !st; s++) {
        size_t ends[2] = {x->segs[s].n0, x->segs[s].n1};
        for (int k = 0; k < 2 && !st; k++) {
            size_t v = ends[k];
            if (deg[v] != 2)
                st = gb_fail(err, GB_EINPUT,
                             "%s: the boundary is %s at node %zu (%.6g, %.6g) of group '%s': every loop must be closed "
                             "and simple",
                             x->path, deg[v] == 1 ? "open" : "branching", x->tag[v], x->coord[3 * v], x->coord[3 * v + 1],
                             x->names[x->segs[s].group]);
        }
    }
    int n_loops = 0;
    size_t nv = 0;
    for (size_t s0 = 0; s0 < n && !st; s0++) {
        if (used[s0]) continue;
        size_t s = s0, v = x->segs[s0].n0;
        int count = 0;
        while (!used[s]) {
            used[s] = 1;
            xy[2 * nv] = x->coord[3 * v];
            xy[2 * nv + 1] = x->coord[3 * v + 1];
            grp[nv++] = x->segs[s].group;
            count++;
            size_t w = x->segs[s].n0 == v ? x->segs[s].n1 : x->segs[s].n0;
            size_t next = adj[2 * w] == s ? adj[2 * w + 1] : adj[2 * w];
            v = w;
            s = next;
        }
        loop_n[n_loops++] = count;
    }
    if (!st && n == 0) st = gb_fail(err, GB_EINPUT, "%s: the physical curve groups hold no elements", x->path);
    if (!st) {
        const char *names[GB_BEM_MAX_GROUPS];
        for (int g = 0; g < x->n_groups; g++) names[g] = x->names[g];
        st = gb_bem_mesh_from_polygons(n_loops, loop_n, xy, grp, x->n_groups, names, o->unbounded, mesh, err);
        if (st && st == GB_EINPUT) {
            char msg[GB_ERROR_MSG_MAX];
            snprintf(msg, sizeof msg, "%s", err->msg);
            gb_fail(err, GB_EINPUT, "%s: %s", x->path, msg);
        }
    }
    free(deg);
    free(adj);
    free(used);
    free(xy);
    free(grp);
    free(loop_n);
    return st;
}

/* gmshInitialize appends the program's directory to PATH and PYTHONPATH at every call: the
 * caller's values are put back (a process that loaded n meshes had them n entries long, and the
 * fuzz targets ran out of memory on the copies; found by fuzz_contacts). */
static char *env_save(const char *name)
{
    const char *v = getenv(name);
    return v ? strdup(v) : NULL;
}

static void env_restore(const char *name, char *saved)
{
    if (saved) setenv(name, saved, 1);
    else unsetenv(name);
    free(saved);
}

/* gmsh started for one file: quiet, and its parse errors reported instead of thrown. */
static void gmsh_start(int *ierr)
{
    gmshInitialize(0, NULL, 0, ierr);
    if (*ierr) return;
    gmshOptionSetNumber("General.Terminal", 0, ierr);
    /* errors only, to the logger (not the terminal), which keeps them all for first_error */
    gmshOptionSetNumber("General.Verbosity", 1, ierr);
    gmshOptionSetNumber("General.AbortOnError", 0, ierr);
    gmshLoggerStart(ierr);
}

/* gmsh 4.8's msh2 reader dereferences a null vertex on some malformed files (a node line with an
 * extra number puts it out of step: fuzz/regress/mesh/gmsh_crash_*.msh) and kills the process.
 * So gmsh first reads a .msh in a child process, which exits without any other work (_exit: no
 * atexit handlers, no stdio buffers flushed twice); a child killed by a signal is a file that
 * gmsh cannot read, refused. A .geo is a program to trust, not data, and is not checked so. */
static gb_status msh_survives_gmsh(const char *path, gb_error *err)
{
    pid_t pid = fork();
    if (pid < 0) return gb_fail(err, GB_EIO, "%s: cannot start a process to check the mesh: %s", path, strerror(errno));
    if (pid == 0) {
        /* the default action, not a sanitizer's or a fuzzer's handler: the parent sees the signal
         * (SIGABRT: gmsh's own assertions, e.g. `p != nullptr' in _readMSH2, found by fuzz_mesh) */
        int fatal[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
        for (size_t k = 0; k < sizeof fatal / sizeof fatal[0]; k++) signal(fatal[k], SIG_DFL);
        int ierr = 0;
        gmsh_start(&ierr);
        if (!ierr) gmshOpen(path, &ierr);
        _exit(0);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return gb_fail(err, GB_EIO, "%s: cannot wait for the mesh check: %s", path, strerror(errno));
    if (WIFSIGNALED(status))
        return gb_fail(err, GB_EINPUT, "%s: gmsh crashed reading it (signal %d, %s): the mesh file is malformed", path,
                       WTERMSIG(status), strsignal(WTERMSIG(status)));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return gb_fail(err, GB_EINPUT, "%s: gmsh failed reading it (exit status %d): the mesh file is malformed", path,
                       WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return GB_OK;
}

gb_status gb_bem_mesh_load(const char *path, const gb_bem_mesh_opts *opts, gb_bem_mesh *mesh, gb_error *err)
{
    memset(mesh, 0, sizeof *mesh);
    gb_bem_mesh_opts dflt = gb_bem_mesh_opts_default();
    const gb_bem_mesh_opts *o = opts ? opts : &dflt;
    int is_geo = ends_with(path, ".geo"), is_msh = gb_bem_mesh_file_is_msh(path);
    if (!is_geo && !is_msh) return gb_fail(err, GB_EINPUT, "%s: expected a gmsh .geo or .msh file", path);
    FILE *f = fopen(path, "rb"); /* gmshOpen on a missing file succeeds with an empty model */
    if (!f) return gb_fail(err, GB_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    fclose(f);
    if (is_msh && (o->size > 0 || o->n_group_sizes > 0))
        return gb_fail(err, GB_EINPUT, "%s: element sizes and counts apply to .geo files, not to a mesh", path);
    if (o->size < 0) return gb_fail(err, GB_EINPUT, "element size must be positive");
    for (int i = 0; i < o->n_group_sizes; i++)
        if (!(o->group_sizes[i].size > 0) && o->group_sizes[i].count <= 0)
            return gb_fail(err, GB_EINPUT, "group '%s': give a positive element size or count",
                           o->group_sizes[i].group);

    gb_status st = is_msh ? msh_survives_gmsh(path, err) : GB_OK;
    if (st) return st;
    extract x;
    memset(&x, 0, sizeof x);
    x.path = path;
    int ierr = 0;
    /* gmshInitialize sets LC_NUMERIC to "C" for the whole process: put the caller's back after */
    char saved_numeric[128] = "C";
    const char *cur = setlocale(LC_NUMERIC, NULL);
    if (cur) snprintf(saved_numeric, sizeof saved_numeric, "%s", cur);
    char *saved_path = env_save("PATH"), *saved_pythonpath = env_save("PYTHONPATH");
    gmsh_start(&ierr);
    env_restore("PATH", saved_path);
    env_restore("PYTHONPATH", saved_pythonpath);
    if (ierr) {
        setlocale(LC_NUMERIC, saved_numeric);
        return gb_fail(err, GB_EINTERNAL, "gmsh could not start");
    }
    gmshOpen(path, &ierr);
    st = gmsh_check(path, "read the file", ierr, err);
    if (!st) st = check_dimension(&x, err);
    if (!st) st = read_groups(&x, err);
    if (!st && is_geo) st = mesh_geo(&x, o, err);
    if (!st) st = read_segments(&x, err);
    if (!st) st = read_nodes(&x, err);
    gmshLoggerStop(&ierr);
    gmshFinalize(&ierr);
    setlocale(LC_NUMERIC, saved_numeric);
    if (!st) st = chain_loops(&x, o, mesh, err);
    free(x.segs);
    free(x.coord);
    free(x.tag);
    return st;
}
