// Two blocks, one mesh, for the frictionless patch test: the lower
// [0,3] x [0,1] x [0,0.3] and the upper [1.125,1.625] x [0.25,0.75] x
// [0.3 + gap, 0.6 + gap]; the mesh size h near the contact faces, 3 h at 0.3 away.
// Physical tags (boundary ids): 1 the lower block's bottom z = 0, 2 the upper
// block's top; volume tags 1 (lower) and 2 (upper).
// Regenerate: gmsh -3 -format msh41 sliding_blocks_3d.geo -o sliding_blocks_3d.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.05;
EndIf
If (!Exists(gap))
  gap = 0.02;
EndIf
Box(1) = {0, 0, 0, 3, 1, 0.3};
Box(2) = {1.125, 0.25, 0.3 + gap, 0.5, 0.5, 0.3};
Field[1] = MathEval;
Field[1].F = Sprintf("%g + 2 * %g * Min(1, Fabs(z - 0.3) / 0.3)", h, h);
Background Field = 1;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, 3 + eps, 1 + eps, eps};
Physical Surface(2) = Surface In BoundingBox{1.125 - eps, 0.25 - eps, 0.6 + gap - eps, 1.625 + eps, 0.75 + eps, 0.6 + gap + eps};
Physical Volume(1) = {1};
Physical Volume(2) = {2};
