/* The `host:` section of a scene (an elastic body with a cavity, meshed by gmsh). */
#ifndef GB_HOST_READ_H
#define GB_HOST_READ_H

#include "gembem/scene.h"
#include "scene/yaml_read.h"

/* Reads top's `host:` mapping: mesh, elements per group, material, boundary of the other groups,
 * the cavity group. The mesh itself is loaded when the simulation is created. */
gb_status gb_host_section_read(gb_ymap *top, gb_host_def *h, gb_error *err);

#endif
