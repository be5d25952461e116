/* The geometric admission of scenes (src/scene/admit.c): the overlaps it counts against a
 * brute-force O(N^2) count, the tolerance on both sides of a refusal, a box and a cavity. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene/admit.h"
#include "scene_fixture.h"

static const double PI = 3.14159265358979323846;

static int admitted(gb_scene *s, const gb_bem_mesh *mesh, const char *needle)
{
    gb_error err = {0};
    memset(&s->overlaps, 0, sizeof s->overlaps);
    gb_status st = gb_scene_admit(s, mesh, &err);
    if (needle && (st != GB_EINPUT || !strstr(err.msg, needle)))
        fprintf(stderr, "expected a refusal with '%s', got status %d '%s'\n", needle, st, err.msg);
    if (!needle && st) fprintf(stderr, "refused: %s\n", err.msg);
    return needle ? st == GB_EINPUT && strstr(err.msg, needle) != NULL : st == GB_OK;
}

/* 1936 discs on a jittered grid of spacing 0.9 in a box of 40 x 40, radii 0.35 to 0.45: the pairs
 * that overlap (about half the neighbours, by up to 0.57 of the smaller radius), counted by the
 * admission through the cell list and here over all pairs; the first column and row cross the
 * left and bottom walls. */
static void random_box(void)
{
    enum { M = 44, N = M * M };
    gb_grain *g = malloc(N * sizeof *g);
    unsigned long long seed = 7;
    for (int i = 0; i < N; i++) {
        g[i].r = 0.35 + 0.1 * fixture_random(&seed);
        g[i].x = 0.3 + 0.9 * (i % M) + 0.2 * (fixture_random(&seed) - 0.5);
        g[i].y = 0.3 + 0.9 * (i / M) + 0.2 * (fixture_random(&seed) - 0.5);
        g[i].rot = 0;
    }
    gb_box box = {0, 40, 0, 40};
    gb_scene s = fixture_scene(g, N, box, 1, 0, 0);
    s.max_overlap = 0.9;
    int count = 0, crossing = 0;
    double largest = 0, largest_wall = 0;
    for (int i = 0; i < N; i++) {
        for (int j = i + 1; j < N; j++) {
            double d = g[i].r + g[j].r - hypot(g[i].x - g[j].x, g[i].y - g[j].y);
            if (d > 0) count++, largest = fmax(largest, d / fmin(g[i].r, g[j].r));
        }
        double gap = fmin(fmin(g[i].x, 40 - g[i].x), fmin(g[i].y, 40 - g[i].y));
        if (g[i].r > gap) crossing++, largest_wall = fmax(largest_wall, (g[i].r - gap) / g[i].r);
    }
    CHECK(admitted(&s, NULL, NULL));
    printf("1936 discs: %d overlapping pairs (largest %.4f), %d crossing a wall (largest %.4f)\n",
           s.overlaps.grain_pairs, s.overlaps.grain_largest, s.overlaps.boundary, s.overlaps.boundary_largest);
    CHECK(count > 100 && s.overlaps.grain_pairs == count);
    CHECK_NEAR(s.overlaps.grain_largest, largest, 1e-12);
    CHECK(crossing > 0 && s.overlaps.boundary == crossing);
    CHECK_NEAR(s.overlaps.boundary_largest, largest_wall, 1e-12);
    s.box = (gb_box){-1, 41, -1, 41}; /* no wall crossed: the largest pair is refused */
    s.max_overlap = 0.99 * largest;
    CHECK(admitted(&s, NULL, "of the smaller radius); expected at most grains.max_overlap"));
    free(g);
}

static void box_cases(void)
{
    gb_grain g[2] = {{1, 1, 0.5, 0}, {1.6, 1, 0.5, 0}}; /* overlap 0.4: 0.8 of the radius */
    gb_box box = {0, 4, 0, 4};
    gb_scene s = fixture_scene(g, 2, box, 1, 0, 0);
    s.max_overlap = GB_MAX_OVERLAP_DEFAULT;
    CHECK(admitted(&s, NULL, "grain 1 (x 1.6, y 1, r 0.5) overlaps grain 0 by 0.4 (0.8 of the smaller radius)"));
    s.max_overlap = 0.85;
    CHECK(admitted(&s, NULL, NULL) && s.overlaps.grain_pairs == 1);
    CHECK_NEAR(s.overlaps.grain_largest, 0.8, 1e-12);
    g[1].x = 3.9; /* crosses the right wall by 0.8 of its radius */
    CHECK(admitted(&s, NULL, NULL) && s.overlaps.boundary == 1 && s.overlaps.grain_pairs == 0);
    CHECK_NEAR(s.overlaps.boundary_largest, 0.8, 1e-12);
    s.max_overlap = 0.75;
    CHECK(admitted(&s, NULL, "crosses the right wall by 0.4 (0.8 of its radius)"));
    g[1].x = 4.1;
    CHECK(admitted(&s, NULL, "has its centre outside the box [0, 4] x [0, 4] (beyond the right wall)"));
    /* a disc that does not fit even crossing both walls by max_overlap = 0.75 of its radius:
     * 2 (r - 0.75 r) = 0.5 r, at least the side 4 from r = 8 */
    g[1].x = 2, g[1].y = 2, g[1].r = 8.0;
    CHECK(admitted(&s, NULL, "is larger than the box (4 x 4)"));
    g[1].r = 7.9; /* centred, it crosses each wall by 5.9 = 0.747 r: past the box, refused for grain 0 */
    CHECK(admitted(&s, NULL, "grain 1 (x 2, y 2, r 7.9) overlaps grain 0"));
}

/* A circular cavity of radius 1 in an infinite plane (64 elements). */
static void cavity_cases(void)
{
    gb_bem_mesh mesh;
    gb_error err = {0};
    CHECK(gb_bem_mesh_circle(0, 0, 1, 64, 1, &mesh, &err) == GB_OK);
    gb_grain g[1] = {{0, 0, 0.5, 0}};
    gb_box box = {0, 0, 0, 0};
    gb_scene s = fixture_scene(g, 1, box, 1, 0, 0);
    s.host.present = 1;
    snprintf(s.host.cavity, sizeof s.host.cavity, "%s", mesh.group_name[0]);
    s.max_overlap = GB_MAX_OVERLAP_DEFAULT;
    CHECK(admitted(&s, &mesh, NULL) && s.overlaps.boundary == 0);
    /* 0.7 from the centre towards the first element's midpoint, at cos(pi/64) from it: it crosses
     * by 0.2 + 1 - cos(pi/64) */
    g[0].x = 0.7 * cos(PI / 64), g[0].y = 0.7 * sin(PI / 64);
    CHECK(admitted(&s, &mesh, NULL) && s.overlaps.boundary == 1);
    CHECK_NEAR(s.overlaps.boundary_largest, (0.2 + 1 - cos(PI / 64)) / 0.5, 1e-12);
    g[0].x = 0.8, g[0].y = 0;
    CHECK(admitted(&s, &mesh, "crosses the boundary of the host's cavity"));
    g[0].x = 1.2;
    CHECK(admitted(&s, &mesh, "has its centre outside the host's cavity"));
    g[0].x = 0, g[0].r = 1.0;
    CHECK(admitted(&s, &mesh, "is larger than the host's cavity"));
    gb_bem_mesh_free(&mesh);
}

int main(void)
{
    random_box();
    box_cases();
    cavity_cases();
    TEST_END();
}
