// SPDX-License-Identifier: MIT
// Plane-strain extrusion through a 45° wedge die (upper half): container
// [0, 10] × [0, 10], a straight die face from (10, 10) down to (15, 5), exit
// [15, 25] × [0, 5] (50 % reduction). Recombined quad-9 cells of size about
// 1.25, finer (0.5) at the die exit corner where the strain rate is singular.
// Regenerate wedge-die.msh with the Gmsh app:
//   gmsh cases/meshes/wedge-die.geo -2 -format msh41 -o cases/meshes/wedge-die.msh
h = 1.25;
Point(1) = {0, 0, 0, h};
Point(2) = {25, 0, 0, h};
Point(3) = {25, 5, 0, h};
Point(4) = {15, 5, 0, 0.4 * h};  // the die exit corner
Point(6) = {10, 10, 0, h};
Point(7) = {0, 10, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 6};
Line(5) = {6, 7};
Line(6) = {7, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
// The names a user would choose; the case file maps them to formflow's parts.
Physical Curve("axis") = {1};
Physical Curve("front_cut") = {2};
Physical Curve("product_surface") = {3};
Physical Curve("die_face") = {4};
Physical Curve("billet_wall") = {5};
Physical Curve("ram") = {6};
Physical Surface("billet") = {1};
Mesh.Algorithm = 6;               // Frontal-Delaunay ...
Mesh.RecombinationAlgorithm = 3;  // ... recombined by blossom into all quadrilaterals
Mesh.RecombineAll = 1;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;   // quad-9, not the 8-node serendipity quad
