// Hand-written POV-Ray 3.7 twin of pattern-object.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern type="object" object="ID"> is POV-Ray's
// object pattern `object { ID A B }`, its map's first entry outside and its last inside, with
// the pattern's transform after it; the <defs> are #declared objects. A material with a
// pattern has diffuse 1 and its single-number ambient multiplies the pattern's colour; a
// material without one has an ambient colour of its own, here divided by its pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.08, 0.08, 0.12> }
camera {
  perspective
  location <0, 3.2, -7>
  right -x * 320 / 240   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 48
  look_at <0, 0.4, 0>
}
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 6, -3> color rgb 0.35 }

#declare Notched = difference {
  box { <-0.85, -0.85, -0.85>, <0.85, 0.85, 0.85> }
  sphere { <0.85, 0.85, -0.85>, 0.9 }
}
#declare Ring = torus { 1.6, 0.45 translate <0, 0, -2.3> }
#declare Beads = union {
  sphere { <-0.6, 0, 0>, 0.45 }
  sphere { <0, 0, 0>, 0.45 }
  sphere { <0.6, 0, 0>, 0.45 }
}
#declare Slab = box { <-2, -0.25, -2>, <2, 0.25, 2> rotate z*35 }

// The floor: a checker outside the ring, plain tiles inside it.
box { <-5, -0.1, -3>, <5, 0, 5>
  pigment { object { Ring
    pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.35, 0.35, 0.4> scale 0.5 }
    pigment { rgb <0.8, 0.45, 0.2> } } }
  finish { ambient 0.15 diffuse 1 }
}

// A sphere coloured by the notched box, turned and moved to the sphere.
sphere { <-2.2, 1, 0.4>, 1
  pigment { object { Notched color rgb <0.95, 0.8, 0.25> color rgb <0.15, 0.35, 0.85> }
            rotate y*25 rotate x*-20 translate <-2.2, 1, 0.4> }
  finish { ambient 0.15 diffuse 1 }
}

// A block whose surface is mirror-like inside the beads and matte outside them.
box { <-0.9, 0, -0.6>, <0.9, 1.1, 0.6>
  texture {
    object { Beads
      texture { pigment { rgb <0.2, 0.6, 0.3> } finish { ambient rgb <0.75, 0.25, 0.5> diffuse 1 } }
      texture { pigment { rgb <0.25, 0.25, 0.3> }
                finish { ambient rgb <0.2, 0.2, 0.05/0.3> diffuse 1 reflection 0.5 } }
    }
    translate <0, 0.55, -0.6>
  }
  rotate y*-15 translate <0.4, 0, -0.9>
}

// A ball rippled inside the slab and bumped outside it.
sphere { <2.3, 1, 0.6>, 1
  pigment { rgb <0.85, 0.3, 0.3> }
  normal { object { Slab normal { bumps 0.4 scale 0.12 } normal { ripples 1.2 scale 0.4 } }
           translate <2.3, 1, 0.6> }
  finish { ambient rgb <0.12/0.85, 0.4, 0.4> diffuse 1 }
}
