// A circular cavity of radius a = 1 in an infinite plane: only the cavity's boundary is meshed;
// the scene says `unbounded: true`. Physical group: "cavity".
a = 1; lc = 0.1;
Point(1) = {0, 0, 0, lc};
Point(2) = {a, 0, 0, lc}; Point(3) = {0, a, 0, lc}; Point(4) = {-a, 0, 0, lc}; Point(5) = {0, -a, 0, lc};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Physical Curve("cavity") = {1, 2, 3, 4};
