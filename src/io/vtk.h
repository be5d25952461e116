/* VTK XML files (ASCII) for ParaView, written one way everywhere: the grains' and contacts'
 * snapshots, the strain field's triangles, the host's boundary and interior, and the .pvd
 * collections that put a run's files on ParaView's time bar. A writer calls these in its file's
 * order and prints each array's numbers itself, one item a line. */
#ifndef GB_IO_VTK_H
#define GB_IO_VTK_H

#include <stdio.h>

typedef enum { GB_VTK_POLYDATA, GB_VTK_UNSTRUCTURED_GRID } gb_vtk_type;

/* From the XML declaration to the points' array, left open for their "x y 0" lines. `cells` names
 * the piece's count of cells: "NumberOfVerts", "NumberOfLines" or "NumberOfCells". */
void gb_vtk_begin(FILE *f, gb_vtk_type type, int n_points, const char *cells, int n_cells);
/* Closes the points' array. */
void gb_vtk_end_points(FILE *f);
/* <section attributes> ... </section>: "PointData", "CellData", "Verts", "Lines", "Cells";
 * attributes (NULL: none) such as "Scalars=\"radius\"". */
void gb_vtk_open(FILE *f, const char *section, const char *attributes);
void gb_vtk_close(FILE *f, const char *section);
/* A data array of `type` ("Float64", "Int32", "Int64", "UInt8"), `components` numbers an item (1:
 * no NumberOfComponents attribute); gb_vtk_array_end closes it. */
void gb_vtk_array(FILE *f, const char *type, const char *name, int components);
void gb_vtk_array_end(FILE *f);
/* Closes the piece and the file. */
void gb_vtk_end(FILE *f, gb_vtk_type type);

/* A collection (.pvd): its head, a line a data set, its tail. The tail is a constant so that a
 * collection that grows step by step can seek back over it. */
#define GB_VTK_PVD_TAIL "</Collection>\n</VTKFile>\n"
void gb_vtk_pvd_head(FILE *f);
void gb_vtk_pvd_dataset(FILE *f, int step, const char *file);

#endif
