// The upper half of an artery ring (plane strain): 1 <= r <= 1.3 about the
// origin, y >= 0, meshed with triangles of size h.
// Physical tags (boundary ids): 1 the inner (luminal) arc, 2 the outer arc,
// 3 the radial face at theta = 0 (x > 0), 4 the radial face at theta = pi
// (x < 0); surface tag 1.
// Regenerate: gmsh -2 -format msh41 half_ring_2d.geo -o half_ring_2d.msh
If (!Exists(h))
  h = 0.04;
EndIf
Point(100) = {0, 0, 0, h};
Point(1) = {1, 0, 0, h};
Point(2) = {1.3, 0, 0, h};
Point(3) = {0, 1.3, 0, h};
Point(4) = {-1.3, 0, 0, h};
Point(5) = {-1, 0, 0, h};
Point(6) = {0, 1, 0, h};
Line(1) = {1, 2};
Circle(2) = {2, 100, 3};
Circle(3) = {3, 100, 4};
Line(4) = {4, 5};
Circle(5) = {5, 100, 6};
Circle(6) = {6, 100, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Physical Curve(1) = {5, 6};
Physical Curve(2) = {2, 3};
Physical Curve(3) = {1};
Physical Curve(4) = {4};
Physical Surface(1) = {1};
