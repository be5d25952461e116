/* What a loading stage is: its name as scenes spell it, and the force its loads put on a grain (the
 * force scale of src/gem/accuracy.c, and the check of a relative accuracy at the first step). */
#include <math.h>

#include "gembem/scene.h"

static const double PI = 3.14159265358979323846;

double gb_scene_load_force(const gb_scene *s, int stage)
{
    if (s->n_grains <= 0) return 0;
    double r = 0, area = 0;
    for (int i = 0; i < s->n_grains; i++) r += s->grains[i].r, area += PI * s->grains[i].r * s->grains[i].r;
    r /= s->n_grains, area /= s->n_grains;
    double weight = hypot(s->body_force_per_area[0], s->body_force_per_area[1]) * area, stress = 0;
    if (stage >= 0 && stage < s->n_stages) {
        const gb_stage *sg = &s->stages[stage];
        switch (sg->kind) {
        case GB_STAGE_ISOTROPIC: stress = sg->stress; break;
        case GB_STAGE_BIAXIAL_STRESS: stress = fmax(sg->s1, sg->s2); break;
        case GB_STAGE_SHEAR_MEAN: stress = sg->mean_stress; break;
        default: break;
        }
    }
    /* a stress [F/L] on a packing carried by contacts about a diameter apart */
    return fmax(weight, stress * 2 * r);
}

/* Indexed by gb_stage_kind: the one list of the names (the scene reader looks kinds up in it). */
static const char *const STAGE_NAMES[GB_STAGE_KINDS] = {
    "isotropic", "strain", "shear_mean_stress", "biaxial_stress", "relax", "host_displacement", "host_load"};

const char *gb_stage_name(gb_stage_kind k)
{
    return (unsigned)k < GB_STAGE_KINDS ? STAGE_NAMES[k] : STAGE_NAMES[GB_STAGE_BIAXIAL_STRESS];
}
