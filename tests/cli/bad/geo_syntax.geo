// The square host of meshes/square_cavity.geo with two syntax errors: a stray brace on line 14
// and a missing value on line 16 (lines counted in this file, from 1). gmsh parses on after
// the first; the first is the one to report.
L = 10; R = 2.5; lc = 1.0;
Point(1) = {-L/2, -L/2, 0, lc}; Point(2) = {L/2, -L/2, 0, lc};
Point(3) = {L/2, L/2, 0, lc};   Point(4) = {-L/2, L/2, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {0, 0, 0, lc};
Point(6) = {R, 0, 0, lc}; Point(7) = {0, R, 0, lc}; Point(8) = {-R, 0, 0, lc}; Point(9) = {0, -R, 0, lc};
Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 8}; Circle(7) = {8, 5, 9}; Circle(8) = {9, 5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Point(10) = {0, 0, 0, lc}};
x = 1;
y = ;
Physical Curve("outer") = {1, 2, 3, 4};
Physical Curve("cavity") = {5, 6, 7, 8};
Physical Surface("body") = {1};
