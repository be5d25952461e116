// An elliptical cavity (semi-axes a = 2, b = 1) in an infinite plane, its major axis inclined at
// 30 degrees to x: only the cavity's boundary is meshed (the scene or program says unbounded).
// Physical group: "cavity". Used by validation/bem/inclusion.c (the elliptic inclusion).
a = 2; b = 1; th = Pi / 6; lc = 0.1;
Point(1) = {0, 0, 0, lc};
Point(2) = {a, 0, 0, lc}; Point(3) = {0, b, 0, lc}; Point(4) = {-a, 0, 0, lc}; Point(5) = {0, -b, 0, lc};
Ellipse(1) = {2, 1, 2, 3}; Ellipse(2) = {3, 1, 4, 4}; Ellipse(3) = {4, 1, 4, 5}; Ellipse(4) = {5, 1, 2, 2};
Rotate {{0, 0, 1}, {0, 0, 0}, th} { Curve{1, 2, 3, 4}; }
Curve Loop(1) = {1, 2, 3, 4};
Physical Curve("cavity") = {1, 2, 3, 4};
