// A hollow ball in plane strain: the ring 0.7 <= r <= 1 about the origin,
// standing on a flat cut at y = -0.98.
// Physical tags (boundary ids): 1 the flat bottom y = -0.98; surface tag 1.
// Regenerate: gmsh -2 -format msh41 hollow_disk_2d.geo -o hollow_disk_2d.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.06;
EndIf
Disk(1) = {0, 0, 0, 1};
Disk(2) = {0, 0, 0, 0.7};
Rectangle(4) = {-1.5, -1.5, 0, 3, 0.52};
BooleanDifference(5) = {Surface{1}; Delete;}{Surface{2, 4}; Delete;};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-1, -0.98 - eps, -eps, 1, -0.98 + eps, eps};
Physical Surface(1) = {5};
