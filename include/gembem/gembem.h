/* gembem's public API in one include: the granular element method (Kishino 1989) with an elastic
 * host by the boundary element method. One header per module; docs/architecture.md shows how they
 * fit together. */
#ifndef GEMBEM_GEMBEM_H
#define GEMBEM_GEMBEM_H

#include "gembem/status.h"       /* gb_status, gb_error: every function's outcome and message */
#include "gembem/grain.h"        /* grains, walls, contact materials: the types every layer shares */
#include "gembem/scene.h"        /* scenes: reading, defaults, stages, BEM scenes */
#include "gembem/bem.h"          /* the boundary element module: meshes, solves, condensation */
#include "gembem/gem.h"          /* a simulation: grains, contacts, reports */
#include "gembem/solver.h"       /* relaxations, solver statistics */
#include "gembem/hybrid.h"       /* an elastic host's cavity and groups */
#include "gembem/measure.h"      /* micromechanics: fabric, energy, work, dissipation */
#include "gembem/strain_field.h" /* strain of a triangulated granular zone, D2min, localisation */
#include "gembem/output.h"       /* run directories and state files */
#include "gembem/run.h"          /* creating and running a simulation through its loading program */
#include "gembem/pack.h"         /* gembem pack: filling a box or a cavity with grains */
#include "gembem/petsc.h"        /* the PETSc linear solver's MPI ranks */

#endif
