// Two blocks (plane strain), one mesh, for the frictionless patch test: the
// lower [0,3] x [0,0.5] and the upper [1,1.5] x [0.5 + gap, 1 + gap] (gap = 0.02, h = 0.025).
// Physical tags (boundary ids): 1 the lower block's bottom y = 0, 2 the upper
// block's top; surface tags 1 (lower) and 2 (upper).
// Regenerate: gmsh -2 -format msh41 -setnumber gap 0.02 -setnumber h 0.025 sliding_blocks_2d.geo -o sliding_blocks_2d.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.1;
EndIf
If (!Exists(gap))
  gap = 0.01;
EndIf
Rectangle(1) = {0, 0, 0, 3, 0.5};
Rectangle(2) = {1, 0.5 + gap, 0, 0.5, 0.5};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-eps, -eps, -eps, 3 + eps, eps, eps};
Physical Curve(2) = Curve In BoundingBox{1 - eps, 0.5 + gap + 0.5 - eps, -eps, 1.5 + eps, 0.5 + gap + 0.5 + eps, eps};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
