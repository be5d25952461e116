/* The `solver:` section of a scene (docs/scene.md). */
#ifndef GB_SOLVER_READ_H
#define GB_SOLVER_READ_H

#include "gembem/scene.h"
#include "scene/yaml_read.h"

/* Reads top's optional `solver:` mapping into *sv, from gb_solver_defaults(): the method, linear
 * solver and Newton iteration (and their combinations), the iteration's parameters, the accuracy
 * (a force, {relative: r}, or absent: the relative default), the caps and cut-backs. */
gb_status gb_solver_section_read(gb_ymap *top, gb_solver_settings *sv, gb_error *err);

#endif
