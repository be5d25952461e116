/* Contact detection: the cell-list pair list equals a brute-force pair loop on random
 * polydisperse packings (size ratio up to 10), including after moves and rebuilds. */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "contact/pairs.h"
#include "scene_fixture.h"

static int compare(const gb_pair_set *L, double skin, const gb_grain *g, int n)
{
    int cap = 40 * n;
    int *bi = malloc((size_t)cap * sizeof(int)), *bj = malloc((size_t)cap * sizeof(int));
    int m = gb_pairs_brute_force(g, n, skin, bi, bj, cap);
    int k = 0, same = 1, grains_in_list = 0;
    for (int q = 0; q < L->n; q++) {
        if (L->p[q].j < 0) continue;
        grains_in_list++;
        if (k >= m || L->p[q].i != bi[k] || L->p[q].j != bj[k]) same = 0;
        k++;
    }
    free(bi);
    free(bj);
    return same && grains_in_list == m && m > 0;
}

int main(void)
{
    unsigned long long seed = 12345;
    for (int trial = 0; trial < 6; trial++) {
        int n = 300 + 400 * trial;
        double ratio = trial % 2 ? 10.0 : 2.0, rmin = 0.05;
        double side = sqrt(n * 3.0 * 0.05 * 0.05 * ratio) * 2;
        gb_grain *g = malloc((size_t)n * sizeof *g);
        for (int i = 0; i < n; i++) {
            g[i].r = rmin * (1 + (ratio - 1) * pow(fixture_random(&seed), 3));
            g[i].x = side * fixture_random(&seed);
            g[i].y = side * fixture_random(&seed);
            g[i].rot = 0;
        }
        gb_box box = {-0.1, side + 0.1, -0.1, side + 0.1};
        gb_pair_set L = {0};
        gb_pair_search S = {0};
        S.skin = 0.02;
        gb_error err;
        gb_world w = {g, n, &box, NULL};
        CHECK(gb_pairs_rebuild(&L, &S, &w, &err) == GB_OK);
        CHECK(compare(&L, S.skin, g, n));
        /* Wall pairs: exactly the grains within r + skin of a wall. */
        int walls = 0, want = 0;
        for (int q = 0; q < L.n; q++) walls += L.p[q].j < 0;
        for (int i = 0; i < n; i++) {
            double gap[4] = {g[i].x - box.left, box.right - g[i].x, g[i].y - box.bottom, box.top - g[i].y};
            for (int w = 0; w < 4; w++) want += gap[w] < g[i].r + S.skin;
        }
        CHECK(walls == want);
        /* Move every grain, rebuild, compare again: pairs persist, the list stays exact. */
        for (int i = 0; i < n; i++) {
            g[i].x += 0.05 * (fixture_random(&seed) - 0.5);
            g[i].y += 0.05 * (fixture_random(&seed) - 0.5);
        }
        CHECK(gb_pairs_stale(&L, &S, &w));
        CHECK(gb_pairs_rebuild(&L, &S, &w, &err) == GB_OK);
        CHECK(compare(&L, S.skin, g, n));
        CHECK(!gb_pairs_stale(&L, &S, &w));
        gb_pair_set_free(&L), gb_pair_search_free(&S);
        free(g);
    }
    /* The counts become offsets; a total past what an int counts is refused, not wrapped. A list
     * of 2^31 real pairs needs some 2e8 grains and 140 GB, so the counts are made up. */
    gb_error err;
    int count[4] = {3, 0, 5, -1};
    CHECK(gb_pairs_offsets(count, 3, &err) == GB_OK);
    CHECK(count[0] == 0 && count[1] == 3 && count[2] == 3 && count[3] == 8);
    int big[4] = {INT_MAX / 2, INT_MAX / 2, 1, -1}; /* INT_MAX in all: the most a list holds */
    CHECK(gb_pairs_offsets(big, 3, &err) == GB_OK && big[3] == INT_MAX);
    int over[4] = {INT_MAX / 2, INT_MAX / 2, 2, -1}; /* one more */
    CHECK(gb_pairs_offsets(over, 3, &err) == GB_ENOMEM);
    CHECK(over[2] == 2 && over[3] == -1); /* left as they were */
    CHECK(strstr(err.msg, "3 grains have more candidate pairs (2147483648) than the 2147483647 a pair list can count; "
                          "use fewer grains") == err.msg);
    int wrap[4] = {INT_MAX, INT_MAX, INT_MAX, -1}; /* would wrap to a small positive total in an int */
    CHECK(gb_pairs_offsets(wrap, 3, &err) == GB_ENOMEM && strstr(err.msg, "(6442450941)"));
    TEST_END();
}
