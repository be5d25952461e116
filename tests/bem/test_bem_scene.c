/* The elastostatic scene reader: every section read into the structures, the component-wise
 * (roller) conditions, the grid and point list with the inside mask; then the scene solved: a
 * quarter plate in uniaxial tension on symmetry rollers, whose exact field is a uniform stress. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <string.h>
#include <unistd.h>

#include "scene/bem_scene_read.h"
#include "check.h"
#include "gembem/scene.h"

int main(void)
{
    gb_error err = {0};
    gb_bem_scene sc;
    CHECK(gb_bem_scene_load("tests/bem/scenes/plate_tension.yaml", &sc, &err) == GB_OK);
    if (err.code) fprintf(stderr, "%s\n", err.msg);
    CHECK(!strcmp(sc.length_unit, "m") && !strcmp(sc.force_unit, "N"));
    CHECK(sc.material.shear_modulus == 100.0 && sc.material.poisson == 0.25 &&
          sc.material.plane == GB_BEM_PLANE_STRESS);
    CHECK(sc.mesh.n_groups == 4 && sc.mesh.n == 80 && !sc.mesh.unbounded);
    int left = gb_bem_mesh_group(&sc.mesh, "left"), bottom = gb_bem_mesh_group(&sc.mesh, "bottom");
    int right = gb_bem_mesh_group(&sc.mesh, "right"), top = gb_bem_mesh_group(&sc.mesh, "top");
    CHECK(sc.problem.bc[left].kind == GB_BEM_BC_COMPONENTS && sc.problem.bc[left].u_given == 1);
    CHECK(sc.problem.bc[bottom].kind == GB_BEM_BC_COMPONENTS && sc.problem.bc[bottom].u_given == 2);
    CHECK(sc.problem.bc[right].kind == GB_BEM_BC_TRACTION && sc.problem.bc[right].value[0] == 2);
    CHECK(sc.problem.bc[top].kind == GB_BEM_BC_FREE);
    CHECK(sc.grid_nx == 5 && sc.grid_ny == 5 && sc.npts == 27);
    int inside = 0;
    for (int i = 0; i < sc.npts; i++) inside += sc.pt_inside[i];
    CHECK(inside == 9 + 2); /* the grid's border lies on the boundary */

    gb_bem_system sys;
    gb_bem_solution sol;
    CHECK(gb_bem_assemble(&sc.mesh, &sc.material, &sys, &err) == GB_OK);
    CHECK(gb_bem_solve(&sc.mesh, &sys, &sc.problem, NULL, &sol, &err) == GB_OK);
    double s = 2, E = 2 * 100.0 * 1.25, exx = s / E, eyy = -0.25 * s / E, worst_u = 0, worst_s = 0;
    for (int i = 0; i < sc.npts; i++) {
        if (!sc.pt_inside[i]) continue;
        double u[2], st[3], *x = sc.pts + 2 * i;
        CHECK(gb_bem_interior(&sc.mesh, &sc.material, &sc.problem, &sol, 1, x, u, st, &err) == GB_OK);
        worst_u = fmax(worst_u, fmax(fabs(u[0] - exx * (x[0] + 1)), fabs(u[1] - eyy * (x[1] + 1))) / (2 * exx));
        worst_s = fmax(worst_s, fmax(fabs(st[0] - s), fmax(fabs(st[1]), fabs(st[2]))) / s);
    }
    printf("plate in tension on rollers, %d elements: max u error %.2e, max stress error %.2e (relative)\n", sc.mesh.n,
           worst_u, worst_s);
    CHECK(worst_u < 5e-3 && worst_s < 5e-3);
    gb_bem_solution_free(&sol);
    gb_bem_system_free(&sys);
    gb_bem_scene_free(&sc);

    /* a roller needs one of each pair */
    char cwd[400];
    CHECK(getcwd(cwd, sizeof cwd) != NULL);
    FILE *f = fopen("/tmp/gb_test_bem_roller.yaml", "w");
    fprintf(f,
            "units: {length: m, force: N}\nmaterial: {shear_modulus: 1, poisson: 0.3, plane: strain}\n"
            "mesh: {file: %s/tests/bem/scenes/plate.geo}\n"
            "boundary:\n  left: {ux: 0, tx: 0}\n  bottom: fixed\n  right: free\n  top: free\n",
            cwd);
    fclose(f);
    CHECK(gb_bem_scene_load("/tmp/gb_test_bem_roller.yaml", &sc, &err) == GB_EINPUT);
    CHECK(strstr(err.msg, ":5:10: boundary.left: give one of ux, tx and one of uy, ty") != NULL);
    if (!strstr(err.msg, ":5:10:")) fprintf(stderr, "%s\n", err.msg);

    /* a host embedded in another scene's mapping */
    f = fopen("/tmp/gb_test_bem_host.yaml", "w");
    fprintf(f,
            "grains: 27\nhost:\n  material: {shear_modulus: 95000, poisson: 0.1, plane: strain}\n"
            "  mesh: {file: %s/meshes/square_cavity.geo, groups: {outer: {count: 20}, cavity: {count: 24}}}\n"
            "  boundary: {outer: fixed, cavity: free}\n  colour: blue\n",
            cwd);
    fclose(f);
    gb_yaml_doc doc;
    gb_ymap root, host;
    CHECK(gb_yaml_load("/tmp/gb_test_bem_host.yaml", &doc, &err) == GB_OK);
    CHECK(gb_ymap_open(&doc, fy_document_root(doc.fyd), "", &root, &err) == GB_OK);
    CHECK(gb_ymap_map(&root, "host", GB_Y_REQUIRED, &host, &err) == GB_OK);
    memset(&sc, 0, sizeof sc);
    CHECK(gb_bem_host_read(&doc, &host, &sc, &err) == GB_OK);
    CHECK(sc.mesh.n == 44 && sc.material.shear_modulus == 95000);
    CHECK(sc.problem.bc[gb_bem_mesh_group(&sc.mesh, "outer")].kind == GB_BEM_BC_FIXED);
    CHECK(gb_ymap_close(&host, &err) == GB_EINPUT);
    CHECK(
        strstr(err.msg, ":6:3: host: unknown key 'colour'; expected one of: material, mesh, boundary, remote_stress") &&
        !strstr(err.msg, "remote_stress, remote_stress"));
    gb_bem_scene_free(&sc);
    gb_yaml_free(&doc);
    TEST_END();
}
