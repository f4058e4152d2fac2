// Hand-written POV-Ray 3.7 twin of material-map-index.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <material-map> read by index is a
// material_map with its entries as textures in order, the pattern's transform after the
// block; a material_map's textures lie in the map's space, so the bumpy entry's own scale
// (Lucent's, in the object's space) is followed by the map's inverse. A material without a
// pattern has its ambient as a colour of its own, so here it is divided by the pigment.
// The bump map with use_index is POV-Ray's, its palette indices the heights.
// Run from examples/gallery, so that the images' relative names are found.
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

#macro Plain(Diffuse, Ambient)
  pigment { rgb Diffuse }
  finish { ambient Ambient / Diffuse diffuse 1 specular 0 phong 0 }
#end

// Left: the emblem's palette index picks one of four textures.
box {
  <-3.9, 0.3, -0.1>, <-1.5, 2.7, 0>
  texture {
    material_map {
      png "textures/emblem.png"
      texture { Plain(<0.1, 0.15, 0.4>, 0.1) }
      texture {
        pigment { rgb 1 }
        finish { ambient 0.02 diffuse 0.05 specular 0 phong 0 reflection { 0.8 } }
      }
      texture {
        pigment { rgb <0.9, 0.45, 0.1> }
        normal { bumps 0.8 accuracy 0.02 scale 0.1 translate <3.9, -0.3, 0> scale 1 / 2.4 }
        finish { ambient 0.15 / <0.9, 0.45, 0.1> diffuse 1 specular 0 phong 0.6 phong_size 40 }
      }
      texture { Plain(<1, 0.9, 0.3>, 0.9) }
    }
    scale 2.4
    translate <-3.9, 0.3, 0>
  }
}

// Middle: the grid's red x 255 picks one of three textures, projected spherically.
sphere {
  <0, 1.6, 0>, 1.2
  texture {
    material_map {
      png "textures/uvgrid.png" map_type 1
      texture {
        pigment { rgb <0.8, 0.8, 0.9> }
        finish { ambient 0.1 / <0.8, 0.8, 0.9> diffuse 1 specular 0 phong 0.5 phong_size 40 }
      }
      texture {
        pigment { rgb <0.2, 0.5, 0.25> }
        finish { ambient 0.1 / <0.2, 0.5, 0.25> diffuse 1 specular 0 phong 0.5 phong_size 40 }
      }
      texture {
        pigment { rgb 1 }
        finish { ambient 0.05 diffuse 0.1 specular 0 phong 0.8 phong_size 40 reflection { 0.5 } }
      }
    }
    rotate y * 20
  }
}

// Right: the emblem's palette indices as bump heights, one copy (flat off it).
box {
  <1.5, 0.3, -0.1>, <3.9, 2.7, 0>
  texture {
    pigment { rgb <0.85, 0.85, 0.8> }
    normal {
      bump_map { png "textures/emblem.png" once interpolate 2 use_index }  // Lucent blends bilinearly by default
      bump_size 0.02
      scale 2
      translate <1.7, 0.5, 0>
    }
    finish { ambient 0.1 / <0.85, 0.85, 0.8> diffuse 1 specular 0 phong 0.4 phong_size 40 }
  }
}

plane {
  y, 0
  texture { Plain(<0.5, 0.5, 0.55>, 0.1) }
}
