// camera-ultra-wide-angle.pov: camera-ultra-wide-angle.xml written by hand the way a POV-Ray user would.
// Render: povray +Icamera-ultra-wide-angle.pov +W240 +H180 -A
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 }
background { rgb 0 }

// Lucent's world is right-handed and POV-Ray's left-handed with the same coordinates: with
// `right -x` (a negative handedness) look_at makes POV-Ray's right forward x sky, Lucent's
// right, so the image is not mirrored. These cameras normalise right and up, or use only the
// ratios of their lengths, as noted.

// The angle spans the width; down the height it is scaled by |up| / |right| = 3/4.
camera {
  ultra_wide_angle
  angle 200
  right -x*4/3
  up y
  location <0, 1, 1>
  look_at <0.5, 0.8, -1>
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

// The sky dome: emission only.
sphere { 0, 60 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission rgb <0.45, 0.62, 0.9> } }
plane {
  y, -0.5
  pigment { checker rgb <0.85, 0.82, 0.75>, rgb <0.25, 0.24, 0.28> }
  finish { ambient 0.12 diffuse 0.9 }
}
sphere { <0, 0.4, -3>, 0.9 texture { Green } }
sphere { <3, 0.3, 0.3>, 0.8 texture { Red } }
box { <-0.7, -0.5, -0.7>, <0.7, 0.9, 0.7> texture { Stone } rotate y*20 translate <0.4, 0, 3.2> }
sphere { <-3.2, 0.2, -0.4>, 0.7 texture { Blue } }
cylinder { <2.4, -0.5, -2.4>, <2.4, 2.6, -2.4>, 0.3 texture { Yellow } }
cylinder { <-2.4, -0.5, -2.4>, <-2.4, 2.6, -2.4>, 0.3 texture { Red } }
torus { 1.5, 0.15 texture { Yellow } translate 3*y }
