// Cook's membrane (3D): the 2D panel with corners (0,0), (48,44), (48,60),
// (0,44) mm extruded 10 mm in z, as a structured tetrahedral mesh: N
// elements along every side of the panel and max(1, floor(N/4)) layers
// through the thickness (each prism split into 3 tetrahedra).
// Physical tags (boundary ids in hyperelastic): 1 the clamped face x = 0,
// 2 the loaded face x = 48, 3 all other faces (free); volume 1.
// Regenerate (scripts/make-cook-meshes.sh does all sizes):
//   gmsh -3 -format msh41 -setnumber N 8 cook_3d.geo -o cook_3d_8.msh
DefineConstant[ N = {4, Name "Elements per side"} ];
thickness = 10;
layers = Floor(N / 4);
If (layers < 1)
  layers = 1;
EndIf

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

// out[0]: the face z = thickness, out[1]: the volume, out[2..5]: the faces
// swept by the lines 1..4.
out[] = Extrude {0, 0, thickness} { Surface{1}; Layers{layers}; };

Physical Surface(1) = {out[5]};
Physical Surface(2) = {out[3]};
Physical Surface(3) = {1, out[0], out[2], out[4]};
Physical Volume(1) = {out[1]};
