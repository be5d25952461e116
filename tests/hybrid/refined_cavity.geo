// A body as gmsh users draw one (ctest hybrid_mesh_sources): the 10 x 10 square with a
// cavity of radius 2.5 by OpenCASCADE booleans, its elements sized by a field that refines
// towards the cavity (size 0.1 within 0.2 of it, growing to 1 at 3), no element counts anywhere.
SetFactory("OpenCASCADE");
Rectangle(1) = {-5, -5, 0, 10, 10};
Disk(2) = {0, 0, 0, 2.5};
BooleanDifference(3) = {Surface{1}; Delete;}{Surface{2}; Delete;};
c() = Abs(Boundary{Surface{3};});
Physical Curve("outer") = {c(0), c(1), c(2), c(3)};
Physical Curve("cavity") = {c(4)};
Mesh.MeshSizeMax = 1.0;
Field[1] = Distance; Field[1].CurvesList = {c(4)};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = 0.1; Field[2].SizeMax = 1;
Field[2].DistMin = 0.2; Field[2].DistMax = 3;
Background Field = 2;
