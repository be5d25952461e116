/* The `host:` section of a scene (an elastic body with a cavity, meshed by gmsh). */
#ifndef GB_HOST_READ_H
#define GB_HOST_READ_H

#include "gembem/scene.h"
#include "scene/yaml_read.h"

/* Reads top's `host:` mapping: mesh, elements per group (optional: a .geo's own sizes; refused for
 * a .msh), material, boundary of the other groups, the cavity group; meshes the host into *mesh
 * (the caller frees it) to check its groups and record its elements (h->group_elements, ...). The
 * simulation meshes it again when it is created. */
gb_status gb_host_section_read(gb_ymap *top, gb_host_def *h, gb_bem_mesh *mesh, gb_error *err);

#endif
