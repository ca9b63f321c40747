// Two bonded parts of the box [0,2] x [0,1] x [0,1], split at x = 1 (a mesh
// plane): physical volume 1 is x < 1, 2 is x > 1 (the regions test).
// Physical tags of the boundary: 1 x = 0, 2 x = 2, 3 y = 0, 4 y = 1,
// 5 z = 0, 6 z = 1.
// Regenerate: gmsh -3 -format msh41 two_regions_3d.geo -o two_regions_3d.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.CharacteristicLengthMax = 0.5;
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, 1 + eps};
Physical Surface(2) = Surface In BoundingBox{2 - eps, -eps, -eps, 2 + eps, 1 + eps, 1 + eps};
Physical Surface(3) = Surface In BoundingBox{-eps, -eps, -eps, 2 + eps, eps, 1 + eps};
Physical Surface(4) = Surface In BoundingBox{-eps, 1 - eps, -eps, 2 + eps, 1 + eps, 1 + eps};
Physical Surface(5) = Surface In BoundingBox{-eps, -eps, -eps, 2 + eps, 1 + eps, eps};
Physical Surface(6) = Surface In BoundingBox{-eps, -eps, 1 - eps, 2 + eps, 1 + eps, 1 + eps};
Physical Volume(1) = Volume In BoundingBox{-eps, -eps, -eps, 1 + eps, 1 + eps, 1 + eps};
Physical Volume(2) = Volume In BoundingBox{1 - eps, -eps, -eps, 2 + eps, 1 + eps, 1 + eps};
