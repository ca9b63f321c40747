// Unstructured tetrahedral mesh of the bar [0,3] x [0,1] x [0,1].
// Physical tags (boundary ids in hyperelastic): 1 x = 0, 2 x = 3, 3 y = 0,
// 4 y = 1, 5 z = 0, 6 z = 1; volume tag 1.
// Regenerate: gmsh -3 -format msh41 bar_3d.geo -o bar_3d.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 3, 1, 1};
Mesh.CharacteristicLengthMax = 0.4;
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, 1 + eps};
Physical Surface(2) = Surface In BoundingBox{3 - eps, -eps, -eps, 3 + eps, 1 + eps, 1 + eps};
Physical Surface(3) = Surface In BoundingBox{-eps, -eps, -eps, 3 + eps, eps, 1 + eps};
Physical Surface(4) = Surface In BoundingBox{-eps, 1 - eps, -eps, 3 + eps, 1 + eps, 1 + eps};
Physical Surface(5) = Surface In BoundingBox{-eps, -eps, -eps, 3 + eps, 1 + eps, eps};
Physical Surface(6) = Surface In BoundingBox{-eps, -eps, 1 - eps, 3 + eps, 1 + eps, 1 + eps};
Physical Volume(1) = {1};
