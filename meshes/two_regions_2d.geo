// Two bonded parts of the rectangle [0,2] x [0,1], split at x = 1 (a mesh
// line): physical surface 1 is x < 1, 2 is x > 1 (the regions test).
// Physical tags of the boundary: 1 x = 0, 2 x = 2, 3 y = 0, 4 y = 1.
// Regenerate: gmsh -2 -format msh41 two_regions_2d.geo -o two_regions_2d.msh
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Rectangle(2) = {1, 0, 0, 1, 1};
BooleanFragments{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Mesh.CharacteristicLengthMax = 0.5;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, eps};
Physical Curve(2) = Curve In BoundingBox{2 - eps, -eps, -eps, 2 + eps, 1 + eps, eps};
Physical Curve(3) = Curve In BoundingBox{-eps, -eps, -eps, 2 + eps, eps, eps};
Physical Curve(4) = Curve In BoundingBox{-eps, 1 - eps, -eps, 2 + eps, 1 + eps, eps};
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, 1 + eps, eps};
Physical Surface(2) = Surface In BoundingBox{1 - eps, -eps, -eps, 2 + eps, 1 + eps, eps};
