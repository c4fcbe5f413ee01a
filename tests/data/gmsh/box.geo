// A 2 x 1 x 0.5 box (volume 1): physical volume "tissue" and physical surface "bottom".
SetFactory("Built-in");
lc = 0.5;
Point(1) = {0, 0, 0, lc}; Point(2) = {2, 0, 0, lc}; Point(3) = {2, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Extrude {0, 0, 0.5} { Surface{1}; }
Physical Volume("tissue") = {1};
Physical Surface("bottom") = {1};
