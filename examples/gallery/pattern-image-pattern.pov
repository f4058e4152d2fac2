// Hand-written POV-Ray 3.7 twin of pattern-image-pattern.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern type="image-pattern"> is
// image_pattern { png "textures/emblem.png" ... } with the pattern's transform after it;
// the <normal> is the normal pattern with its depth as the bump size. A material with a
// pattern has diffuse 1 and its single-number ambient multiplies the pattern's colour;
// without a pattern Lucent's ambient is a colour of its own, so here it is divided by the
// pigment. Run from examples/gallery, so that the image's relative name is found.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.1, 0.1, 0.15> }
camera {
  perspective
  location <0, 2, 8.2>
  right -x * 320 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 50
  look_at <0, 2, 0>
}
light_source { <-3, 6, 8> color rgb 1 }
light_source { <4, 4, 6> color rgb 0.3 }

// Left: the emblem's grey levels, blended bilinearly, through a colour map.
box {
  <-3.9, 0.3, -0.1>, <-1.5, 2.7, 0>
  texture {
    pigment {
      image_pattern { png "textures/emblem.png" interpolate 2 }
      color_map { [0 rgb <0.05, 0.1, 0.4>] [0.5 rgb <0.9, 0.4, 0.1>] [1 rgb <1, 1, 0.7>] }
      scale 2.4
      translate <-3.9, 0.3, 0>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

// Middle: the emblem projected spherically as bumps.
sphere {
  <0, 1.6, 0>, 1.2
  texture {
    pigment { rgb <0.8, 0.8, 0.9> }
    normal { image_pattern { png "textures/emblem.png" map_type 1 } 0.6 }
    finish {
      ambient rgb <0.2 / 0.8, 0.2 / 0.8, 0.2 / 0.9> diffuse 1 specular 0 phong 0.5 phong_size 40
    }
  }
}

// Right: the emblem's transparency picks a plain red or a checker; one copy, inside the
// face, off which the value is 0 (red).
box {
  <1.5, 0.3, -0.1>, <3.9, 2.7, 0>
  texture {
    pigment {
      image_pattern { png "textures/emblem.png" once use_alpha }
      pigment_map {
        [0.2 rgb <0.8, 0.15, 0.1>]
        [0.8 checker rgb <0.9, 0.9, 0.8>, rgb <0.2, 0.3, 0.5> scale 0.3 translate <0, 0, 0.15>]
      }
      scale 2
      translate <1.7, 0.5, 0>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

plane {
  y, 0
  texture {
    pigment { rgb <0.5, 0.5, 0.55> }
    finish { ambient rgb <0.1 / 0.5, 0.1 / 0.5, 0.1 / 0.55> diffuse 1 specular 0 phong 0 }
  }
}
