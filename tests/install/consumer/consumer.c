/* A program of a gembem user, built against an installed gembem (pkg-config or find_package):
 * loads the three-disc scene of Kishino's case 1 (validation/three_discs/case1.yaml) and checks
 * what the file says, counted by hand: 3 grains of radius 1 cm, the top one at 1 + 2 sin 60 deg,
 * 10 + 100 load steps, the box's top at 2 + 2 sin 60 deg. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gembem/gembem.h>

static int failures;

static void expect(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "consumer: FAILED: %s\n", what);
        failures++;
    }
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: consumer SCENE.yaml VERSION\n");
        return 2;
    }
    gb_error err = {0};
    gb_scene scene;
    if (gb_scene_load(argv[1], &scene, &err) != GB_OK) {
        fprintf(stderr, "consumer: %s\n", err.msg);
        return 1;
    }
    gb_sim *sim = NULL;
    if (gb_sim_create(&scene, &sim, &err) != GB_OK) {
        fprintf(stderr, "consumer: %s\n", err.msg);
        gb_scene_free(&scene);
        return 1;
    }
    expect(!strcmp(gb_version(), argv[2]), "gb_version() is the installed package's version");
    expect(gb_sim_n_grains(sim) == 3, "3 grains");
    for (int i = 0; i < 3; i++) expect(gb_sim_grain(sim, i).r == 1.0, "radius 1");
    expect(fabs(gb_sim_grain(sim, 2).y - (1.0 + sqrt(3.0))) < 1e-12, "top disc at 1 + 2 sin 60 = 1 + sqrt 3");
    expect(gb_scene_total_steps(&scene) == 110, "10 + 100 steps");
    gb_box box = gb_sim_box(sim);
    expect(box.left == 0.0 && box.right == 4.0 && fabs(box.top - (2.0 + sqrt(3.0))) < 1e-12, "the box 4 x (2 + sqrt 3)");
    gb_sim_free(sim);
    gb_scene_free(&scene);
    if (!failures) printf("consumer: gembem %s, 3 discs as the scene says\n", gb_version());
    return failures != 0;
}
