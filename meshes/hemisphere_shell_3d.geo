// A quarter of a thin hemispherical shell (x >= 0, y >= 0): mid-surface
// radius R = 1 about the origin, thickness t = 0.02 (R/t = 50), polar angle
// 0 ... deg degrees from the z axis (90: the hemisphere; the apex's outer
// point (0, 0, R + t/2) is a vertex). Meshed with tetrahedra of size lc
// (about one through the thickness).
// Physical tags (boundary ids): 1 the rim (polar angle deg), 2 the symmetry
// plane x = 0, 3 the symmetry plane y = 0; volume 1.
// Regenerate: gmsh -3 -format msh41 hemisphere_shell_3d.geo -o hemisphere_shell_3d.msh
SetFactory("OpenCASCADE");
R = 1;
If (!Exists(t))
  t = 0.02;
EndIf
If (!Exists(deg))
  deg = 90;
EndIf
If (!Exists(lc))
  lc = 0.06;
EndIf
th = deg * Pi / 180;
Ri = R - t / 2; Ro = R + t / 2;
Point(1) = {0, 0, 0, lc};
Point(2) = {0, 0, Ri, lc}; Point(3) = {0, 0, Ro, lc};
Point(4) = {Ro * Sin(th), 0, Ro * Cos(th), lc};
Point(5) = {Ri * Sin(th), 0, Ri * Cos(th), lc};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
out[] = Extrude {{0, 0, 1}, {0, 0, 0}, Pi / 2} {Surface{1};};
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-2, -2, Ri * Cos(th) - eps, 2, 2, Ro * Cos(th) + eps};
Physical Surface(2) = Surface In BoundingBox{-eps, -2, -2, eps, 2, 2};
Physical Surface(3) = Surface In BoundingBox{-2, -eps, -2, 2, eps, 2};
Physical Volume(1) = {out[1]};
Mesh.CharacteristicLengthMax = lc;
