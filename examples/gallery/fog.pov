// Hand-written POV-Ray 3.7 twin of fog.xml (written from POV-Ray's documentation, not
// exported). Lucent's <fog color="F" distance="d"/> is POV-Ray's constant fog (fog_type 1):
// a stretch of length t keeps exp(-t/d) of the colour beyond it and adds the rest of F.
// Rays that leave the scene show F alone; inside the (not hollow) glass sphere there is
// no fog, in both renderers.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.2, 0.3, 0.5> }
fog { fog_type 1 distance 9 color rgb <0.7, 0.75, 0.8> }

camera {
  perspective
  location <0, 1.6, 6>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
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
#while (I < 6)
  cylinder { <-2.2, 0, 2 - 4 * I>, <-2.2, 2.2, 2 - 4 * I>, 0.3 Post(<0.8, 0.2, 0.15>, <0.1, 0.03, 0.03>) }
  cylinder { <2.2, 0, 2 - 4 * I>, <2.2, 2.2, 2 - 4 * I>, 0.3 Post(<0.15, 0.3, 0.8>, <0.03, 0.05, 0.1>) }
  #local I = I + 1;
#end

// The mirror: Lucent's reflective k_r is POV-Ray's reflection.
sphere {
  <-0.6, 0.8, -1>, 0.8
  texture {
    pigment { rgb 0.05 }
    finish { ambient 0 diffuse 1 specular 0.8 roughness 1 / 200 phong 0 reflection 0.85 }
  }
}

// The glass: transmissive 0.9 is transmit 0.9 of a black pigment (no diffuse, no ambient).
sphere {
  <0.9, 0.5, 1.5>, 0.5
  texture {
    pigment { rgbt <0, 0, 0, 0.9> }
    finish { ambient 0 diffuse 0 specular 0.6 roughness 1 / 150 phong 0 reflection 0 }
  }
  interior { ior 1.4 }
}
