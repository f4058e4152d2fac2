camera { location <0, 1, -5> look_at 0 aperture 1 blur_samples 20
  bokeh { pigment { rgb 1 } } }
sphere { 0, 1 pigment { rgb 1 } }
