// The shallow ironing benchmark (plane strain, mm), both bodies in one mesh:
// the geometry of solids4foam's hyperElasticity/shallowIroning (after
// Yastrebov 2011 and Code_Aster SSNP153).
// - the foundation [0,12] x [0,4];
// - the slab above its left end: x in [0.2, 1.4], straight sides from y = 4.5
//   up to its top y = 5.4, and below a circular arc of radius 0.75 (centre
//   (0.8, 4.95)) from (0.2, 4.5) to (1.4, 4.5) whose lowest point (0.8, 4.2)
//   is 0.2 above the foundation.
// h is the element size on the contact edges (the foundation's top and the
// whole slab); h_bottom the size at the foundation's bottom corners, graded
// linearly up to its top.
// Physical tags (boundary ids): 1 the foundation's bottom y = 0 (clamped),
// 2 the slab's top y = 5.4 (moved); surface tags 1 (foundation) and 2 (slab).
// Regenerate (h = 0.25 for parameters/shallow_ironing_2d.prm, 0.1 for the
// benchmark's fine run):
//   gmsh -2 -format msh41 -setnumber h 0.25 shallow_ironing_2d.geo -o shallow_ironing_2d.msh
If (!Exists(h))
  h = 0.1;
EndIf
If (!Exists(h_bottom))
  h_bottom = 0.5;
EndIf

// The foundation.
Point(1) = {0, 0, 0, h_bottom};
Point(2) = {12, 0, 0, h_bottom};
Point(3) = {12, 4, 0, h};
Point(4) = {0, 4, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// The slab: the bottom arc, the right side, the top, the left side.
Point(5) = {0.2, 4.5, 0, h};
Point(6) = {1.4, 4.5, 0, h};
Point(7) = {1.4, 5.4, 0, h};
Point(8) = {0.2, 5.4, 0, h};
Point(9) = {0.8, 4.95, 0, h};            // the arc's centre, not meshed
Circle(5) = {5, 9, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};

Physical Curve(1) = {1};
Physical Curve(2) = {7};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
