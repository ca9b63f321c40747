// A bent bar (plane strain): the ring 0.8 <= r <= 1 about the origin, open
// at the top by a slot of width 0.1 (the bar's two end faces, x = -0.05 and
// x = 0.05), standing on a flat cut at y = -0.98.
// Physical tags (boundary ids): 1 the flat bottom y = -0.98; 2 and 3 the
// outer arcs near the right and the left end (from 80 down to 60 degrees,
// where a scene grips the bar to bend it; the ends themselves stay free);
// surface tag 1.
// Regenerate: gmsh -2 -format msh41 c_ring_2d.geo -o c_ring_2d.msh
If (!Exists(h))
  h = 0.05;
EndIf
w = 0.05;
Point(100) = {0, 0, 0, h};
Point(1) = {w, Sqrt(1 - w * w), 0, h};
Point(2) = {w, Sqrt(0.64 - w * w), 0, h};
Point(3) = {0.5, Sqrt(0.75), 0, h};
Point(14) = {Cos(80 * Pi / 180), Sin(80 * Pi / 180), 0, h};
Point(15) = {-Cos(80 * Pi / 180), Sin(80 * Pi / 180), 0, h};
Point(9) = {1, 0, 0, h};
Point(4) = {Sqrt(1 - 0.98 * 0.98), -0.98, 0, h};
Point(5) = {-Sqrt(1 - 0.98 * 0.98), -0.98, 0, h};
Point(10) = {-1, 0, 0, h};
Point(6) = {-0.5, Sqrt(0.75), 0, h};
Point(7) = {-w, Sqrt(1 - w * w), 0, h};
Point(8) = {-w, Sqrt(0.64 - w * w), 0, h};
Point(11) = {0.8, 0, 0, h};
Point(12) = {0, -0.8, 0, h};
Point(13) = {-0.8, 0, 0, h};
Circle(1) = {1, 100, 14};
Circle(14) = {14, 100, 3};
Circle(2) = {3, 100, 9};
Circle(3) = {9, 100, 4};
Line(4) = {4, 5};
Circle(5) = {5, 100, 10};
Circle(6) = {10, 100, 6};
Circle(7) = {6, 100, 15};
Circle(15) = {15, 100, 7};
Line(8) = {7, 8};
Circle(9) = {8, 100, 13};
Circle(10) = {13, 100, 12};
Circle(11) = {12, 100, 11};
Circle(12) = {11, 100, 2};
Line(13) = {2, 1};
Curve Loop(1) = {1, 14, 2, 3, 4, 5, 6, 7, 15, 8, 9, 10, 11, 12, 13};
Plane Surface(1) = {1};
Physical Curve(1) = {4};
Physical Curve(2) = {14};
Physical Curve(3) = {7};
Physical Surface(1) = {1};
