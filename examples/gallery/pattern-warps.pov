// Hand-written POV-Ray 3.7 twin of pattern-warps.xml (written from POV-Ray 3.7's
// documentation, not exported). A Lucent pattern's <warp> steps are POV-Ray's transforms
// and warp { } blocks in the order written, and the pattern's transform attribute the
// transforms written after them (POV-Ray applies what is written last first to the point);
// a checker's scale is written first. A material with a pattern has diffuse 1 and its
// single-number ambient multiplies the pattern's colour; the shapes' transforms come after
// their textures, so the patterns lie in the shapes' object space as Lucent's do.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.1, 0.1, 0.15> }
camera {
  perspective
  location <0, 2.2, 9.5>
  right -x * 320 / 240   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 52
  look_at <0, 1.9, 0>
}
light_source { <-4, 7, 9> color rgb 1 }
light_source { <5, 4, 8> color rgb 0.35 }

#declare Flat = finish { ambient 0.25 diffuse 1 specular 0 phong 0 }

// Top row. An onion repeated along x every 0.9, each slab moved up 0.3, every other one
// mirrored in x.
box {
  <-4.3, 2.3, -0.1>, <-1.6, 4.1, 0>
  texture {
    pigment {
      onion
      color_map { [0 rgb <0.9, 0.8, 0.3>] [0.5 rgb <0.7, 0.2, 0.1>] [1 rgb <0.1, 0.2, 0.5>] }
      scale 0.5
      warp { repeat x*0.9 offset y*0.3 flip x }
      translate <-3, 3.2, 0.3>
    }
    finish { Flat }
  }
}

// A checker sucked into black holes repeated every 1.5 in x and y, each moved at random.
box {
  <-1.35, 2.3, -0.1>, <1.35, 4.1, 0>
  texture {
    pigment {
      checker rgb <0.95, 0.95, 0.85>, rgb <0.15, 0.35, 0.55>
      scale 0.25
      warp { black_hole <0.6, 0.6, 0>, 0.6 strength 3 falloff 1.5 repeat <1.5, 1.5, 0> turbulence <0.3, 0.3, 0> }
      translate <0, 0, 0.1>
    }
    finish { Flat }
  }
}

// A gradient scaled, then bent by a turbulence warp, then moved.
box {
  <1.6, 2.3, -0.1>, <4.3, 4.1, 0>
  texture {
    pigment {
      gradient x triangle_wave
      color_map { [0 rgb <0.2, 0.6, 0.3>] [1 rgb <0.95, 0.9, 0.7>] }
      scale 0.4
      warp { turbulence <0.5, 0.2, 0> octaves 4 }
      translate <0.2, 0, 0>
    }
    finish { Flat }
  }
}

// Bottom row: the mapping warps.
sphere {
  0, 1
  texture {
    pigment {
      checker rgb <1, 0.6, 0.1>, rgb <0.2, 0.2, 0.6>
      translate <0, 0, 0.5>
      scale <0.0625, 0.125, 1>
      warp { spherical }
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0.3 phong_size 40 }
  }
  rotate y*-30
  translate <-3.1, 1, 0.4>
}

cylinder {
  <0, 0, 0>, <0, 1.9, 0>, 0.75
  texture {
    pigment {
      checker rgb <0.9, 0.9, 0.9>, rgb <0.6, 0.1, 0.1>
      translate <0, 0, 0.1>
      scale <0.125, 0.3, 1>
      warp { cylindrical }
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
  rotate y*20
  translate <-1, 0, 0.4>
}

box {
  <-0.75, -0.75, -0.75>, <0.75, 0.75, 0.75>
  texture {
    pigment {
      checker rgb <0.95, 0.85, 0.4>, rgb <0.3, 0.1, 0.4>
      translate <0, 0, 0.1>
      scale <0.0625, 0.0833333, 1>
      warp { cubic }
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
  rotate x*25
  rotate y*35
  translate <1.2, 1.05, 0.4>
}

torus {
  0.75, 0.3
  texture {
    pigment {
      checker rgb <0.2, 0.7, 0.6>, rgb <0.95, 0.95, 0.9>
      translate <0, 0, 0.05>
      scale <0.0833333, 0.25, 1>
      warp { toroidal major_radius 0.75 }
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0.3 phong_size 40 }
  }
  rotate x*60
  translate <3.2, 1, 0.4>
}

plane {
  y, 0
  texture {
    pigment { rgb <0.5, 0.5, 0.55> }
    finish { ambient rgb <0.1 / 0.5, 0.1 / 0.5, 0.1 / 0.55> diffuse 1 specular 0 phong 0 }
  }
}
