// A quarter of a thin slice of a two-layer artery wall: the media
// 1 <= r <= 1.2 and the adventitia 1.2 <= r <= 1.35 about the z axis,
// 0 <= z <= 0.1, x >= 0, y >= 0 (the interface r = 1.2 is a mesh surface).
// Physical tags: surfaces 1 the lumen r = 1, 2 the outer wall r = 1.35,
// 3 the symmetry plane x = 0, 4 the symmetry plane y = 0, 5 z = 0,
// 6 z = 0.1; volumes 1 the media, 2 the adventitia.
// Regenerate: gmsh -3 -format msh41 artery_ring_3d.geo -o artery_ring_3d.msh
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 1.35};
Disk(2) = {0, 0, 0, 1.2};
Disk(3) = {0, 0, 0, 1.0};
Rectangle(4) = {0, 0, 0, 2, 2};
BooleanDifference(5) = {Surface{1}; Delete; }{Surface{2}; };
BooleanDifference(6) = {Surface{2}; Delete; }{Surface{3}; Delete; };
BooleanIntersection(7) = {Surface{5}; Delete; }{Surface{4}; };
BooleanIntersection(8) = {Surface{6}; Delete; }{Surface{4}; Delete; };
Coherence;
Mesh.CharacteristicLengthMin = 0.07;
Mesh.CharacteristicLengthMax = 0.07;
Extrude {0, 0, 0.1} { Surface{:}; Layers{1}; }
Coherence;
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, 1 + eps, 0.1 + eps};
Physical Surface(2) = Surface In BoundingBox{-1.35 - eps, -1.35 - eps, -eps, 1.35 + eps, 1.35 + eps, 0.1 + eps};
Physical Surface(2) -= Surface In BoundingBox{-1.2 - eps, -1.2 - eps, -eps, 1.2 + eps, 1.2 + eps, 0.1 + eps};
Physical Surface(2) -= Surface In BoundingBox{-eps, -eps, -eps, eps, 2, 0.1 + eps};
Physical Surface(2) -= Surface In BoundingBox{-eps, -eps, -eps, 2, eps, 0.1 + eps};
Physical Surface(2) -= Surface In BoundingBox{-eps, -eps, -eps, 2, 2, eps};
Physical Surface(2) -= Surface In BoundingBox{-eps, -eps, 0.1 - eps, 2, 2, 0.1 + eps};
Physical Surface(3) = Surface In BoundingBox{-eps, -eps, -eps, eps, 2, 0.1 + eps};
Physical Surface(4) = Surface In BoundingBox{-eps, -eps, -eps, 2, eps, 0.1 + eps};
Physical Surface(5) = Surface In BoundingBox{-eps, -eps, -eps, 2, 2, eps};
Physical Surface(6) = Surface In BoundingBox{-eps, -eps, 0.1 - eps, 2, 2, 0.1 + eps};
Physical Volume(1) = Volume In BoundingBox{-eps, -eps, -eps, 1.2 + eps, 1.2 + eps, 0.1 + eps};
Physical Volume(2) = Volume In BoundingBox{-eps, -eps, -eps, 1.35 + eps, 1.35 + eps, 0.1 + eps};
Physical Volume(2) -= Volume In BoundingBox{-eps, -eps, -eps, 1.2 + eps, 1.2 + eps, 0.1 + eps};
