// A solid ball of radius 1 about the origin (no physical surface: nothing
// is clamped; the example squeezed_ball_3d holds it between two plates).
// Volume tag 1.
// Regenerate: gmsh -3 -format msh41 -setnumber h 0.2 ball_3d.geo -o ball_3d.msh
// (and with h 0.4: ball_coarse_3d.msh, 118 vertices, for contact_held ball)
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.2;
EndIf
Sphere(1) = {0, 0, 0, 1};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
Physical Volume(1) = {1};
