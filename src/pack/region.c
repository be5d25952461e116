/* The region a packing fills (region.h). */
#include <math.h>

#include "pack/region.h"

void gb_region_init(gb_region *rg, const gb_scene *s, const gb_bem_mesh *mesh)
{
    rg->box = mesh ? NULL : &s->box;
    rg->mesh = mesh;
    rg->margin = 0;
    if (!mesh) {
        rg->lo[0] = s->box.left, rg->hi[0] = s->box.right, rg->lo[1] = s->box.bottom, rg->hi[1] = s->box.top;
        rg->area = (s->box.right - s->box.left) * (s->box.top - s->box.bottom);
        return;
    }
    rg->cavity = gb_bem_mesh_group(mesh, s->host.cavity);
    double box[4], twice = 0;
    gb_bem_mesh_group_box(mesh, rg->cavity, box);
    rg->lo[0] = box[0], rg->hi[0] = box[1], rg->lo[1] = box[2], rg->hi[1] = box[3];
    for (int e = 0; e < mesh->n; e++) {
        if (mesh->group[e] != rg->cavity) continue;
        const double *a = &mesh->p0[2 * e], *b = &mesh->p1[2 * e];
        twice += a[0] * b[1] - b[0] * a[1];
        rg->margin = fmax(rg->margin, 0.5 * mesh->length[e]);
    }
    rg->area = 0.5 * fabs(twice); /* a cavity's loop runs clockwise (the body on its left) */
}

int gb_region_fits(const gb_region *rg, double x, double y, double r)
{
    if (!(x - r > rg->lo[0] && x + r < rg->hi[0] && y - r > rg->lo[1] && y + r < rg->hi[1])) return 0;
    if (!rg->mesh) return 1;
    return gb_bem_mesh_in_cavity(rg->mesh, rg->cavity, x, y) && gb_bem_mesh_distance(rg->mesh, x, y) >= r + rg->margin;
}
