// gmsh: -3
// A 3D mesh (a meshed volume) with physical curves: refused.
SetFactory("OpenCASCADE");
Box(1) = {-5, -5, 0, 10, 10, 10};
Physical Curve("outer") = {1, 2, 3, 4};
Physical Curve("cavity") = {5, 6, 7, 8};
Physical Volume("solid") = {1};
