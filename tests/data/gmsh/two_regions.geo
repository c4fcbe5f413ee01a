// Two stacked unit cubes (volume 2): physical volumes "lower" (volume 1) and "upper"
// (volume 2), and "both" (volumes 1 and 2), so that Gmsh 2.2 lists every tet twice.
SetFactory("Built-in");
lc = 0.5;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
lower[] = Extrude {0, 0, 1} { Surface{1}; };
upper[] = Extrude {0, 0, 1} { Surface{lower[0]}; };
Physical Volume("lower") = {lower[1]};
Physical Volume("upper") = {upper[1]};
Physical Volume("both") = {lower[1], upper[1]};
