#include "io/scene_report.h"

void gb_info_quoted(FILE *f, const char *key, const char *text)
{
    fprintf(f, "%s: \"", key);
    for (const char *c = text; *c; c++) fputc(*c == '"' ? '\'' : *c, f);
    fputs("\"\n", f);
}

static void write_host_mesh(FILE *f, const gb_scene *s)
{
    const gb_host_def *h = &s->host;
    const char *source = h->counts_given                         ? "host.elements (counts per group)"
                         : gb_bem_mesh_file_is_msh(h->mesh) ? "the .msh as gmsh wrote it"
                                                            : "the .geo's own mesh sizes";
    fprintf(f, "host_mesh:   # the boundary elements the host was meshed with\n  source: %s\n  elements: {", source);
    for (int g = 0; g < h->n_groups; g++) fprintf(f, "%s%s: %d", g ? ", " : "", h->group[g], h->group_elements[g]);
    fprintf(f, "}\n  cavity_shortest: %.6g\n  cavity_longest: %.6g\n", h->cavity_min, h->cavity_max);
    fprintf(f, "  cavity_shortest_over_mean_radius: %.4g\n", h->cavity_min / s->overlaps.mean_radius);
    fprintf(f, "  cavity_longest_over_mean_radius: %.4g   # warned above %g\n", h->cavity_max / s->overlaps.mean_radius,
            GB_ELEMENT_RATIO_WARN);
    fprintf(f, "  grains_overlapping_particles: %d   # the half-disc boundary particles, at the start\n"
               "  largest_particle_overlap: %.4g   # of the grain's radius\n",
            s->overlaps.particles, s->overlaps.particle_largest);
}

void gb_scene_report_write(FILE *f, const gb_scene *s)
{
    const gb_overlaps *o = &s->overlaps;
    fprintf(f, "admission:   # the overlaps that the scene's geometric check accepted\n");
    fprintf(f, "  max_overlap: %g   # grains.max_overlap: of the smaller radius, or of the grain's at a boundary\n",
            s->max_overlap);
    fprintf(f, "  mean_radius: %.6g\n  grain_pairs_overlapping: %d\n  largest_grain_overlap: %.4g\n", o->mean_radius,
            o->grain_pairs, o->grain_largest);
    fprintf(f, "  grains_crossing_boundary: %d   # a wall or the cavity's boundary\n  largest_boundary_crossing: %.4g\n",
            o->boundary, o->boundary_largest);
    if (s->host.present) write_host_mesh(f, s);
    if (s->warning[0]) gb_info_quoted(f, "warning", s->warning);
}
