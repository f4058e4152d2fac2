// Hand-written POV-Ray 3.7 twin of normal-maps.xml (written from POV-Ray's documentation,
// not exported). Lucent's <normal-map>, <normal-list> and <slope-map> are POV-Ray's
// normal_map, a block pattern's list of normals and slope_map; a nested normal's
// transforms compose with the outer pattern's. An empty <entry/> of a list is a normal
// that bends nothing (bumps 0: POV-Ray wants every cell's normal). The coordinates are
// Lucent's, seen through a mirrored camera (right -x). Lucent's ambient without a texture
// is not scaled by the diffuse colour, so POV-Ray's is divided by it.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.45, 0.55, 0.7> }
camera {
  perspective
  location <0, 0.4, -9>
  right -x * 320 / 240
  up y
  angle 48
  look_at <0, 0.4, 0>
}
light_source { <6, 8, -10> color rgb 1 }
light_source { <-8, 3, -6> color rgb 0.4 }

#macro Plate(Colour, Phong, PhongSize, Normal, Where)
  box { <-1.2, -1.2, 0>, <1.2, 1.2, 0.5>
    texture {
      pigment { rgb Colour }
      normal { Normal }
      finish { ambient rgb 0.1 / Colour diffuse 1 phong Phong phong_size PhongSize specular 0 }
    }
    translate Where
  }
#end

// A normal map: marble, then scalloped stripes, by a gradient across the plate.
Plate(<0.8, 0.75, 0.6>, 0.6, 80,
  normal {
    gradient x
    normal_map {
      [0.3 marble 1.2 turbulence 0.5]
      [0.7 gradient y 1.2 scallop_wave scale 0.3]
    }
    translate -1.2 * x
    scale 2.4
  },
  <-2.8, 1.7, 0>)

// A checker of bumps and a flat cell.
Plate(<0.6, 0.7, 0.85>, 0.6, 80,
  normal {
    checker
    normal { bumps 1 scale 0.15 }
    normal { bumps 0 }
    scale 0.6
  },
  <0, 1.7, 0>)

// A slope map: the onion's rings as triangles.
Plate(<0.85, 0.6, 0.5>, 0.6, 80,
  normal {
    onion 0.8
    slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] [1 <0, -1>] }
    scale 0.4
  },
  <2.8, 1.7, 0>)

// A hexagon of three normals.
Plate(<0.7, 0.8, 0.6>, 0.6, 80,
  normal {
    hexagon
    normal { ripples 0.6 scale 0.4 }
    normal { wrinkles 0.6 scale 0.5 }
    normal { leopard 0.8 scale 0.05 }
    scale 0.35
    rotate -90 * x
  },
  <-2.8, -1, 0>)

// A slope map of sine-shaped ridges.
Plate(<0.8, 0.8, 0.8>, 0.6, 80,
  normal {
    gradient <1, 1, 0> 0.6
    slope_map { [0 <0.5, 1>] [0.25 <1, 0>] [0.5 <0.5, -1>] [0.75 <0, 0>] [1 <0.5, 1>] }
    scale 0.5
  },
  <0, -1, 0>)

// Bumpy bricks in smooth mortar.
Plate(<0.75, 0.45, 0.35>, 0.4, 60,
  normal {
    brick
    normal { bumps 0 }
    normal { granite 0.3 scale 0.3 }
    brick_size <0.8, 0.3, 0.5>
    mortar 0.1
  },
  <2.8, -1, 0>)
