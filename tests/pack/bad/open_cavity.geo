// A square body whose "cavity" is a polyline that does not close: refused (not a closed loop).
Point(1) = {-5, -5, 0, 1}; Point(2) = {5, -5, 0, 1}; Point(3) = {5, 5, 0, 1}; Point(4) = {-5, 5, 0, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {-1, -1, 0, 0.3}; Point(6) = {1, -1, 0, 0.3}; Point(7) = {1, 1, 0, 0.3}; Point(8) = {-1, 1, 0, 0.3};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8};
Physical Curve("outer") = {1, 2, 3, 4};
Physical Curve("cavity") = {5, 6, 7};
