// Square body 10 x 10 with an L-shaped cavity: a square of side A with a square of side B cut
// from its top right corner (a re-entrant corner of the host pointing into the grains), centred
// on the body. Cavity area A^2 - B^2 = 14.9 cm^2, legs A - B = 2.1 cm wide.
// Physical groups: "bottom", "right", "top", "left" (for loading the body), "cavity".
L = 10; A = 4.6; B = 2.5; lc = 1.0;
Point(1) = {-L/2, -L/2, 0, lc}; Point(2) = {L/2, -L/2, 0, lc};
Point(3) = {L/2, L/2, 0, lc};   Point(4) = {-L/2, L/2, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {-A/2, -A/2, 0, lc}; Point(6) = {A/2, -A/2, 0, lc};
Point(7) = {A/2, A/2 - B, 0, lc}; Point(8) = {A/2 - B, A/2 - B, 0, lc};
Point(9) = {A/2 - B, A/2, 0, lc}; Point(10) = {-A/2, A/2, 0, lc};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 9}; Line(9) = {9, 10};
Line(10) = {10, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8, 9, 10};
Plane Surface(1) = {1, 2};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("cavity") = {5, 6, 7, 8, 9, 10};
Physical Surface("body") = {1};
