// A disk of radius 2 about the origin with a small hole of radius 0.25 at its
// centre (the hole is where a test holds the disk), meshed with triangles:
// 32 equal segments on the outer circle (vertices every 11.25 degrees from
// (2, 0)), 16 on the hole, sizes graded in between.
// Physical tags (boundary ids): 1 the hole's circle, 2 the outer circle;
// surface tag 1.
// Regenerate: gmsh -2 -format msh41 disk_with_hole_2d.geo -o disk_with_hole_2d.msh
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 2};
Disk(2) = {0, 0, 0, 0.25};
BooleanDifference(3) = {Surface{1}; Delete;}{Surface{2}; Delete;};
eps = 1e-6;
outer() = Curve In BoundingBox{-2 - eps, -2 - eps, -eps, 2 + eps, 2 + eps, eps};
inner() = Curve In BoundingBox{-0.25 - eps, -0.25 - eps, -eps, 0.25 + eps, 0.25 + eps, eps};
outer() -= inner();
Transfinite Curve{outer()} = 33;
Transfinite Curve{inner()} = 17;
Physical Curve(1) = {inner()};
Physical Curve(2) = {outer()};
Physical Surface(1) = {3};
