// The bar [0,L] x [0,1] x [0,1] of meshes/bar_3d.geo (L = 3 unless given)
// with the mesh size h a parameter:
//   gmsh -3 -format msh41 -setnumber h 0.025 bar_big.geo -o bar_big.msh
// gives about 875,000 tetrahedra (150,352 nodes, 39 MB); with
// -setnumber L 4 it is the benchmark's twisted bar (4 x 1 x 1).
If (!Exists(L))
  L = 3;
EndIf
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, L, 1, 1};
Mesh.CharacteristicLengthMax = h;
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, 1 + eps};
Physical Surface(2) = Surface In BoundingBox{L - eps, -eps, -eps, L + eps, 1 + eps, 1 + eps};
Physical Surface(3) = Surface In BoundingBox{-eps, -eps, -eps, L + eps, eps, 1 + eps};
Physical Surface(4) = Surface In BoundingBox{-eps, 1 - eps, -eps, L + eps, 1 + eps, 1 + eps};
Physical Surface(5) = Surface In BoundingBox{-eps, -eps, -eps, L + eps, 1 + eps, eps};
Physical Surface(6) = Surface In BoundingBox{-eps, -eps, 1 - eps, L + eps, 1 + eps, 1 + eps};
Physical Volume(1) = {1};
