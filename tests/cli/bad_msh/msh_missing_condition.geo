// gmsh: -1
// A group of the mesh (outer) without a condition in the scene.
L = 10; C = 4; lc = 1; z = 0;
Point(1) = {-L/2, -L/2, z, lc}; Point(2) = {L/2, -L/2, z, lc}; Point(3) = {L/2, L/2, z, lc}; Point(4) = {-L/2, L/2, z, lc};
Point(5) = {-C/2, -C/2, z, lc}; Point(6) = {C/2, -C/2, z, lc}; Point(7) = {C/2, C/2, z, lc}; Point(8) = {-C/2, C/2, z, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Physical Curve("outer") = {1, 2, 3, 4}; Physical Curve("cavity") = {5, 6, 7, 8};
