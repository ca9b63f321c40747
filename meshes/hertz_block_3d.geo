// Quarter of a half-space block for the 3D Hertz test: [0, L] x [0, L] x
// [-L, 0], its top z = 0 indented at the origin (the contact's centre, on
// the symmetry planes x = 0 and y = 0). Tetrahedra of size hmin within
// rfine of the origin, growing linearly with the distance (slope k) up to
// hmax. The defaults (hmin 0.002 within 0.03, slope 0.12: 7,222 vertices)
// are the ctest's; the grading a few contact radii around the contact
// decides the force's accuracy more than hmin does
// (benchmarks/contact/README.md).
// Physical tags (boundary ids): 1 x = 0, 2 y = 0, 3 the bottom z = -L,
// 4 the top z = 0, 5 x = L, 6 y = L; volume tag 1.
// Regenerate:
//   gmsh -3 -format msh41 hertz_block_3d.geo -o hertz_block_3d.msh
SetFactory("OpenCASCADE");
If (!Exists(L))
  L = 1;
EndIf
If (!Exists(hmin))
  hmin = 0.002;
EndIf
If (!Exists(rfine))
  rfine = 0.03;
EndIf
If (!Exists(k))
  k = 0.12;
EndIf
If (!Exists(hmax))
  hmax = 0.25;
EndIf
Box(1) = {0, 0, -L, L, L, L};
Point(100) = {0, 0, 0};
Field[1] = Distance;
Field[1].PointsList = {100};
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g, %g + %g * Max(0, F1 - %g))", hmax, hmin, k, rfine);
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthFromCurvature = 0;
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -L - eps, eps, L + eps, eps};
Physical Surface(2) = Surface In BoundingBox{-eps, -eps, -L - eps, L + eps, eps, eps};
Physical Surface(3) = Surface In BoundingBox{-eps, -eps, -L - eps, L + eps, L + eps, -L + eps};
Physical Surface(4) = Surface In BoundingBox{-eps, -eps, -eps, L + eps, L + eps, eps};
Physical Surface(5) = Surface In BoundingBox{L - eps, -eps, -L - eps, L + eps, L + eps, eps};
Physical Surface(6) = Surface In BoundingBox{-eps, L - eps, -L - eps, L + eps, L + eps, eps};
Physical Volume(1) = {1};
