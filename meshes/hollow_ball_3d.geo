// A hollow ball: the shell 0.7 <= r <= 1 about the origin, standing on a
// flat cut at z = -0.98.
// Physical tags (boundary ids): 1 the flat bottom z = -0.98; volume tag 1.
// Regenerate (h sets the size; the benchmark makes finer ones):
//   gmsh -3 -format msh41 -setnumber h 0.15 hollow_ball_3d.geo -o hollow_ball_3d.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.15;
EndIf
Sphere(1) = {0, 0, 0, 1};
Sphere(2) = {0, 0, 0, 0.7};
Box(3) = {-1.5, -1.5, -1.5, 3, 3, 0.52};
BooleanDifference(5) = {Volume{1}; Delete;}{Volume{2, 3}; Delete;};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-1, -1, -0.98 - eps, 1, 1, -0.98 + eps};
Physical Volume(1) = {5};
