// Hand-written POV-Ray 3.7 twin of fog-layers.xml (written from POV-Ray's documentation,
// not exported). Two fogs, both applied: a ground fog (fog_type 2) whose turbulence thins
// it in patches, and a constant one with a little turbulence. The left glass sphere is
// hollow, so the fog goes on inside it; the right one is not, and its inside stays clear.
// The fogs' noise is at POV-Ray's world point, the coordinates as written (the camera's
// negative right keeps Lucent's right-handed coordinates unchanged).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.35, 0.5, 0.8> }
fog {
  fog_type 2 distance 3 color rgb <0.25, 0.35, 0.9> fog_offset 0 fog_alt 0.4
  turbulence <0.6, 0.6, 0.6> octaves 5 omega 0.4 lambda 1.8 turb_depth 0.7
}
fog { fog_type 1 distance 40 color rgb <1, 0.6, 0.2> turbulence 0.3 turb_depth 0.9 }

camera {
  perspective
  location <0, 1.5, 7>
  right -x * 240 / 180   // negative: our right-handed world, unchanged coordinates
  up y
  angle 55
  look_at <0, 0.8, -4>
}

light_source { <-4, 8, 6> color rgb 1 }

// Lucent's ambient k_a is POV-Ray's ambient times the pigment: give ambient as k_a / k_d.
#macro Post(Kd, Ka)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular 0.3 roughness 1 / 40 phong 0 reflection 0 }
  }
#end

plane {
  y, 0
  texture {
    pigment { checker rgb <0.9, 0.85, 0.75>, rgb <0.3, 0.25, 0.2> }
    finish { ambient 0.15 diffuse 0.8 specular 0 phong 0 reflection 0 }
  }
}

#local I = 0;
#while (I < 5)
  cylinder { <-2.4, 0, 2 - 4 * I>, <-2.4, 2.4, 2 - 4 * I>, 0.3 Post(<0.8, 0.2, 0.15>, <0.1, 0.03, 0.03>) }
  cylinder { <2.4, 0, 2 - 4 * I>, <2.4, 2.4, 2 - 4 * I>, 0.3 Post(<0.15, 0.3, 0.8>, <0.03, 0.05, 0.1>) }
  #local I = I + 1;
#end

// The glass: transmissive 0.9 is transmit 0.9 of a black pigment (no diffuse, no ambient).
#declare Glass = texture {
  pigment { rgbt <0, 0, 0, 0.9> }
  finish { ambient 0 diffuse 0 specular 0.6 roughness 1 / 150 phong 0 reflection 0 }
}
sphere { <-1, 1, 0>, 1 texture { Glass } interior { ior 1.05 } hollow }
sphere { <1.2, 1, 0>, 1 texture { Glass } interior { ior 1.05 } }
