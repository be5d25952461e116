/* Benchmark (a command, not a test): assembly and condensation seconds for 100 .. 4000 boundary
 * elements, and the GFLOP/s of the dense LU (dgetrf) against a DGEMM of the same size in the same
 * run. Host: an annulus 1 < r < 2, half the elements on each circle, outer fixed, condensed on
 * the cavity. Prints a markdown table with the machine, the date and the thread count.
 * Usage: bem_bench [max_elements]    (OPENBLAS_NUM_THREADS sets the BLAS threads) */
#define _POSIX_C_SOURCE 200809L
#include <cblas.h>
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <time.h>

#include "gembem/bem.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void annulus(int n, gb_bem_mesh *m)
{
    int h = n / 2, ln[2] = {n - h, h};
    double *xy = malloc(sizeof(double) * 2 * (size_t)n);
    int *g = malloc(sizeof(int) * (size_t)n);
    for (int i = 0; i < ln[0]; i++) {
        double a = 2 * 3.14159265358979323846 * i / ln[0];
        xy[2 * i] = 2 * cos(a), xy[2 * i + 1] = 2 * sin(a), g[i] = 0;
    }
    for (int i = 0; i < h; i++) {
        double a = 2 * 3.14159265358979323846 * i / h;
        xy[2 * (ln[0] + i)] = cos(a), xy[2 * (ln[0] + i) + 1] = sin(a), g[ln[0] + i] = 1;
    }
    const char *names[2] = {"outer", "cavity"};
    gb_error err = {0};
    if (gb_bem_mesh_from_polygons(2, ln, xy, g, 2, names, 0, m, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        exit(1);
    }
    free(xy);
    free(g);
}

/* best of `reps` runs of dgetrf and dgemm on n x n */
static void dense_rates(int n, int reps, double *lu_gf, double *mm_gf, double *lu_s)
{
    size_t nn = (size_t)n * (size_t)n;
    double *A = malloc(sizeof(double) * nn), *B = malloc(sizeof(double) * nn), *C = malloc(sizeof(double) * nn);
    double *W = malloc(sizeof(double) * nn);
    int *ip = malloc(sizeof(int) * (size_t)n);
    unsigned s = 12345;
    for (size_t i = 0; i < nn; i++) {
        s = s * 1103515245u + 12345u;
        A[i] = (double)(s >> 8) / 16777216.0 - 0.5;
        B[i] = A[i];
    }
    for (int i = 0; i < n; i++) A[(size_t)i * (size_t)n + (size_t)i] += n; /* well conditioned */
    double tl = 1e30, tm = 1e30;
    for (int r = 0; r < reps; r++) {
        memcpy(W, A, sizeof(double) * nn);
        double t0 = now();
        LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, W, n, ip);
        tl = fmin(tl, now() - t0);
        t0 = now();
        cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, n, n, n, 1.0, A, n, B, n, 0.0, C, n);
        tm = fmin(tm, now() - t0);
    }
    *lu_gf = 2.0 / 3.0 * (double)n * n * n / tl * 1e-9;
    *mm_gf = 2.0 * (double)n * n * n / tm * 1e-9;
    *lu_s = tl;
    free(A), free(B), free(C), free(W), free(ip);
}

int main(int argc, char **argv)
{
    int nmax = argc > 1 ? atoi(argv[1]) : 4000;
    struct utsname u;
    uname(&u);
    char cpu[256] = "unknown";
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "model name", 10)) {
                char *c = strchr(line, ':');
                if (c) snprintf(cpu, sizeof cpu, "%s", c + 2);
                cpu[strcspn(cpu, "\n")] = '\0';
                break;
            }
        fclose(f);
    }
    time_t t = time(NULL);
    char date[64];
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&t));
    const char *env = getenv("OPENBLAS_NUM_THREADS");
    printf("### Benchmark: %s, %s %s, %s, OPENBLAS_NUM_THREADS=%s (OpenBLAS uses %d threads)\n\n", cpu, u.sysname,
           u.release, date, env ? env : "unset", openblas_get_num_threads());
    printf("| elements | DOFs | assembly s | condensation s | LU s (dgetrf, DOFs) | LU GFLOP/s | DGEMM GFLOP/s | LU / "
           "DGEMM | asymmetry of K |\n");
    printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    int sizes[] = {100, 250, 500, 1000, 2000, 3000, 4000};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0] && sizes[k] <= nmax; k++) {
        int n = sizes[k];
        gb_bem_mesh m;
        gb_bem_system sys;
        gb_bem_stiffness K;
        gb_error err = {0};
        annulus(n, &m);
        gb_bem_material mat = {1.0, 0.3, GB_BEM_PLANE_STRAIN};
        double t0 = now();
        if (gb_bem_assemble(&m, &mat, &sys, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
        double ta = now() - t0;
        gb_bem_problem p;
        memset(&p, 0, sizeof p);
        p.bc[0].kind = GB_BEM_BC_FIXED;
        p.bc[1].kind = GB_BEM_BC_FREE;
        t0 = now();
        if (gb_bem_condense(&m, &sys, &p, 1, NULL, &K, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
        double tc = now() - t0;
        double lu_gf, mm_gf, lu_s;
        dense_rates(2 * n, n <= 1000 ? 3 : 2, &lu_gf, &mm_gf, &lu_s);
        printf("| %d | %d | %.3f | %.3f | %.3f | %.1f | %.1f | %.2f | %.2e |\n", n, 2 * n, ta, tc, lu_s, lu_gf, mm_gf,
               lu_gf / mm_gf, K.asymmetry);
        fflush(stdout);
        gb_bem_stiffness_free(&K);
        gb_bem_system_free(&sys);
        gb_bem_mesh_free(&m);
    }
    return 0;
}
