// A 10 m slope, 1V:1.5H (the outline of BENCHMARKS.md G5), of two layers:
// "fill" above y = 10 and "foundation" below. Mesh it with
//   gmsh -2 -format msh22 layered-slope.geo -o layered-slope.msh
h = 1.0;
Point(1) = {0, 0, 0, h};
Point(2) = {45, 0, 0, h};
Point(3) = {45, 5, 0, h};
Point(4) = {30, 5, 0, h};
Point(5) = {22.5, 10, 0, h};
Point(6) = {15, 15, 0, h};
Point(7) = {0, 15, 0, h};
Point(8) = {0, 10, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 8};
Line(6) = {8, 1};
Line(7) = {5, 6};
Line(8) = {6, 7};
Line(9) = {7, 8};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {-5, 7, 8, 9};
Plane Surface(2) = {2};
Physical Surface("foundation") = {1};
Physical Surface("fill") = {2};
