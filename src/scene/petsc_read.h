/* solver.linear: petsc and its solver.petsc section (docs/scene.md). */
#ifndef GB_PETSC_READ_H
#define GB_PETSC_READ_H

#include "gembem/scene.h"
#include "scene/yaml_read.h"

/* Reads solver.petsc into sv->petsc (defaults: MUMPS's direct solve). `linear_node` is
 * solver.linear's value when it says petsc, else NULL (then a petsc section is refused). Refuses
 * linear: petsc in a gembem built without PETSc. */
gb_status gb_read_petsc(gb_ymap *solver, struct fy_node *linear_node, gb_solver_settings *sv, gb_error *err);

#endif
