// A lathe, a sor, two prisms (one with an outline not symmetric in z, conic) and a blob with
// transformed components, as POV-Ray reads them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> right x*4/3 look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
plane { y, 0 pigment { rgb 0.75 } }
lathe { cubic_spline 8, <0, -0.2>, <0, 0>, <0.6, 0.1>, <0.9, 0.5>, <0.4, 1>, <0.6, 1.4>,
        <0, 1.5>, <0, 1.7> sturm pigment { rgb <0.9, 0.3, 0.2> } translate <-3, 0, 0.5> }
sor { 7, <0, -0.5>, <0.6, 0>, <0.9, 0.4>, <0.4, 1>, <0.5, 1.4>, <0.7, 1.6>, <0.8, 1.8>
      pigment { rgb <0.2, 0.8, 0.3> } translate <-1.2, 0, 1.5> }
prism { conic_sweep linear_spline 0.5, 1, 5, <-1, -1>, <1, -1>, <1, 0.5>, <-1, 1>, <-1, -1>
        rotate x*180 translate y pigment { rgb <0.3, 0.4, 0.95> } translate <1, 0, 0.3> }
prism { quadratic_spline 0, 0.8, 6, <-1, 0>, <0, -1>, <1, 0>, <0, 1.5>, <-1, 0>, <0, -1>
        pigment { rgb <0.95, 0.85, 0.3> } translate <3, 0, -0.5> }
blob {
  threshold 0.6
  sphere { <0, 0, 0>, 1, 1 }
  sphere { <0.8, 0, 0.3>, 0.8, strength 1 rotate y*30 }
  cylinder { <-1, 0, 0>, <-1, 1, 1>, 0.5, 2 scale 1.2 }
  component 1, 1, <0, 0.7, -0.4>
  pigment { rgb <0.9, 0.5, 0.9> } scale 0.6 translate <-0.3, 0.6, -2>
}
