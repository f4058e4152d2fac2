// Hand-written POV-Ray 3.7 twin of parametric.xml (written from POV-Ray's documentation, not
// exported), in POV-Ray's own left-handed numbers: every z of the XML negated (the z
// functions too), rotations about x and y turned the other way (the importer's mapping).
// Lucent's material (k_a, k_d, specular k_s with shininess s) is pigment k_d, ambient
// k_a / k_d, diffuse 1, specular k_s with roughness 1/s; mapping="uv" is POV-Ray's uv_mapping.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 3.4, -9.5>
  right x * 240 / 180
  up y
  angle 48
  look_at <0, 0.9, 0>
}
light_source { <-5, 8, -7> color rgb 1 }
light_source { <4, 3, -6> color rgb 0.4 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

plane {
  y, 0
  texture {
    pigment { rgb <0.6, 0.6, 0.55> }
    finish { ambient rgb <0.05, 0.05, 0.05> / <0.6, 0.6, 0.55> diffuse 1 specular 0 phong 0 }
  }
}

// The Möbius strip of portfolio/allobjects.pov, on its edge.
parametric {
  function { cos(u) + v*cos(u/2)*cos(u) }
  function { sin(u) + v*cos(u/2)*sin(u) }
  function { -v*sin(u/2) }
  <0, -0.3>, <2*pi, 0.3>
  contained_by { box { <-1.35, -1.35, -0.35>, <1.35, 1.35, 0.35> } }
  max_gradient 1.5
  precompute 14, x, y, z
  Surface(<0.9, 0.8, 0.7>, <0.09, 0.08, 0.07>, 0.4, 40)
  rotate y * 35
  translate <-2.7, 1.45, -0.2>
}

// A sphere by its angles; uv_mapping reads its (u, v).
parametric {
  function { cos(u)*sin(v) } function { cos(v) } function { -sin(u)*sin(v) }
  <0, 0>, <2*pi, pi>
  contained_by { sphere { 0, 1.02 } }
  precompute 14, x, y, z
  pigment { uv_mapping checker rgb <0.9, 0.75, 0.2>, rgb <0.15, 0.3, 0.65>
            scale <pi/4, pi/4, 1> translate z * 0.5 }
  finish { ambient 0.2 diffuse 0.8 specular 0 phong 0 reflection 0 }
  translate <0, 1, 0.3>
}

// A tube round a helix: two turns.
parametric {
  function { (0.6 + 0.15*cos(u))*cos(v) }
  function { 0.15*sin(u) + 0.08*v }
  function { -(0.6 + 0.15*cos(u))*sin(v) }
  <0, 0>, <2*pi, 4*pi>
  contained_by { box { <-0.8, -0.2, -0.8>, <0.8, 1.2, 0.8> } }
  max_gradient 0.8
  precompute 16, x, y, z
  Surface(<0.8, 0.5, 0.3>, <0.08, 0.05, 0.03>, 0.6, 80)
  translate <2.6, 0.2, -0.3>
}
