// A unit block resting on a long one, one mesh: the lower [0,2.5] x [0,1] x
// [0,0.5] and the upper [0.5,1.5] x [0,1] x [0.50501,1.50501], 1.002
// barrier distances of 0.005 apart (the friction test's d_hat).
// Physical tags (boundary ids): 1 the lower block's bottom z = 0; volume
// tags 1 (lower) and 2 (upper).
// Regenerate: gmsh -3 -format msh41 block_on_block_3d.geo -o block_on_block_3d.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.34;
EndIf
gap = 0.00501;
Box(1) = {0, 0, 0, 2.5, 1, 0.5};
Box(2) = {0.5, 0, 0.5 + gap, 1, 1, 1};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, 2.5 + eps, 1 + eps, eps};
Physical Volume(1) = {1};
Physical Volume(2) = {2};
