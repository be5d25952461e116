/* Files of an elastic body's solution (`gembem bem`, and a hybrid run's host): boundary CSV and VTK
 * polydata, interior VTK unstructured grid and CSV, the condensed stiffness. Full precision (%.17g). */
#ifndef GB_IO_BEM_OUTPUT_H
#define GB_IO_BEM_OUTPUT_H

#include "gembem/scene.h"

gb_status gb_bem_write_boundary_csv(const char *path, const gb_bem_mesh *m, const gb_bem_solution *sol,
                                    const double *bstress, gb_error *err);
gb_status gb_bem_write_boundary_vtp(const char *path, const gb_bem_mesh *m, const gb_bem_solution *sol, gb_error *err);
/* Points with inside[i] = 0 are left out; a grid (nx x ny first points) gets quad cells whose four
 * corners are inside, the other points vertex cells. u: 2 per point, s: 3 per point. */
gb_status gb_bem_write_interior_vtu(const char *path, const gb_bem_scene *sc, const double *u, const double *s,
                                    gb_error *err);
gb_status gb_bem_write_interior_csv(const char *path, const gb_bem_scene *sc, const double *u, const double *s,
                                    gb_error *err);
gb_status gb_bem_write_stiffness_csv(const char *path, const gb_bem_mesh *m, const gb_bem_stiffness *k, gb_error *err);

#endif
