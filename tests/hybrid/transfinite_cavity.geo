// meshes/square_cavity.geo with its cavity's arcs divided by Transfinite Curve (12 elements each),
// as a gmsh user sets counts in the file itself (ctest hybrid_mesh_sources).
Include "../../meshes/square_cavity.geo";
Transfinite Curve{5, 6, 7, 8} = 13;
