// Two separate blocks (plane strain), one mesh, a gap far below 1e-3 of
// the diagonal: the lower [0,1] x [0,0.5] and the upper
// [0.25,0.75] x [0.5004,1.0004], 4e-4 apart (issue 43: the automatic
// d_hat is half the smallest reference gap, 2e-4).
// Physical tags (boundary ids): 1 the lower block's bottom y = 0, 2 the
// upper block's top y = 1.0004; surface tags 1 (lower) and 2 (upper).
// Regenerate: gmsh -2 -format msh41 close_blocks_2d.geo -o close_blocks_2d.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.1;
EndIf
gap = 4e-4;
Rectangle(1) = {0, 0, 0, 1, 0.5};
Rectangle(2) = {0.25, 0.5 + gap, 0, 0.5, 0.5};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-eps, -eps, -eps, 1 + eps, eps, eps};
Physical Curve(2) = Curve In BoundingBox{0.25 - eps, 1 + gap - eps, -eps, 0.75 + eps, 1 + gap + eps, eps};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
