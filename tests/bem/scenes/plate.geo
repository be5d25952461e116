// A 2 x 2 square with one physical group per side (scene tests).
Point(1) = {-1, -1, 0, 0.25}; Point(2) = {1, -1, 0, 0.25}; Point(3) = {1, 1, 0, 0.25}; Point(4) = {-1, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Physical Curve("bottom") = {1}; Physical Curve("right") = {2}; Physical Curve("top") = {3}; Physical Curve("left") = {4};
