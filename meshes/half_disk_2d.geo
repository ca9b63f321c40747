// Plane-strain half disk of radius 1 (the lower half of the disk about
// (0, 1)), flat face y = 1 on top, for the Hertz contact test: meshed with
// triangles of size 0.004 near the lowest point (0, 0), growing to 0.1.
// Physical tags (boundary ids): 1 the flat top y = 1, 2 the arc; surface 1.
// Regenerate: gmsh -2 -format msh41 half_disk_2d.geo -o half_disk_2d.msh
SetFactory("OpenCASCADE");
Disk(1) = {0, 1, 0, 1};
Rectangle(2) = {-1.5, 1, 0, 3, 1.5};
BooleanDifference(3) = {Surface{1}; Delete;}{Surface{2}; Delete;};
Point(100) = {0, 0, 0};
Field[1] = Distance;
Field[1].PointsList = {100};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.004;
Field[2].SizeMax = 0.1;
Field[2].DistMin = 0.12;
Field[2].DistMax = 0.6;
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-1 - eps, 1 - eps, -eps, 1 + eps, 1 + eps, eps};
Physical Curve(2) = Curve In BoundingBox{-1 - eps, -eps, -eps, 1 + eps, 1 - eps, eps};
Physical Surface(1) = {3};
