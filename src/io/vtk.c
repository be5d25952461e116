/* VTK XML (ASCII) for ParaView: the structure of every VTK file gembem writes (io/vtk.h). */
#include "io/vtk.h"

static const char *type_name(gb_vtk_type type)
{
    return type == GB_VTK_POLYDATA ? "PolyData" : "UnstructuredGrid";
}

void gb_vtk_begin(FILE *f, gb_vtk_type type, int n_points, const char *cells, int n_cells)
{
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"%s\" version=\"0.1\" byte_order=\"LittleEndian\">\n<%s>\n"
               "<Piece NumberOfPoints=\"%d\" %s=\"%d\">\n<Points>\n",
            type_name(type), type_name(type), n_points, cells, n_cells);
    gb_vtk_array(f, "Float64", NULL, 3);
}

void gb_vtk_end_points(FILE *f)
{
    gb_vtk_array_end(f);
    gb_vtk_close(f, "Points");
}

void gb_vtk_open(FILE *f, const char *section, const char *attributes)
{
    fprintf(f, "<%s%s%s>\n", section, attributes ? " " : "", attributes ? attributes : "");
}

void gb_vtk_close(FILE *f, const char *section)
{
    fprintf(f, "</%s>\n", section);
}

void gb_vtk_array(FILE *f, const char *type, const char *name, int components)
{
    fprintf(f, "<DataArray type=\"%s\"", type);
    if (name) fprintf(f, " Name=\"%s\"", name);
    if (components > 1) fprintf(f, " NumberOfComponents=\"%d\"", components);
    fprintf(f, " format=\"ascii\">\n");
}

void gb_vtk_array_end(FILE *f)
{
    fprintf(f, "</DataArray>\n");
}

void gb_vtk_end(FILE *f, gb_vtk_type type)
{
    fprintf(f, "</Piece>\n</%s>\n</VTKFile>\n", type_name(type));
}

void gb_vtk_pvd_head(FILE *f)
{
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n");
}

void gb_vtk_pvd_dataset(FILE *f, int step, const char *file)
{
    fprintf(f, "<DataSet timestep=\"%d\" file=\"%s\"/>\n", step, file);
}
