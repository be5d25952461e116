/* The `pack:` section of a pack scene (docs/scene.md, "Pack scenes"); the rest of the scene is read
 * by the granular scene's reader (src/scene/scene_pack.h). */
#include <math.h>
#include <string.h>

#include "gembem/pack.h"
#include "pack/region.h"
#include "pack/sizes.h"
#include "scene/scene_pack.h"

/* sizes: {radii | diameters: [...], fractions: [...], fractions_of: area | number}
 *      | {uniform: [rmin, rmax]} | {lognormal: [rmin, rmax], median: m, sigma: s} */
static gb_status read_sizes(gb_ymap *pack, gb_pack_sizes *z, gb_error *err)
{
    gb_ymap m;
    gb_status st;
    struct fy_node *rad, *dia, *uni, *logn, *fr, *frof;
    if ((st = gb_ymap_map(pack, "sizes", GB_Y_REQUIRED, &m, err)) || (st = gb_ymap_find(&m, "radii", 0, &rad, err)) ||
        (st = gb_ymap_find(&m, "diameters", 0, &dia, err)) || (st = gb_ymap_find(&m, "uniform", 0, &uni, err)) ||
        (st = gb_ymap_find(&m, "lognormal", 0, &logn, err)) || (st = gb_ymap_find(&m, "fractions", 0, &fr, err)) ||
        (st = gb_ymap_find(&m, "fractions_of", 0, &frof, err)))
        return st;
    if (!!rad + !!dia + !!uni + !!logn != 1)
        return gb_yaml_fail(m.doc, m.node, err, "pack.sizes: expected one of radii: [r1, ...], diameters: [d1, ...], "
                                                "uniform: [rmin, rmax] or lognormal: [rmin, rmax]");
    memset(z, 0, sizeof *z);
    if (rad || dia) {
        z->kind = GB_SIZES_DISCRETE;
        if ((st = gb_ymap_numbers(&m, rad ? "radii" : "diameters", 0, GB_PACK_MAX_SIZES, z->radius, &z->n, err)))
            return st;
        for (int k = 0; k < z->n; k++) {
            if (!(z->radius[k] > 0))
                return gb_yaml_fail(m.doc, rad ? rad : dia, err, "pack.sizes.%s: expected sizes > 0",
                                    rad ? "radii" : "diameters");
            if (dia) z->radius[k] *= 0.5;
            z->fraction[k] = 1.0 / z->n;
        }
        char of[16] = "area";
        if ((st = gb_ymap_string(&m, "fractions_of", 0, of, sizeof of, err))) return st;
        if (strcmp(of, "area") && strcmp(of, "number"))
            return gb_yaml_fail(m.doc, frof, err, "pack.sizes.fractions_of: expected 'area' or 'number', found '%s'", of);
        z->by_number = !strcmp(of, "number");
        int nf = 0;
        if (fr) {
            if ((st = gb_ymap_numbers(&m, "fractions", 0, GB_PACK_MAX_SIZES, z->fraction, &nf, err))) return st;
            double sum = 0;
            int bad = nf != z->n;
            for (int k = 0; k < nf; k++) bad |= !(z->fraction[k] >= 0), sum += z->fraction[k];
            if (bad || !(fabs(sum - 1) <= 1e-6))
                return gb_yaml_fail(m.doc, fr, err, "pack.sizes.fractions: expected %d shares >= 0, one per size, "
                                                    "summing to 1", z->n);
        }
        return gb_ymap_close(&m, err);
    }
    if (fr || frof)
        return gb_yaml_fail(m.doc, fr ? fr : frof, err, "pack.sizes: fractions and fractions_of go with discrete "
                                                        "radii or diameters");
    double b[2];
    z->kind = uni ? GB_SIZES_UNIFORM : GB_SIZES_LOGNORMAL;
    if ((st = gb_ymap_vector(&m, uni ? "uniform" : "lognormal", 0, 2, b, err))) return st;
    if (!(b[0] > 0 && b[1] > b[0]))
        return gb_yaml_fail(m.doc, uni ? uni : logn, err, "pack.sizes.%s: expected radii [rmin, rmax] with "
                                                          "0 < rmin < rmax", uni ? "uniform" : "lognormal");
    z->rmin = b[0], z->rmax = b[1];
    if (logn) {
        struct fy_node *med, *sig;
        if ((st = gb_ymap_find(&m, "median", GB_Y_REQUIRED, &med, err)) ||
            (st = gb_ymap_find(&m, "sigma", GB_Y_REQUIRED, &sig, err)) ||
            (st = gb_ymap_number(&m, "median", GB_Y_REQUIRED, &z->median, err)) ||
            (st = gb_ymap_number(&m, "sigma", GB_Y_REQUIRED, &z->sigma, err)))
            return st;
        if (!(z->median >= z->rmin && z->median <= z->rmax))
            return gb_yaml_fail(m.doc, med, err, "pack.sizes.median: expected a radius within the bounds [%g, %g]",
                                z->rmin, z->rmax);
        if (!(z->sigma > 0 && z->sigma <= 3))
            return gb_yaml_fail(m.doc, sig, err, "pack.sizes.sigma: expected the standard deviation of ln r in (0, 3]");
    }
    return gb_ymap_close(&m, err);
}

/* The rules between the keys and the region (its area, its size against the grains'). */
static gb_status check(gb_ymap *m, const gb_scene *s, const gb_bem_mesh *mesh, gb_pack_def *d, gb_error *err)
{
    struct fy_node *cn, *pn, *sn, *fn;
    gb_ymap_find(m, "count", 0, &cn, err), gb_ymap_find(m, "protocol", 0, &pn, err);
    gb_ymap_find(m, "stress", 0, &sn, err), gb_ymap_find(m, "solid_fraction", 0, &fn, err);
    gb_region rg;
    gb_region_init(&rg, s, mesh);
    double a = gb_sizes_mean_area(&d->sizes), rmax = gb_sizes_max_radius(&d->sizes);
    if (d->protocol == GB_PACK_GROWTH) {
        if (!fn == !sn)
            return gb_yaml_fail(m->doc, m->node, err, "pack: the growth protocol grows the grains to a target: give "
                                                      "solid_fraction or stress (one of them)");
        if (sn && !cn)
            return gb_yaml_fail(m->doc, sn, err, "pack.stress: give the grains' count (their radii are scaled by "
                                                 "the one factor that reaches the stress)");
        if (fn && !(d->solid_fraction <= GB_PACK_MAX_SOLID_FRACTION))
            return gb_yaml_fail(m->doc, fn, err, "pack.solid_fraction: %g is above %.2f, the densest the growth "
                                                 "protocol makes (random close packing of discs is about 0.84; "
                                                 "beyond %.2f the grains press into each other by more than a few "
                                                 "per cent of their radii)", d->solid_fraction,
                                GB_PACK_MAX_SOLID_FRACTION, GB_PACK_MAX_SOLID_FRACTION);
    } else {
        if (sn)
            return gb_yaml_fail(m->doc, sn, err, "pack.stress: a target stress is the growth protocol's; a deposit "
                                                 "is loaded by its own weight");
        if (!cn == !fn)
            return gb_yaml_fail(m->doc, m->node, err, "pack: a deposition needs the grains' count or solid_fraction "
                                                      "(their area over the region's), one of them");
        if (fn && !(d->solid_fraction <= GB_PACK_MAX_FILL))
            return gb_yaml_fail(m->doc, fn, err, "pack.solid_fraction: %g is above %.2f, the most a deposit of "
                                                 "discs holds of its region (random close packing is about 0.84, "
                                                 "less along the walls)", d->solid_fraction, GB_PACK_MAX_FILL);
        if (s->body_force_per_area[0] == 0 && s->body_force_per_area[1] == 0)
            return gb_yaml_fail(m->doc, pn, err, "pack.protocol: a deposition needs a body force for the grains "
                                                 "to fall: body_force: {weight_per_area: w} or {gravity: [gx, gy], "
                                                 "density: rho}");
    }
    if (!cn) {
        double count = round(d->solid_fraction * rg.area / a);
        if (!(count >= 1))
            return gb_yaml_fail(m->doc, fn, err, "pack.solid_fraction: the region (area %g) is too small for one "
                                                 "grain (mean area %g) at solid fraction %g", rg.area, a,
                                d->solid_fraction);
        if (count > GB_PACK_MAX_COUNT)
            return gb_yaml_fail(m->doc, fn, err, "pack.solid_fraction: the region (area %g) takes %.0f grains of "
                                                 "mean area %g, more than %ld", rg.area, count, a, GB_PACK_MAX_COUNT);
        d->count = (long)count;
    }
    /* the grains keep their drawn sizes unless growth scales them */
    int fixed_sizes = d->protocol == GB_PACK_DEPOSITION || !cn;
    double w = rg.hi[0] - rg.lo[0], h = rg.hi[1] - rg.lo[1];
    if (fixed_sizes && !(2 * (rmax + rg.margin) < fmin(w, h)))
        return gb_yaml_fail(m->doc, m->node, err, "pack: the region (%g x %g%s) is too small for the largest grain "
                                                  "(radius %g)", w, h, mesh ? ", the cavity's bounding box less its "
                                                  "boundary particles" : "", rmax);
    if (d->protocol == GB_PACK_DEPOSITION && cn && !(d->count * a <= GB_PACK_MAX_FILL * rg.area))
        return gb_yaml_fail(m->doc, cn, err, "pack.count: the region (area %g) is too small for %ld grains: their "
                                             "area, about %g, is %.3g of it; a deposit holds at most %.2f of its "
                                             "region", rg.area, d->count, d->count * a, d->count * a / rg.area,
                            GB_PACK_MAX_FILL);
    return GB_OK;
}

static gb_status read_pack(gb_ymap *top, gb_scene *s, const gb_bem_mesh *mesh, void *user, gb_error *err)
{
    gb_pack_def *d = user;
    gb_ymap m;
    gb_status st;
    char protocol[32] = "";
    memset(d, 0, sizeof *d);
    long seed = 1, count = 0;
    d->max_iterations = 10000000L;
    if ((st = gb_ymap_map(top, "pack", GB_Y_REQUIRED, &m, err)) ||
        (st = gb_ymap_string(&m, "protocol", GB_Y_REQUIRED, protocol, sizeof protocol, err)) ||
        (st = gb_ymap_int(&m, "seed", 0, 0, 9007199254740991L, &seed, err)) ||
        (st = gb_ymap_int(&m, "count", 0, 1, GB_PACK_MAX_COUNT, &count, err)) ||
        (st = gb_ymap_number(&m, "solid_fraction", GB_Y_POSITIVE, &d->solid_fraction, err)) ||
        (st = gb_ymap_number(&m, "stress", GB_Y_POSITIVE, &d->stress, err)) ||
        (st = gb_ymap_int(&m, "max_iterations", 0, 1, 2000000000L, &d->max_iterations, err)) ||
        (st = gb_ymap_number(&m, "friction_deg", 0, &d->friction_deg, err)) ||
        (st = read_sizes(&m, &d->sizes, err)))
        return st;
    d->seed = (uint64_t)seed, d->count = count;
    if (!strcmp(protocol, "growth")) d->protocol = GB_PACK_GROWTH;
    else if (strcmp(protocol, "deposition")) {
        struct fy_node *v;
        gb_ymap_find(&m, "protocol", 0, &v, err);
        return gb_yaml_fail(m.doc, v, err, "pack.protocol: expected 'deposition' (the grains fall and settle) or "
                                           "'growth' (they grow to a solid fraction or a stress), found '%s'",
                            protocol);
    }
    if (!(d->friction_deg >= 0 && d->friction_deg <= s->grain_grain.friction_deg)) {
        struct fy_node *v;
        gb_ymap_find(&m, "friction_deg", 0, &v, err);
        return gb_yaml_fail(m.doc, v, err, "pack.friction_deg: %g is outside 0 to %g, the grains' friction angle "
                                           "(materials.grain_grain.friction_deg)%s", d->friction_deg,
                            s->grain_grain.friction_deg, d->friction_deg > 0 ? ": packed with more friction than "
                            "the scene's, the grains would slip once it applies" : "");
    }
    if ((st = gb_ymap_close(&m, err))) return st;
    return check(&m, s, mesh, d, err);
}

gb_status gb_pack_scene_load(const char *path, gb_scene *scene, gb_bem_mesh *mesh, gb_pack_def *def, gb_error *err)
{
    return gb_scene_load_pack(path, scene, mesh, read_pack, def, err);
}
