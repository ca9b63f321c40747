// Plane-strain block [0,2] x [0,1] with a circular hole of radius 0.25 at
// (1, 0.5), meshed with triangles.
// Physical tags (boundary ids): 1 bottom y = 0, 2 top y = 1, 3 left x = 0,
// 4 right x = 2, 5 the hole; surface tag 1.
// Regenerate: gmsh -2 -format msh41 block_with_hole_2d.geo -o block_with_hole_2d.msh
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 2, 1};
Disk(2) = {1, 0.5, 0, 0.25};
BooleanDifference(3) = {Surface{1}; Delete;}{Surface{2}; Delete;};
Mesh.CharacteristicLengthMax = 0.08;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-eps, -eps, -eps, 2 + eps, eps, eps};
Physical Curve(2) = Curve In BoundingBox{-eps, 1 - eps, -eps, 2 + eps, 1 + eps, eps};
Physical Curve(3) = Curve In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, eps};
Physical Curve(4) = Curve In BoundingBox{2 - eps, -eps, -eps, 2 + eps, 1 + eps, eps};
Physical Curve(5) = Curve In BoundingBox{0.75 - eps, 0.25 - eps, -eps, 1.25 + eps, 0.75 + eps, eps};
Physical Surface(1) = {3};
