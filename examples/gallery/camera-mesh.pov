// camera-mesh.pov: camera-mesh.xml written by hand the way a POV-Ray user would.
// Render: povray +Icamera-mesh.pov +W240 +H180 -A
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 }
background { rgb <0.3, 0.4, 0.55> }

// The mesh camera's rays are given by its faces, in the world's own numbers: no handedness
// to undo. Distribution 3: each pixel's (u, v) is looked up on the lens's uvs; smooth: the
// ray leaves along the vertex normals interpolated there.
#declare Cols = 6;
#declare Rows = 4;
#macro LensPoint(I, J) <-1.2 + 2.4 * I / Cols, 0.1 + 1.8 * J / Rows, 3> #end
#macro LensNormal(P) vnormalize(<0.5 * P.x, 0.5 * (P.y - 1), -1>) #end
#macro LensUv(P) <(P.x + 1.2) / 2.4, (P.y - 0.1) / 1.8> #end
camera {
  mesh_camera {
    1 3
    mesh {
      #for (J, 0, Rows - 1)
        #for (I, 0, Cols - 1)
          #local A = LensPoint(I, J);
          #local B = LensPoint(I + 1, J);
          #local C = LensPoint(I + 1, J + 1);
          #local D = LensPoint(I, J + 1);
          smooth_triangle { A, LensNormal(A), B, LensNormal(B), C, LensNormal(C)
                            uv_vectors LensUv(A), LensUv(B), LensUv(C) }
          smooth_triangle { A, LensNormal(A), C, LensNormal(C), D, LensNormal(D)
                            uv_vectors LensUv(A), LensUv(C), LensUv(D) }
        #end
      #end
    }
    smooth
  }
}

light_source { <4, 7, 5> color rgb <1, 0.95, 0.9> }
light_source { <-6, 4, -2> color rgb <0.35, 0.4, 0.5> }

// Lucent's ambient is absolute, POV-Ray's is a fraction of the pigment: divide by it.
// Lucent's Blinn exponent n is POV-Ray's 1/roughness.
#macro Plastic(Kd, Ka, Ks, N)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd  diffuse 1  specular Ks  roughness 1 / N }
  }
#end
#declare Red    = Plastic(<0.85, 0.15, 0.1>, <0.1, 0.02, 0.02>, 0.5, 60)
#declare Yellow = Plastic(<0.9, 0.8, 0.15>, <0.1, 0.09, 0.02>, 0.5, 60)
#declare Green  = Plastic(<0.15, 0.7, 0.25>, <0.02, 0.08, 0.03>, 0.5, 60)
#declare Blue   = Plastic(<0.15, 0.3, 0.9>, <0.02, 0.03, 0.1>, 0.5, 60)
#declare Stone  = Plastic(<0.8, 0.78, 0.72>, <0.1, 0.1, 0.1>, 0.2, 30)

plane {
  y, -0.5
  pigment { checker rgb <0.85, 0.82, 0.75>, rgb <0.25, 0.24, 0.28> }
  finish { ambient 0.12 diffuse 0.9 }
}
sphere { <0, 0.4, -3>, 0.9 texture { Green } }
sphere { <2.6, 0.3, -1.5>, 0.8 texture { Red } }
sphere { <-2.8, 0.2, -1.6>, 0.7 texture { Blue } }
box { <-0.7, -0.5, -0.7>, <0.7, 0.9, 0.7> texture { Stone } rotate y*20 translate <1.2, 0, -6> }
cylinder { <2.4, -0.5, -4.4>, <2.4, 2.6, -4.4>, 0.3 texture { Yellow } }
cylinder { <-2.4, -0.5, -4.4>, <-2.4, 2.6, -4.4>, 0.3 texture { Red } }
