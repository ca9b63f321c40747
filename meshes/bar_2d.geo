// Unstructured triangular mesh of the rectangle [0,3] x [0,1].
// Physical tags (boundary ids in hyperelastic): 1 x = 0, 2 x = 3, 3 y = 0,
// 4 y = 1; surface tag 1.
// Regenerate: gmsh -2 -format msh41 bar_2d.geo -o bar_2d.msh
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 3, 1};
Mesh.CharacteristicLengthMax = 0.25;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, eps};
Physical Curve(2) = Curve In BoundingBox{3 - eps, -eps, -eps, 3 + eps, 1 + eps, eps};
Physical Curve(3) = Curve In BoundingBox{-eps, -eps, -eps, 3 + eps, eps, eps};
Physical Curve(4) = Curve In BoundingBox{-eps, 1 - eps, -eps, 3 + eps, 1 + eps, eps};
Physical Surface(1) = {1};
