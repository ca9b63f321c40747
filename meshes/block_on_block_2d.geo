// A unit block (plane strain) resting on a long one, one mesh: the lower
// [0,2.5] x [0,0.5] and the upper [0.5,1.5] x [0.50501,1.50501], 1.002
// barrier distances of 0.005 apart (the friction test's d_hat).
// Physical tags (boundary ids): 1 the lower block's bottom y = 0; surface
// tags 1 (lower) and 2 (upper).
// Regenerate: gmsh -2 -format msh41 block_on_block_2d.geo -o block_on_block_2d.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.25;
EndIf
gap = 0.00501;
Rectangle(1) = {0, 0, 0, 2.5, 0.5};
Rectangle(2) = {0.5, 0.5 + gap, 0, 1, 1};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-eps, -eps, -eps, 2.5 + eps, eps, eps};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
