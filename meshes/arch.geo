// Shallow circular arch, clamped at both ends: span 2 a, rise h of the
// midline, thickness d. The crown's top point (0, h + d/2) is a vertex.
// Physical tags (boundary ids): 1 left end, 2 right end, 3 top, 4 bottom;
// surface (2D) or volume (3D) tag 1. In 3D the arch is extruded by the
// width b in z (two layers, so (0, h + d/2, b/2) is a vertex), tags 5
// (z = 0) and 6 (z = b).
// Regenerate: gmsh -2 -format msh41 arch.geo -o arch_2d.msh
//             gmsh -3 -setnumber three_d 1 -format msh41 arch.geo -o arch_3d.msh
If (!Exists(three_d))
  three_d = 0;
EndIf
a = 1; h = 0.2; d = 0.02; b = 0.1;
nx = 30; ny = 3;
R = (a * a + h * h) / (2 * h);
Point(1) = {0, h - R, 0};
Point(2) = {-a * (R + d / 2) / R, (h - R) + (R - h) * (R + d / 2) / R, 0};
Point(3) = {0, h + d / 2, 0};
Point(4) = {a * (R + d / 2) / R, (h - R) + (R - h) * (R + d / 2) / R, 0};
Point(5) = {-a * (R - d / 2) / R, (h - R) + (R - h) * (R - d / 2) / R, 0};
Point(6) = {0, h - d / 2, 0};
Point(7) = {a * (R - d / 2) / R, (h - R) + (R - h) * (R - d / 2) / R, 0};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4};
Circle(3) = {5, 1, 6}; Circle(4) = {6, 1, 7};
Line(5) = {5, 2}; Line(6) = {6, 3}; Line(7) = {7, 4};
Curve Loop(1) = {3, 6, -1, -5}; Plane Surface(1) = {1};
Curve Loop(2) = {4, 7, -2, -6}; Plane Surface(2) = {2};
Transfinite Curve{1, 2, 3, 4} = nx + 1;
Transfinite Curve{5, 6, 7} = ny + 1;
Transfinite Surface{1} Alternate; Transfinite Surface{2} Alternate;
If (three_d == 0)
  Physical Curve(1) = {5};
  Physical Curve(2) = {7};
  Physical Curve(3) = {1, 2};
  Physical Curve(4) = {3, 4};
  Physical Surface(1) = {1, 2};
Else
  e1[] = Extrude {0, 0, b} { Surface{1}; Layers{2}; };
  e2[] = Extrude {0, 0, b} { Surface{2}; Layers{2}; };
  // e[0] top (z = b), e[1] volume, e[2..5] the sides from the loop's curves
  Physical Surface(1) = {e1[5]};
  Physical Surface(2) = {e2[3]};
  Physical Surface(3) = {e1[4], e2[4]};
  Physical Surface(4) = {e1[2], e2[2]};
  Physical Surface(5) = {1, 2};
  Physical Surface(6) = {e1[0], e2[0]};
  Physical Volume(1) = {e1[1], e2[1]};
EndIf
