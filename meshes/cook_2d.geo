// Cook's membrane (2D): the tapered panel with corners (0,0), (48,44),
// (48,60), (0,44) mm, as a structured (transfinite) triangle mesh with N
// elements along every side (each quadrilateral split into 2 triangles).
// Physical tags (boundary ids in hyperelastic): 1 the clamped edge x = 0,
// 2 the loaded edge x = 48, 3 the free edges (bottom and top); surface 1.
// Regenerate (scripts/make-cook-meshes.sh does all sizes):
//   gmsh -2 -format msh41 -setnumber N 8 cook_2d.geo -o cook_2d_8.msh
DefineConstant[ N = {4, Name "Elements per side"} ];

Point(1) = {0, 0, 0};
Point(2) = {48, 44, 0};
Point(3) = {48, 60, 0};
Point(4) = {0, 44, 0};
Line(1) = {1, 2}; // bottom
Line(2) = {2, 3}; // right (loaded)
Line(3) = {3, 4}; // top
Line(4) = {4, 1}; // left (clamped)
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 2, 3, 4} = N + 1;
Transfinite Surface{1} = {1, 2, 3, 4};

Physical Curve(1) = {4};
Physical Curve(2) = {2};
Physical Curve(3) = {1, 3};
Physical Surface(1) = {1};
