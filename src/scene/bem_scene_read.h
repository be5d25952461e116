/* Reading an elastic host from a mapping of any YAML scene, for scenes that embed a host (the
 * coupled granular scenes): the keys material, mesh, boundary and remote_stress, exactly as in a
 * `gembem bem` scene (see validation/bem/annulus_pressure.yaml), with the same file:line:column
 * errors. Fills scene->material, mesh_path, mesh_opts, mesh (meshed here) and problem; the caller
 * closes the mapping (gb_ymap_close) after reading its own keys, and frees with
 * gb_bem_scene_free. */
#ifndef GB_BEM_SCENE_READ_H
#define GB_BEM_SCENE_READ_H

#include "gembem/scene.h"
#include "scene/yaml_read.h"

/* One group's boundary condition at `val`: fixed | free | {displacement: [ux, uy]} |
 * {traction: [tx, ty]} | {pressure: p} | {normal_displacement: d} | {ux | tx: a, uy | ty: b}
 * (component-wise: a roller). `path` names the value in messages ("boundary.top"). */
gb_status gb_bem_bc_read(const gb_yaml_doc *doc, struct fy_node *val, const char *path, gb_bem_bc *bc, gb_error *err);

gb_status gb_bem_host_read(const gb_yaml_doc *doc, gb_ymap *map, gb_bem_scene *scene, gb_error *err);

#endif
