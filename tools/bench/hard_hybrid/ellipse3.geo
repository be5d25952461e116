// Square body 10 x 10 with an elliptical cavity of aspect 3 at its centre, its long axis
// horizontal (semi-axes A = 3.9, B = 1.3 cm; area pi A B = 15.9 cm^2).
// Physical groups: "bottom", "right", "top", "left" (for loading the body), "cavity".
L = 10; A = 3.9; B = 1.3; lc = 1.0;
Point(1) = {-L/2, -L/2, 0, lc}; Point(2) = {L/2, -L/2, 0, lc};
Point(3) = {L/2, L/2, 0, lc};   Point(4) = {-L/2, L/2, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {0, 0, 0, lc};
Point(6) = {A, 0, 0, lc}; Point(7) = {0, B, 0, lc}; Point(8) = {-A, 0, 0, lc}; Point(9) = {0, -B, 0, lc};
// Ellipse(tag) = {start, centre, a point on the major axis, end}
Ellipse(5) = {6, 5, 6, 7}; Ellipse(6) = {7, 5, 8, 8}; Ellipse(7) = {8, 5, 8, 9}; Ellipse(8) = {9, 5, 6, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("cavity") = {5, 6, 7, 8};
Physical Surface("body") = {1};
