// Plane-strain section of a bonded rubber bushing: a steel sleeve
// 0.5 <= r <= 0.6 vulcanised to a rubber ring 0.6 <= r <= 1.5 about the
// origin (the interface r = 0.6 is a mesh line).
// Physical tags: boundary 1 the inner circle r = 0.5 (the shaft), 2 the outer
// circle r = 1.5 (the housing); surface 1 the steel sleeve, 2 the rubber.
// Regenerate: gmsh -2 -format msh41 bushing_2d.geo -o bushing_2d.msh
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 1.5};
Disk(2) = {0, 0, 0, 0.6};
Disk(3) = {0, 0, 0, 0.5};
BooleanDifference(4) = {Surface{1}; }{Surface{2}; };
BooleanDifference(5) = {Surface{2}; Delete; }{Surface{3}; Delete; };
Delete { Surface{1}; }
Coherence;
Mesh.CharacteristicLengthMin = 0.08;
Mesh.CharacteristicLengthMax = 0.12;
eps = 1e-6;
Physical Curve(1) = Curve In BoundingBox{-0.5 - eps, -0.5 - eps, -eps, 0.5 + eps, 0.5 + eps, eps};
Physical Curve(2) = Curve In BoundingBox{-1.5 - eps, -1.5 - eps, -eps, 1.5 + eps, 1.5 + eps, eps};
Physical Curve(2) -= Curve In BoundingBox{-0.6 - eps, -0.6 - eps, -eps, 0.6 + eps, 0.6 + eps, eps};
Physical Surface(1) = Surface In BoundingBox{-0.6 - eps, -0.6 - eps, -eps, 0.6 + eps, 0.6 + eps, eps};
Physical Surface(2) = Surface In BoundingBox{-1.5 - eps, -1.5 - eps, -eps, 1.5 + eps, 1.5 + eps, eps};
Physical Surface(2) -= Surface In BoundingBox{-0.6 - eps, -0.6 - eps, -eps, 0.6 + eps, 0.6 + eps, eps};
