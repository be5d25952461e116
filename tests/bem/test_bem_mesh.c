/* Boundary meshes: gmsh .geo and .msh, element counts and sizes, orientation by the body's
 * outward normal whatever gmsh returns, and the broken boundaries that must be refused. */
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gembem/bem.h"

static double loop_area(const gb_bem_mesh *m, int k)
{
    double A = 0;
    for (int e = m->loop_start[k]; e < m->loop_start[k + 1]; e++)
        A += 0.5 * (m->p0[2 * e] * m->p1[2 * e + 1] - m->p0[2 * e + 1] * m->p1[2 * e]);
    return A;
}

/* Every loop chained (end of one element = start of the next), outer CCW, cavities CW, and the
 * normal pointing away from the body: a point a little along -n is inside, along +n is not. */
static int well_oriented(const gb_bem_mesh *m)
{
    int ok = 1;
    for (int k = 0; k < m->n_loops; k++) {
        double A = loop_area(m, k);
        ok &= m->loop_outer[k] ? A > 0 : A < 0;
        for (int e = m->loop_start[k]; e < m->loop_start[k + 1]; e++) {
            int next = e + 1 < m->loop_start[k + 1] ? e + 1 : m->loop_start[k];
            ok &= hypot(m->p1[2 * e] - m->p0[2 * next], m->p1[2 * e + 1] - m->p0[2 * next + 1]) < 1e-12;
            double d = 0.05 * m->length[e];
            ok &= gb_bem_mesh_inside(m, m->mid[2 * e] - d * m->normal[2 * e],
                                     m->mid[2 * e + 1] - d * m->normal[2 * e + 1]);
            ok &= !gb_bem_mesh_inside(m, m->mid[2 * e] + d * m->normal[2 * e],
                                      m->mid[2 * e + 1] + d * m->normal[2 * e + 1]);
        }
    }
    return ok;
}

static int refused(const char *path, const gb_bem_mesh_opts *o, const char *needle)
{
    gb_bem_mesh m;
    gb_error err = {0};
    gb_status st = gb_bem_mesh_load(path, o, &m, &err);
    if (st != GB_EINPUT || !strstr(err.msg, needle)) {
        fprintf(stderr, "%s: status %d, message '%s', expected '%s'\n", path, st, err.msg, needle);
        if (!st) gb_bem_mesh_free(&m);
        return 0;
    }
    return 1;
}

int main(void)
{
    gb_error err = {0};
    gb_bem_mesh m;
    gb_bem_mesh_opts o = gb_bem_mesh_opts_default();

    /* counts per group, distributed over the group's four arcs */
    o.n_group_sizes = 2;
    snprintf(o.group_sizes[0].group, GB_BEM_NAME_MAX, "cavity");
    o.group_sizes[0].count = 40;
    snprintf(o.group_sizes[1].group, GB_BEM_NAME_MAX, "outer");
    o.group_sizes[1].count = 62;
    CHECK(gb_bem_mesh_load("meshes/annulus.geo", &o, &m, &err) == GB_OK);
    CHECK(m.n == 102 && m.n_loops == 2 && m.n_groups == 2 && !m.unbounded);
    int gc = gb_bem_mesh_group(&m, "cavity"), go = gb_bem_mesh_group(&m, "outer"), nc = 0;
    CHECK(gc >= 0 && go >= 0 && gb_bem_mesh_group(&m, "nope") == -1);
    for (int e = 0; e < m.n; e++) {
        nc += m.group[e] == gc;
        double r = hypot(m.mid[2 * e], m.mid[2 * e + 1]),
               rn = (m.mid[2 * e] * m.normal[2 * e] + m.mid[2 * e + 1] * m.normal[2 * e + 1]) / r;
        if (m.group[e] == gc)
            CHECK(r < 1.01 && rn < -0.99); /* cavity normal points to the centre */
        else
            CHECK(r > 1.9 && rn > 0.99);
    }
    CHECK(nc == 40);
    CHECK(well_oriented(&m));
    gb_bem_mesh_free(&m);

    /* gmshInitialize appends to PATH and PYTHONPATH: the caller's values come back (fuzz_contacts
     * ran out of memory on them after 20 000 loads) */
    static const char *const vars[2] = {"PATH", "PYTHONPATH"};
    char before[2][4096];
    for (int k = 0; k < 2; k++)
        snprintf(before[k], sizeof before[k], "%s", getenv(vars[k]) ? getenv(vars[k]) : "(unset)");
    for (int rep = 0; rep < 2; rep++) {
        CHECK(gb_bem_mesh_load("tests/bem/annulus_coarse.msh", NULL, &m, &err) == GB_OK);
        gb_bem_mesh_free(&m);
    }
    for (int k = 0; k < 2; k++) CHECK(!strcmp(before[k], getenv(vars[k]) ? getenv(vars[k]) : "(unset)"));

    /* gmsh sets LC_NUMERIC to "C": the caller's setting comes back */
    if (setlocale(LC_NUMERIC, "C.UTF-8")) {
        CHECK(gb_bem_mesh_load("meshes/hole_infinite.geo", NULL, &m, &err) == GB_OK);
        const char *now = setlocale(LC_NUMERIC, NULL);
        CHECK(now && !strcmp(now, "C.UTF-8"));
        gb_bem_mesh_free(&m);
        setlocale(LC_NUMERIC, "C");
    }

    /* a global element size */
    o = gb_bem_mesh_opts_default();
    o.size = 0.5;
    CHECK(gb_bem_mesh_load("meshes/square_cavity.geo", &o, &m, &err) == GB_OK);
    double lmax = 0;
    for (int e = 0; e < m.n; e++) lmax = fmax(lmax, m.length[e]);
    CHECK(lmax <= 0.5 * 1.05 && m.n >= 100);
    CHECK(well_oriented(&m));
    gb_bem_mesh_free(&m);

    /* the non-convex cavity, the infinite plane, a .msh file */
    o = gb_bem_mesh_opts_default();
    CHECK(gb_bem_mesh_load("meshes/irregular_cavity.geo", &o, &m, &err) == GB_OK);
    CHECK(m.n_loops == 2 && well_oriented(&m));
    gb_bem_mesh_free(&m);
    o.unbounded = 1;
    CHECK(gb_bem_mesh_load("meshes/hole_infinite.geo", &o, &m, &err) == GB_OK);
    CHECK(m.unbounded && m.n_loops == 1 && !m.loop_outer[0] && loop_area(&m, 0) < 0 && well_oriented(&m));
    CHECK(!gb_bem_mesh_inside(&m, 0, 0) && gb_bem_mesh_inside(&m, 5, 5));
    gb_bem_mesh_free(&m);
    o.unbounded = 0;
    CHECK(gb_bem_mesh_load("tests/bem/annulus_coarse.msh", &o, &m, &err) == GB_OK);
    CHECK(m.n_loops == 2 && well_oriented(&m));
    gb_bem_mesh_free(&m);

    /* node tags far apart (fuzz/regress/mesh): the same mesh as with gmsh's own tags, read in
     * milliseconds (nodes were indexed by tag: 2e12 asked for 48 TB, 7.7e17 overflowed) */
    gb_bem_mesh ref;
    CHECK(gb_bem_mesh_load("fuzz/corpus/mesh/square_cavity_v2.msh", &o, &ref, &err) == GB_OK);
    const char *far[2] = {"fuzz/regress/mesh/node_tag_2e12.msh", "fuzz/regress/mesh/node_tag_overflow.msh"};
    for (int k = 0; k < 2; k++) {
        CHECK(gb_bem_mesh_load(far[k], &o, &m, &err) == GB_OK);
        CHECK(m.n == ref.n && m.n_loops == ref.n_loops);
        for (int e = 0; e < m.n && m.n == ref.n; e++)
            CHECK(m.p0[2 * e] == ref.p0[2 * e] && m.p1[2 * e + 1] == ref.p1[2 * e + 1]);
        gb_bem_mesh_free(&m);
    }
    gb_bem_mesh_free(&ref);

    /* broken input */
    CHECK(refused("meshes/does_not_exist.geo", &o, "cannot open"));
    CHECK(refused(gb_test_file("bem_syntax.geo", "Point(1) = {0, 0, 0\nLine(1) = {1, 2};\n"), &o, "gmsh could not read"));
    CHECK(
        refused(gb_test_file("bem_open.geo",
                          "Point(1) = {0,0,0}; Point(2) = {1,0,0}; Point(3) = {1,1,0}; Point(4) = {0,1,0};\n"
                          "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4};\nPhysical Curve(\"outer\") = {1,2,3};\n"),
                &o, "open at node"));
    CHECK(refused(gb_test_file("bem_cross.geo",
                            "Point(1) = {0,0,0}; Point(2) = {2,1,0}; Point(3) = {2,0,0}; Point(4) = {0,2,0};\n"
                            "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};\n"
                            "Physical Curve(\"outer\") = {1,2,3,4};\n"),
                  &o, "crosses or touches"));
    CHECK(refused(gb_test_file("bem_nogroup.geo", "Point(1) = {0,0,0}; Point(2) = {1,0,0}; Point(3) = {0,1,0};\n"
                                           "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"),
                  &o, "no physical curve groups"));
    CHECK(refused(gb_test_file("bem_two.geo", "Point(1) = {0,0,0}; Point(2) = {1,0,0}; Point(3) = {0,1,0};\n"
                                       "Point(4) = {5,0,0}; Point(5) = {6,0,0}; Point(6) = {5,1,0};\n"
                                       "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"
                                       "Line(4) = {4,5}; Line(5) = {5,6}; Line(6) = {6,4};\n"
                                       "Physical Curve(\"a\") = {1,2,3}; Physical Curve(\"b\") = {4,5,6};\n"),
                  &o, "both outermost"));
    CHECK(refused("meshes/annulus.txt", &o, "expected a gmsh"));
    o.n_group_sizes = 1;
    snprintf(o.group_sizes[0].group, GB_BEM_NAME_MAX, "hole");
    o.group_sizes[0].count = 10;
    CHECK(refused("meshes/annulus.geo", &o, "no physical curve group named 'hole'"));
    o = gb_bem_mesh_opts_default();

    /* polygons: zero-length element, fold-back, orientation of a clockwise outer loop */
    double sq[] = {0, 0, 1, 0, 1, 0, 1, 1, 0, 1};
    int g5[5] = {0}, n5[1] = {5};
    CHECK(gb_bem_mesh_from_polygons(1, n5, sq, g5, 1, NULL, 0, &m, &err) == GB_EINPUT &&
          strstr(err.msg, "zero-length"));
    double fold[] = {0, 0, 2, 0, 1, 0, 1, 1};
    int n4[1] = {4};
    CHECK(gb_bem_mesh_from_polygons(1, n4, fold, g5, 1, NULL, 0, &m, &err) == GB_EINPUT);
    double cw[] = {0, 0, 0, 1, 1, 1, 1, 0};
    int gg[4] = {0, 1, 2, 3};
    const char *names[4] = {"left", "top", "right", "bottom"};
    CHECK(gb_bem_mesh_from_polygons(1, n4, cw, gg, 4, names, 0, &m, &err) == GB_OK);
    CHECK(well_oriented(&m) && loop_area(&m, 0) > 0);
    for (int e = 0; e < 4; e++) { /* the groups follow their edges through the reversal */
        const char *gname = m.group_name[m.group[e]];
        double nx = m.normal[2 * e], ny = m.normal[2 * e + 1];
        CHECK((!strcmp(gname, "left") && nx < -0.99) || (!strcmp(gname, "top") && ny > 0.99) ||
              (!strcmp(gname, "right") && nx > 0.99) || (!strcmp(gname, "bottom") && ny < -0.99));
    }
    gb_bem_mesh_free(&m);
    TEST_END();
}
