camera { location -3 * z look_at 0 }
plane { z, 0 pigment { image_map { gif "heights/truncated.gif" } } }
