// A unit cube meshed by gmsh (make.sh): volume 1, with boundary triangles, edges and
// points that the readers drop.
SetFactory("Built-in");
lc = 0.4;
Point(1) = {0,0,0,lc}; Point(2) = {1,0,0,lc}; Point(3) = {1,1,0,lc}; Point(4) = {0,1,0,lc};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};
Extrude {0,0,1} { Surface{1}; }
Physical Volume("tissue") = {1};
Physical Surface("bottom") = {1};
