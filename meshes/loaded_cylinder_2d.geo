// A thick-walled cylinder as measured under load (plane strain): the
// annulus a <= r <= 2.2 with a = 1.4234377353573, the loaded radii of the
// neo-Hookean cylinder 1 <= R <= 2 (E = 1, nu = 0.3) inflated by p = 0.3
// with its outer surface moved to r = 2.2 (the radial reference of
// tests/support/radial_inflation.h); triangles of size about 2 pi a / N on
// the inner circle. Physical tags (boundary ids): 1 the inner circle, 2 the
// outer circle; surface tag 1. parameters/unloaded_cylinder_2d.prm finds
// its unloaded shape.
// Regenerate: gmsh -2 -format msh41 loaded_cylinder_2d.geo -o loaded_cylinder_2d.msh
SetFactory("OpenCASCADE");
If (!Exists(N))
  N = 32;
EndIf
a = 1.4234377353573;
b = 2.2;
Disk(1) = {0, 0, 0, b};
Disk(2) = {0, 0, 0, a};
BooleanDifference(3) = {Surface{1}; Delete;}{Surface{2}; Delete;};
Mesh.CharacteristicLengthMin = 2 * Pi * a / N;
Mesh.CharacteristicLengthMax = 2 * Pi * a / N;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-a - eps, -a - eps, -eps, a + eps, a + eps, eps};
Physical Curve(2) = Curve In BoundingBox{-b - eps, -b - eps, -eps, b + eps, b + eps, eps};
Physical Curve(2) -= Curve In BoundingBox{-a - eps, -a - eps, -eps, a + eps, a + eps, eps};
Physical Surface(1) = {3};
