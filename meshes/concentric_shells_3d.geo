// Two concentric hemispherical shells, a quarter of them (x, y >= 0):
// the inner 0.9 <= r <= 1, the outer 1.02 <= r <= 1.12, 0.02 apart, every
// arc divided into the same n equal angles, so that the facing edges on the
// symmetry planes x = 0 and y = 0 and on the rim z = 0 are parallel (issue
// 43: such edges were taken as 0 apart).
// Physical tags (boundary ids): 1 the inner face r = 0.9, 2 the outer face
// r = 1.12, 3 the symmetry plane x = 0, 4 the symmetry plane y = 0; volume
// tags 1 (inner shell) and 2 (outer shell).
// Regenerate: gmsh -3 -format msh41 concentric_shells_3d.geo -o concentric_shells_3d.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.15;
EndIf
If (!Exists(n))
  n = 10;
EndIf
Sphere(1) = {0, 0, 0, 1, 0, Pi/2, Pi/2};
Sphere(2) = {0, 0, 0, 0.9, 0, Pi/2, Pi/2};
BooleanDifference(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Sphere(4) = {0, 0, 0, 1.12, 0, Pi/2, Pi/2};
Sphere(5) = {0, 0, 0, 1.02, 0, Pi/2, Pi/2};
BooleanDifference(6) = {Volume{4}; Delete;}{Volume{5}; Delete;};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
// The arcs (every curve longer than the shells' thickness): n equal angles.
arcs() = Curve{:};
For i In {0:#arcs() - 1}
  bb() = BoundingBox Curve{arcs(i)};
  If ((bb(3) - bb(0)) + (bb(4) - bb(1)) + (bb(5) - bb(2)) > 0.5)
    Transfinite Curve{arcs(i)} = n + 1;
  EndIf
EndFor
eps = 1e-6;
// The spherical faces: their boxes extend in all three directions.
faces() = Surface{:};
inner() = {};
outer() = {};
For i In {0:#faces() - 1}
  bb() = BoundingBox Surface{faces(i)};
  If (bb(3) - bb(0) > 0.5 && bb(4) - bb(1) > 0.5 && bb(5) - bb(2) > 0.5)
    If (Fabs(bb(3) - 0.9) < 1e-3)
      inner() += {faces(i)};
    EndIf
    If (Fabs(bb(3) - 1.12) < 1e-3)
      outer() += {faces(i)};
    EndIf
  EndIf
EndFor
Physical Surface(1) = {inner()};
Physical Surface(2) = {outer()};
Physical Surface(3) = Surface In BoundingBox{-eps, -eps, -eps, eps, 1.2, 1.2};
Physical Surface(4) = Surface In BoundingBox{-eps, -eps, -eps, 1.2, eps, 1.2};
Physical Volume(1) = {3};
Physical Volume(2) = {6};
