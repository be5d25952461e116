/* The global system's internals, shared by its assembly (assemble.c) and its solution (global.c);
 * private to src/solver. */
#ifndef GB_GLOBAL_IMPL_H
#define GB_GLOBAL_IMPL_H

#include "solver/global.h"
#include "solver/linear.h"
#include "solver/solver_impl.h"

/* Wall DOFs: x axis (left and right walls inward), y axis (bottom and top inward), and the
 * isotropic strain of constant mean stress control. */
enum { NW = 3, W_X = 0, W_Y = 1, W_MEAN = 2 };

/* The system is a graph of nodes: grains (3 DOFs: x, y, r w), boundary particles (2 DOFs) and the
 * wall DOFs (1 each), in that order. Column block v of the matrix holds, for each node u adjacent
 * to v (itself included, in increasing order), the rows of u's DOFs; every column of v has the
 * same rows. */
struct gb_global {
    const gb_solver_settings *set;
    const gb_linear_backend *linear; /* solver.linear's */
    gb_linear *ls;            /* its state, made at the first move */
    int symmetric;            /* the tangent's symmetric part (else the exact tangent): gb_linear_symmetric */
    int n, np;                /* grains, boundary particles */
    int nodes, ndof;
    long pattern_of;          /* pairs.generation the pattern was built for (-1: none) */
    int *dof0;                /* per node: its first DOF */
    int *adj_start, *adj;     /* per node: adjacent nodes adj[adj_start[v] .. adj_start[v + 1]) */
    int *adj_off;             /* per adjacency entry: row offset of that node within the column */
    int *collen, *colstart;   /* per node: rows per column, first entry of its first column */
    int adj_cap;
    int *pos_ij, *pos_ji, pos_cap; /* per pair: entry of i in j's list, of j in i's list */
    int *wall_in_grain;       /* per grain and wall DOF: entry of the wall in the grain's list, or -1 */
    int *grain_in_wall;       /* per wall DOF and grain: entry of the grain in the wall's list, or -1 */
    unsigned char *touch;     /* per grain: bit 0 pairs with the left/right wall, bit 1 bottom/top */
    int *Ap, *Ai, nnz, cap;
    double *Ax;
    double *rhs, *x;
    unsigned char *held;      /* per DOF: held (identity row) */
    double *S;                /* per grain: its block of K (s00 s01 s02 s11 s12 s22) */
    double *Sp;               /* per particle: its contact block (s00 s01 s11) */
    double *kt;               /* per pair: tangential stiffness used in K (0 for a sliding contact) */
    double *slide;            /* per pair: d pt / d overlap of a sliding contact, +-kn tan phi (exact tangent) */
    unsigned char *stick;     /* per pair: kt in K even if it slides (a single contact in the system, or a
                                 sliding contact that the first solution unloads) */
    unsigned char *unloading; /* per pair: a sliding contact that a solution unloaded: kt in K until one
                                 loads it again (reset with the pattern) */
    int kt_cap;
    unsigned char *resumed;   /* unloading flags from a checkpoint, for the pattern of pairs.generation resumed_of */
    long resumed_of;
    int dumped;               /* the first solution was written (GB_DUMP_FIRST_SOLVE, a test hook) */
    gb_global_stats stats;
};


/* Entry of node u in v's adjacency list (binary search), or -1. */
static inline int entry_of(const gb_global *gl, int v, int u)
{
    int lo = gl->adj_start[v], hi = gl->adj_start[v + 1] - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (gl->adj[mid] == u) return mid;
        if (gl->adj[mid] < u) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

static inline int wall_node(const gb_global *gl, int w) { return gl->n + gl->np + w; }

/* Adds v to the entry (row: DOF a of the node at adjacency entry q of node col; column: DOF b of
 * node col). */
static inline void add(gb_global *gl, int col, int b, int q, int a, double v)
{
    gl->Ax[gl->colstart[col] + b * gl->collen[col] + gl->adj_off[q] + a] += v;
}

/* The length that converts wall DOF w into the inward displacement of wall `wall`. */
double gb_global_wall_lever(const gb_sim *sim, int w, int wall);
/* Per-pair buffers for a pair list of P->cap pairs. */
gb_status gb_global_pair_buffers(gb_global *gl, const gb_pair_set *P, gb_error *err);
/* The tangent of every contact (gl->kt, gl->slide) and the diagonal blocks gl->S, gl->Sp. */
void gb_global_tangents(gb_global *gl, const gb_sim *sim);
/* The matrix into gl->Ax, with the relative diagonal shift `shift`. */
void gb_global_assemble(gb_global *gl, const gb_sim *sim, double shift);

#endif
