// Square body 10 x 10 with an irregular, non-convex (kidney-shaped) cavity: a closed spline.
// Physical groups: "outer" (the four sides) and "cavity".
L = 10; lc = 0.5;
Point(1) = {-L/2, -L/2, 0, lc}; Point(2) = {L/2, -L/2, 0, lc};
Point(3) = {L/2, L/2, 0, lc};   Point(4) = {-L/2, L/2, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(10) = {2.5, 0.0, 0, lc};  Point(11) = {2.0, 1.8, 0, lc};  Point(12) = {0.3, 2.2, 0, lc};
Point(13) = {-0.4, 0.9, 0, lc}; Point(14) = {-1.8, 1.9, 0, lc}; Point(15) = {-2.7, 0.2, 0, lc};
Point(16) = {-2.0, -1.9, 0, lc}; Point(17) = {0.2, -2.4, 0, lc}; Point(18) = {2.1, -1.6, 0, lc};
Spline(5) = {10, 11, 12, 13, 14, 15, 16, 17, 18, 10};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5};
Plane Surface(1) = {1, 2};
Physical Curve("outer") = {1, 2, 3, 4};
Physical Curve("cavity") = {5};
Physical Surface("body") = {1};
