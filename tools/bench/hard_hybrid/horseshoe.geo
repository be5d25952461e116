// Square body 10 x 10 with a horseshoe-shaped cavity (an arch with two straight legs, open at
// the bottom: the host bulges into it between the legs). Outer radius R1, inner R2, legs H long
// below the arch's centre at (0, C). Cavity area pi/2 (R1^2 - R2^2) + 2 H (R1 - R2) = 15.2 cm^2.
// Physical groups: "bottom", "right", "top", "left" (for loading the body), "cavity".
L = 10; R1 = 2.8; R2 = 1.2; H = 1.6; C = -0.6; lc = 1.0;
Point(1) = {-L/2, -L/2, 0, lc}; Point(2) = {L/2, -L/2, 0, lc};
Point(3) = {L/2, L/2, 0, lc};   Point(4) = {-L/2, L/2, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {0, C, 0, lc};                                   // the arch's centre
Point(6) = {R1, C, 0, lc};  Point(7) = {0, C + R1, 0, lc};  Point(8) = {-R1, C, 0, lc};
Point(9) = {-R1, C - H, 0, lc}; Point(10) = {-R2, C - H, 0, lc}; Point(11) = {-R2, C, 0, lc};
Point(12) = {0, C + R2, 0, lc}; Point(13) = {R2, C, 0, lc}; Point(14) = {R2, C - H, 0, lc};
Point(15) = {R1, C - H, 0, lc};
Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 8};               // the outer arch
Line(7) = {8, 9}; Line(8) = {9, 10}; Line(9) = {10, 11};    // the left leg
Circle(10) = {11, 5, 12}; Circle(11) = {12, 5, 13};         // the inner arch
Line(12) = {13, 14}; Line(13) = {14, 15}; Line(14) = {15, 6}; // the right leg
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
Plane Surface(1) = {1, 2};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("cavity") = {5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
Physical Surface("body") = {1};
