// Hand-written POV-Ray 3.7 twin of csg-cavity-media.xml (written from POV-Ray's
// documentation, not exported): glass-fresnel.pov's glass with cavities cut by parts that
// wear textures and interiors of their own. POV-Ray gives every CSG part its own interior
// (a part without one takes its parent's, here none: the default, ior 1), and a ray keeps
// the list of interiors it is in: crossing a cut's wall from the glass enters the cut
// part's interior, so the ray bends from the glass's index into the cut's.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 0.0039 }

#declare Glass = texture {
  pigment { rgbt 1 }
  finish {
    ambient 0 diffuse 0 phong 0
    specular 1 roughness 1 / 300
    reflection { 0, 1 fresnel on }
    conserve_energy
  }
}
// A clear surface: nothing of its own, everything passes.
#declare Clear = texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }
// glasschess.pov's PieceTex: a tinted colour that lets 0.6 through, mirroring 0.3, with
// POV-Ray's default ambient 0.1 and diffuse 0.6.
#declare Lining = texture { pigment { rgbt <0.9, 0.9, 0.6, 0.6> } finish { reflection 0.3 } }
#macro Checker(C1, C2, Size, Ka, Kd)
  texture {
    pigment { checker rgb C1, rgb C2 scale Size }
    finish { ambient Ka diffuse Kd specular 0 phong 0 reflection 0 }
  }
#end

background { rgb <0.5, 0.6, 0.7> }
camera {
  perspective
  location <0, 2.4, 6>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-3, 6, 5> color rgb 1 }

plane { y, 0 Checker(0.9, 0.25, 0.5, 0.15, 0.8) }
plane { z, -3 Checker(<0.9, 0.6, 0.3>, <0.2, 0.3, 0.6>, 0.6, 0.2, 0.7) }

// An air bubble: the ball's default interior, ior 1.
difference {
  box { <-0.7, 0, -0.7>, <0.7, 1.6, 0.7> texture { Glass } interior { ior 1.5 } }
  sphere { <0, 0.8, 0>, 0.55 texture { Clear } }
  no_shadow
  rotate y * 20
  translate -1.9 * x
}
// A denser core: the box's own interior, ior 2.
difference {
  sphere { <0, 0.9, 0.3>, 0.9 texture { Glass } interior { ior 1.5 } }
  box { <-0.45, 0.45, -0.15>, <0.45, 1.35, 0.75>
    texture { Clear } interior { ior 2 }
    translate -0.3 * z rotate y * 30 translate 0.3 * z }
  no_shadow
}
// The glasschess piece: a tinted lining, ior 1.
difference {
  box { <-0.7, 0, -0.7>, <0.7, 1.6, 0.7> texture { Glass } interior { ior 1.5 } }
  sphere { <0, 0.8, 0>, 0.55 texture { Lining } }
  no_shadow
  rotate y * -20
  translate 1.9 * x
}
