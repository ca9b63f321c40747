// The twisting hemisphere (Sauer and De Lorenzis 2015; Zimmerman and
// Ateshian 2018, FEBio; solids4foam's twistingHemisphere): a hollow
// hemisphere (outer radius 1, inner 0.5) above the block [-1, 1]^2 x [0, 2],
// its lowest point a gap g above the block's top. Two volumes of one mesh:
// physical volume 1 the block, 2 the hemisphere; physical surface 1 the
// block's bottom z = 0, 2 the hemisphere's flat top (the annulus z = 2 + g +
// 1). Element size h on the hemisphere and the block's top within 1.2 of
// the axis, growing to 3 h elsewhere.
//   gmsh -3 -format msh22 -setnumber h 0.1 twisting_hemisphere.geo -o MESH
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.1;
EndIf
g = 0.01;
L = 2;
zc = L + g + 1;
Box(1) = {-1, -1, 0, 2, 2, L};
Sphere(2) = {0, 0, zc, 1};
Sphere(3) = {0, 0, zc, 0.5};
BooleanDifference(4) = { Volume{2}; Delete; }{ Volume{3}; Delete; };
Box(5) = {-2, -2, zc, 4, 4, 2};
BooleanDifference(6) = { Volume{4}; Delete; }{ Volume{5}; Delete; };
Physical Volume(1) = {1};
Physical Volume(2) = {6};
bottom() = Surface In BoundingBox{-1.1, -1.1, -0.01, 1.1, 1.1, 0.01};
top() = Surface In BoundingBox{-1.1, -1.1, zc - 0.01, 1.1, 1.1, zc + 0.01};
Physical Surface(1) = {bottom()};
Physical Surface(2) = {top()};
Field[1] = Ball;
Field[1].Radius = 1.2;
Field[1].XCenter = 0; Field[1].YCenter = 0; Field[1].ZCenter = L;
Field[1].Thickness = 0.8;
Field[1].VIn = h;
Field[1].VOut = 3 * h;
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
