// Two separate blocks, one mesh: the lower [0,1]^2 x [0,0.5] and the upper
// [0.25,0.75]^2 x [0.52,1.02], 0.02 apart.
// Physical tags (boundary ids): 1 the lower block's bottom z = 0, 2 the
// upper block's top z = 1.02; volume tags 1 (lower) and 2 (upper).
// Regenerate: gmsh -3 -format msh41 two_blocks_3d.geo -o two_blocks_3d.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.2;
EndIf
Box(1) = {0, 0, 0, 1, 1, 0.5};
Box(2) = {0.25, 0.25, 0.52, 0.5, 0.5, 0.5};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, 1 + eps, eps};
Physical Surface(2) = Surface In BoundingBox{0.25 - eps, 0.25 - eps, 1.02 - eps, 0.75 + eps, 0.75 + eps, 1.02 + eps};
Physical Volume(1) = {1};
Physical Volume(2) = {2};
