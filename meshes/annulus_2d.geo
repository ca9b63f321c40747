// Plane-strain hollow cylinder: the annulus 1 <= r <= 2 about the origin,
// meshed with triangles of size about 2 pi / N on the inner circle.
// Physical tags (boundary ids): 1 the inner circle, 2 the outer circle;
// surface tag 1.
// Regenerate: gmsh -2 -format msh41 -setnumber N 16 annulus_2d.geo -o annulus_2d_16.msh
SetFactory("OpenCASCADE");
If (!Exists(N))
  N = 16;
EndIf
Disk(1) = {0, 0, 0, 2};
Disk(2) = {0, 0, 0, 1};
BooleanDifference(3) = {Surface{1}; Delete;}{Surface{2}; Delete;};
Mesh.CharacteristicLengthMin = 2 * Pi / N;
Mesh.CharacteristicLengthMax = 2 * Pi / N;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-1 - eps, -1 - eps, -eps, 1 + eps, 1 + eps, eps};
Physical Curve(2) = Curve In BoundingBox{-2 - eps, -2 - eps, -eps, 2 + eps, 2 + eps, eps};
Physical Curve(2) -= Curve In BoundingBox{-1 - eps, -1 - eps, -eps, 1 + eps, 1 + eps, eps};
Physical Surface(1) = {3};
