#!/usr/bin/env bash
# Regenerates the POV-Ray 3.7 reference values of tests/patterns from POV-Ray itself.
#
# Values come from POV-Ray's functions, printed to 17 decimals: `function { pattern {...} }`
# (the pattern with its transform, turbulence, frequency and wave: POV-Ray's f_pattern),
# `function { pigment {...} }` (the colour, float) and f_noise_generator (the raw noise).
# A pattern function takes fractal exterior types 0..6 only, so types 7 and 8 are read
# through a pigment (colors.csv). Points are k/4096 for integer k, so the CSV's integers give them exactly. Normals cannot
# be read from a function: they are rendered (normals.csv, see there).
#
# Needs povray (3.7) and oiiotool. Usage: make_references.sh [output folder]
set -euo pipefail

out=${1:-$(cd "$(dirname "$0")" && pwd)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run_pov() {  # scene, then extra povray options
  local scene=$1
  shift
  if ! povray -D -V -GS -GR "+I$scene" "$@" >"$work/log" 2>&1; then
    cat "$work/log" >&2
    exit 1
  fi
}

header() {
  cat <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
// N points k/4096 with |k/4096| < R, from a seeded stream; Row(KX, KY, KZ, X, Y, Z)
// writes one line.
#macro Points(N, Seed, R)
  #local S = seed(Seed);
  #for (I, 1, N)
    #local KX = floor((rand(S) * 2 - 1) * R * 4096);
    #local KY = floor((rand(S) * 2 - 1) * R * 4096);
    #local KZ = floor((rand(S) * 2 - 1) * R * 4096);
    Row(KX, KY, KZ, KX / 4096, KY / 4096, KZ / 4096)
  #end
#end
#macro Ints(KX, KY, KZ) concat(str(KX, 0, 0), ",", str(KY, 0, 0), ",", str(KZ, 0, 0)) #end
POV
}

# --- noise.csv: x,y,z as k/4096, then noise for generators 1, 2, 3 -------------------------
{
  header
  cat <<POV
#fopen Out "$work/noise.csv" write
#write (Out, "kx,ky,kz,n1,n2,n3\n")
#macro Row(KX, KY, KZ, X, Y, Z)
  #write (Out, Ints(KX, KY, KZ), ",", str(f_noise_generator(X, Y, Z, 1), 0, 17), ",",
         str(f_noise_generator(X, Y, Z, 2), 0, 17), ",", str(f_noise_generator(X, Y, Z, 3), 0, 17), "\n")
#end
Points(300, 11, 8)
Points(100, 12, 4096)
#fclose Out
POV
} >"$work/noise.pov"
run_pov "$work/noise.pov" +W8 +H8 "+O$work/discard.png"
cp "$work/noise.csv" "$out/noise.csv"

# --- patterns.csv and colors.csv: one case a line, NAME|HALF-RANGE|POV-Ray text ----------
# tests/patterns/pattern_cases.h holds the same cases as Lucent specs.
pattern_cases=(
  "gradient|8|gradient <1, 2, -0.5>"
  "onion|8|onion"
  "radial|8|radial"
  "spiral1|8|spiral1 3"
  "spiral2|8|spiral2 5"
  "wood|8|wood"
  "marble|8|marble"
  "agate|8|agate"
  "granite|8|granite"
  "bozo|8|bozo"
  "spotted|8|spotted"
  "leopard|8|leopard"
  "crackle|8|crackle"
  "wrinkles|8|wrinkles"
  "bumps|8|bumps"
  "dents|8|dents"
  "ripples|8|ripples"
  "waves|8|waves"
  "bozo_generator1|8|bozo noise_generator 1"
  "bozo_generator3|8|bozo noise_generator 3"
  "bozo_far|4096|bozo"
  "granite_generator1|8|granite noise_generator 1"
  "granite_generator3|8|granite noise_generator 3"
  "agate_generator1|8|agate noise_generator 1"
  "wrinkles_generator1|8|wrinkles noise_generator 1"
  "dents_generator3|8|dents noise_generator 3"
  "spotted_generator1|8|spotted noise_generator 1"
  "crackle_far|2048|crackle"
  "crackle_metric1|8|crackle metric 1 form <1, 0, 0>"
  "crackle_metric3|8|crackle metric 3 form <-0.5, 1.2, 0.3> offset 0.2"
  "crackle_offset|8|crackle offset 0.5"
  "crackle_solid|8|crackle solid"
  "crackle_solid_generator1|8|crackle solid noise_generator 1"
  "ripples_frequency|8|ripples frequency 2.5 phase 0.3"
  "waves_frequency|8|waves frequency 0.7 phase -0.2"
  "turbulence_scalar|8|bozo turbulence 0.5"
  "turbulence_vector|8|bozo turbulence <0.2, 0.6, 1.1> octaves 3 omega 0.7 lambda 2.5"
  "turbulence_generator3|8|bozo turbulence 0.7 noise_generator 3"
  "turbulence_generator1|8|granite turbulence 0.3 noise_generator 1"
  "turbulence_octaves_clamped|8|onion turbulence 0.2 octaves 12"
  "dnoise_x|8|gradient x turbulence <1, 0, 0> octaves 1 frequency 0"
  "dnoise_y|8|gradient y turbulence <0, 1, 0> octaves 1 frequency 0"
  "dnoise_z|8|gradient z turbulence <0, 0, 1> octaves 1 frequency 0"
  "marble_turbulence|8|marble turbulence 0.8"
  "marble_octaves|8|marble turbulence <1.5, 0, 0> octaves 9 omega 0.35 lambda 3.1"
  "wood_turbulence|8|wood turbulence <0.3, 0.2, 0.1>"
  "spiral1_turbulence|8|spiral1 2 turbulence 0.4"
  "spiral2_turbulence|8|spiral2 4 turbulence <0.1, 0.3, 0.2> octaves 4"
  "agate_octaves|8|agate octaves 3 omega 0.6 lambda 1.7"
  "agate_turbulence|8|agate turbulence 0.3"
  "agate_turb|8|agate agate_turb 0.35 turbulence 0.2"
  "onion_frequency|8|onion frequency 3 phase 0.25"
  "gradient_negative_frequency|8|gradient y frequency -2.5 phase 0.1"
  "bozo_frequency0|8|bozo frequency 0 phase 0.5"
  "onion_sine|8|onion sine_wave"
  "onion_triangle|8|onion triangle_wave"
  "onion_scallop|8|onion scallop_wave"
  "onion_cubic|8|onion cubic_wave"
  "onion_poly|8|onion poly_wave 2.5"
  "marble_ramp|8|marble ramp_wave"
  "wood_sine|8|wood sine_wave frequency 0.3"
  "bozo_transform|8|bozo scale 0.37 translate <1, 2, 3>"
  "gradient_rotate|8|gradient x rotate <0, 0, 30>"
  "marble_scaled_turbulence|8|marble turbulence 0.5 scale <2, 0.5, 1>"
  "planar|2|planar"
  "planar_sine|2|planar frequency 2 sine_wave"
  "planar_turbulence|2|planar turbulence 0.4 rotate <0, 0, 30>"
  "quilted|2|quilted"
  "quilted_controls|2|quilted control0 0.3 control1 0.8"
  "quilted_frequency|2|quilted control0 0 control1 0.5 frequency 2 phase 0.1"
  "mandel|2|mandel 30"
  "mandel_colourings|2|mandel 20 exterior 6, 0.2 interior 1, 1"
  "mandel3|2|mandel 25 exponent 3 interior 5, 2"
  "mandel4|2|mandel 25 exponent 4 exterior 2, 0.3 interior 2, 0.7"
  "mandel7|2|mandel 15 exponent 7 exterior 5, 3 interior 3, 0.5"
  "mandel_placed|2|mandel 25 exterior 0, 0.3 interior 6, 0.5 scale 0.5 rotate <0, 0, 30> translate <-0.5, 0, 0>"
  "julia|2|julia <0.3, 0.44>, 30 interior 1, 1"
  "julia3|2|julia <-0.5, 0.5>, 20 exponent 3 exterior 2, 4"
  "julia4|2|julia <0.2, -0.6>, 20 exponent 4 exterior 4, 0.1 interior 4, 1"
  "julia9|2|julia <0.1, 0.2>, 12 exponent 9 exterior 5, 0.3 interior 6, 0.5"
  "julia33|1|julia <0.4, 0.1>, 8 exponent 33 exterior 3, 0.2 interior 1, 1"
  "magnet1m|3|magnet 1 mandel 40 interior 1, 0.5"
  "magnet1j|3|magnet 1 julia <0.4, 0.1>, 30 exterior 6, 0.01"
  "magnet2m|3|magnet 2 mandel 30 exterior 0, 0.3 interior 1, 0.4"
  "magnet2j|3|magnet 2 julia <1.1, 0.3>, 25"
  "spherical|2|spherical"
  "spherical_sine|2|spherical frequency 3 phase 0.2 sine_wave"
  "cylindrical|2|cylindrical"
  "cylindrical_turbulence|2|cylindrical turbulence 0.3 scale <1, 2, 0.5>"
  "boxed|2|boxed"
  "boxed_rotated|2|boxed rotate <20, 30, 0> frequency 2 triangle_wave"
  "cells|8|cells"
  "cells_placed|8|cells scale 0.3 translate <0.5, 0, 0>"
  "cells_far|4096|cells"
  "cells_turbulence|8|cells turbulence 0.5 frequency 1.5 phase 0.1"
  "pigment_checker|4|pigment_pattern { checker rgb <1, 0.5, 0>, rgb <0, 0.2, 1> scale 0.5 }"
  "pigment_gradient|2|pigment_pattern { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0.2, 0.9, 0.4>] } } frequency 2 sine_wave"
  "pigment_granite|4|pigment_pattern { granite scale 0.3 } turbulence 0.2 scale 1.5"
)
color_cases=(
  "map_bozo|8|bozo color_map { [0.2 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0.5>] [0.9 rgb <0.1, 0.2, 0.9>] }"
  "map_single|8|onion color_map { [0.5 rgb <0.3, 0.6, 0.9>] }"
  "map_step|2|gradient x color_map { [0 rgb 0] [0.5 rgb <1, 0, 0>] [0.5 rgb <0, 0, 1>] [1 rgb 1] }"
  "map_single_precision|8|leopard color_map { [0.1 rgb <0.25, 0.5, 0.75>] [0.3 rgb <1, 0.5, 0>] [0.7 rgb <0, 0.3, 0.1>] }"
  "map_none|8|granite"
  "map_wide|8|marble turbulence 0.6 color_map { [-0.5 rgb <0.2, 0.4, 0.6>] [0.3 rgb <0.9, 0.1, 0.3>] [1.5 rgb <0.05, 0.95, 0.5>] }"
  "hexagon|8|hexagon rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1>"
  "hexagon_scaled|8|hexagon rgb <0.2, 0.3, 0.4>, rgb <0.9, 0.8, 0.1>, rgb <0.5, 0.5, 0> scale 0.3 translate <0.1, 0, -0.2>"
  "hexagon_turbulence|8|hexagon rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1> turbulence 0.3"
  "brick|32|brick rgb <0.1, 0.2, 0.3>, rgb <0.9, 0.8, 0.7>"
  "brick_sized|4|brick rgb <0.1, 0.2, 0.3>, rgb <0.9, 0.8, 0.7> mortar 0.2 brick_size <1, 0.5, 0.7>"
  "brick_turbulence|16|brick rgb <1, 1, 1>, rgb <0, 0, 0> turbulence 0.4 octaves 3"
  "mandel_exterior7|2|mandel 15 exponent 7 exterior 7, 3 interior 3, 0.5 color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.25>] }"
  "julia_exterior8|2|julia <-0.5, 0.5>, 20 exponent 3 exterior 8, 4 color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.25>] }"
)

write_cases() {  # kind (pattern or pigment), csv path, cases...
  local kind=$1 csv=$2
  shift 2
  header
  echo "#fopen Out \"$csv\" write"
  if [ "$kind" = pattern ]; then
    echo '#write (Out, "case,kx,ky,kz,value\n")'
  else
    echo '#write (Out, "case,kx,ky,kz,r,g,b\n")'
  fi
  local i=0
  for c in "$@"; do
    IFS='|' read -r name range text <<<"$c"
    i=$((i + 1))
    echo "#declare F$i = function { $kind { $text } }"
    echo "#macro Row(KX, KY, KZ, X, Y, Z)"
    if [ "$kind" = pattern ]; then
      echo "  #write (Out, \"$name,\", Ints(KX, KY, KZ), \",\", str(F$i(X, Y, Z), 0, 17), \"\\n\")"
    else
      echo "  #local C = F$i(X, Y, Z);"
      echo "  #write (Out, \"$name,\", Ints(KX, KY, KZ), \",\", str(C.red, 0, 17), \",\", str(C.green, 0, 17), \",\", str(C.blue, 0, 17), \"\\n\")"
    fi
    echo "#end"
    echo "Points(100, $((100 + i)), $range)"
  done
  echo "#fclose Out"
}

write_cases pattern "$work/patterns.csv" "${pattern_cases[@]}" >"$work/patterns.pov"
run_pov "$work/patterns.pov" +W8 +H8 "+O$work/discard.png"
cp "$work/patterns.csv" "$out/patterns.csv"

write_cases pigment "$work/colors.csv" "${color_cases[@]}" >"$work/colors.pov"
run_pov "$work/colors.pov" +W8 +H8 "+O$work/discard.png"
cp "$work/colors.csv" "$out/colors.csv"

# --- tilings.csv: POV-Ray's 27 tilings, 300 points each, and some placed --------------------
# tests/patterns/tiling_test.cpp holds the same cases. POV-Ray 3.7 does not take tiling in a
# pattern function, so the value is read as the red of a pigment mapping 0..1 to black..white
# (a float colour: the value to single precision).
tiling_cases=()
for n in $(seq 1 27); do tiling_cases+=("tiling$n|300|6|tiling $n"); done
tiling_cases+=(
  "tiling_far2|100|1000|tiling 2"
  "tiling_far13|100|1000|tiling 13"
  "tiling_far21|100|1000|tiling 21"
  "tiling_far25|100|300|tiling 25"
  "tiling_far26|100|300|tiling 26"
  "tiling_far27|100|300|tiling 27"
  "tiling_near25|100|0.2|tiling 25"
  "tiling_near27|100|0.2|tiling 27"
  "tiling_placed|100|6|tiling 9 scale 0.7 rotate <10, 30, 0> translate <0.3, 0, -1>"
  "tiling_wave|100|6|tiling 7 frequency 2 phase 0.1 sine_wave"
  "tiling_turbulence|100|6|tiling 17 turbulence 0.3"
  "tiling_byte|100|6|tiling 258.7"
)
{
  header
  echo "#fopen Out \"$work/tilings.csv\" write"
  echo '#write (Out, "case,kx,ky,kz,value\n")'
  i=0
  for c in "${tiling_cases[@]}"; do
    IFS='|' read -r name count range text <<<"$c"
    i=$((i + 1))
    echo "#declare P$i = function { pigment { $text color_map { [0 rgb 0] [1 rgb 1] } } }"
    echo "#declare F$i = function { P$i(x, y, z).red }"
    echo "#macro Row(KX, KY, KZ, X, Y, Z)"
    echo "  #write (Out, \"$name,\", Ints(KX, KY, KZ), \",\", str(F$i(X, Y, Z), 0, 17), \"\\n\")"
    echo "#end"
    echo "Points($count, $((500 + i)), $range)"
  done
  echo "#fclose Out"
} >"$work/tilings.pov"
run_pov "$work/tilings.pov" +W8 +H8 "+O$work/discard.png"
cp "$work/tilings.csv" "$out/tilings.csv"

# --- pavements.csv: POV-Ray's pavements, every arrangement and every corner modifier ----------
# tests/patterns/pavement_test.cpp reads the case names: sSIDES_tTILES_pN (60 points with the
# default modifiers) and sSIDES_tTILES_pN_eE_iI_fF (3 points each of every exterior, interior
# and form, 0..2, 0..2 and 0..3), and two placed cases. Read through a grey pigment as the
# tilings are (POV-Ray 3.7 takes neither in a pattern function).
{
  header
  cat <<POV
#fopen Out "$work/pavements.csv" write
#write (Out, "case,kx,ky,kz,value\n")
#declare P = 0;
#declare G = 0;
#macro Pavement(S, T, N, E, I, F, Name, Count, Seed)
  #undef P
  #undef G
  #declare P = function { pigment { pavement number_of_sides S number_of_tiles T pattern N
    exterior E interior I form F color_map { [0 rgb 0] [1 rgb 1] } } }
  #declare G = function { P(x, y, z).red }
  #macro Row(KX, KY, KZ, X, Y, Z)
    #write (Out, Name, ",", Ints(KX, KY, KZ), ",", str(G(X, Y, Z), 0, 17), "\n")
  #end
  Points(Count, Seed, 8)
#end
#declare Counts = array[3][6] { {1, 1, 1, 3, 4, 12}, {1, 1, 2, 5, 12, 35}, {1, 1, 3, 7, 22, 0} }
#declare Sides = array[3] { 3, 4, 6 }
#declare Seed = 700;
#for (K, 0, 2)
  #for (T, 1, 6)
    #for (N, 1, Counts[K][T - 1])
      #declare Base = concat("s", str(Sides[K], 0, 0), "_t", str(T, 0, 0), "_p", str(N, 0, 0));
      #declare Seed = Seed + 1;
      Pavement(Sides[K], T, N, 0, 0, 0, Base, 60, Seed)
      #for (E, 0, 2) #for (I, 0, 2) #for (F, 0, 3)
        #declare Seed = Seed + 1;
        Pavement(Sides[K], T, N, E, I, F,
                 concat(Base, "_e", str(E, 0, 0), "_i", str(I, 0, 0), "_f", str(F, 0, 0)), 3, Seed)
      #end #end #end
    #end
  #end
#end
#undef P
#undef G
#declare P = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 8
  interior 2 scale 0.7 rotate <10, 30, 0> translate <0.3, 0, -1> color_map { [0 rgb 0] [1 rgb 1] } } }
#declare G = function { P(x, y, z).red }
#macro Row(KX, KY, KZ, X, Y, Z)
  #write (Out, "pavement_placed,", Ints(KX, KY, KZ), ",", str(G(X, Y, Z), 0, 17), "\n")
#end
Points(100, 690, 6)
#undef P
#undef G
#declare P = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2
  form 2 frequency 2 phase 0.1 sine_wave turbulence 0.3 color_map { [0 rgb 0] [1 rgb 1] } } }
#declare G = function { P(x, y, z).red }
#macro Row(KX, KY, KZ, X, Y, Z)
  #write (Out, "pavement_waved,", Ints(KX, KY, KZ), ",", str(G(X, Y, Z), 0, 17), "\n")
#end
Points(100, 691, 6)
#fclose Out
POV
} >"$work/pavements.pov"
run_pov "$work/pavements.pov" +W8 +H8 "+O$work/discard.png"
cp "$work/pavements.csv" "$out/pavements.csv"

# --- normals.csv: perturbed normals, rendered ----------------------------------------------
# A plane z = 0 facing the camera (normal -z) seen by an orthographic camera over the square
# of side 4 centred at (0.375, -1.25), 16x16 pixels, pixel (i, j) at x = 0.375 + 4((i+0.5)/16
# - 0.5), y = -1.25 + 4(0.5 - (j+0.5)/16). Three shadowless parallel lights, red from -z, green
# from (1, 0, -1)/√2, blue from (0, 1, -1)/√2, on a white surface with diffuse 1 and no ambient:
# each 16-bit channel is 65535·max(0, N·L) for its light, N the perturbed normal.
normal_cases=(
  "bumps|bumps 0.5"
  "bumps_scaled|bumps 0.8 scale <0.5, 1.5, 1>"
  "bumps_turbulence|bumps 0.5 turbulence 0.4"
  "dents|dents 0.9"
  "dents_generator1|dents 0.9 noise_generator 1"
  "wrinkles|wrinkles 0.4"
  "ripples|ripples 0.6 frequency 3"
  "waves|waves 0.7 frequency 2 phase 0.1"
  "granite|granite 0.3"
  "bozo|bozo 0.6 scale 0.5"
  "marble|marble 0.5 turbulence 0.5"
  "crackle|crackle 0.5"
  "agate|agate 0.4"
  "onion|onion 0.5 sine_wave"
  "leopard|leopard 0.5 scale 0.2"
  "gradient|gradient x 0.5 frequency 2"
  "wood|wood 0.5 turbulence 0.1"
  "spiral1|spiral1 3 0.5"
  "spiral2|spiral2 2 0.5"
  "radial|radial 0.4 frequency 6"
  "spotted|spotted 0.5 noise_generator 3"
  "slope_rotated|granite 0.6 rotate <20, 30, 40> scale <1, 0.5, 2>"
  "planar|planar 0.8"
  "planar_rotated|planar 0.6 rotate <0, 0, 40> scale 1.5"
  "quilted|quilted 0.6 control0 0.5 control1 0.8 scale 0.7"
  "mandel|mandel 30 0.5 scale 1.5"
  "normal_map|gradient x normal_map { [0.3 bumps 0.6 scale 0.5] [0.7 marble 0.5 turbulence 0.5] } scale 2"
  "normal_map_three|bozo normal_map { [0.2 ripples 0.6 frequency 3] [0.5 granite 0.3] [0.8 leopard 0.5 scale 0.2] } scale 0.7"
  "checker_normals|checker normal { bumps 0.8 scale 0.3 } normal { wrinkles 0.5 } scale 0.9"
  "hexagon_normals|hexagon normal { ripples 0.5 } normal { granite 0.4 } normal { bumps 0.7 } rotate x * 90 scale 0.6"
  "brick_normals|brick normal { granite 0.3 } normal { bumps 0.8 scale 0.2 } brick_size <1, 0.4, 0.6> mortar 0.1"
  "slope_map|onion 0.8 slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] [1 <0, -1>] } scale 0.6"
  "slope_map_sine|gradient <1, 1, 0> 0.6 slope_map { [0 <0.5, 1>] [0.25 <1, 0>] [0.5 <0.5, -1>] [0.75 <0, 0>] [1 <0.5, 1>] } scale 0.8"
  "slope_map_granite|granite 0.5 slope_map { [0 <0, 0>] [0.4 <0.2, 2>] [1 <1, 0>] }"
  "checker_slope|checker 0.5 scale 0.7"
  "hexagon_slope|hexagon 0.6 rotate x * 90 scale 0.5"
  "brick_slope|brick 0.75 brick_size <1, 0.4, 0.6> mortar 0.1"
  "spherical|spherical 0.7 scale 2"
  "cylindrical|cylindrical 0.5 scale 1.5 rotate <0, 0, 30>"
  "boxed|boxed 0.6 scale 1.7 rotate <0, 0, 20>"
  "cells|cells 0.5 scale 0.6"
  "pigment_pattern|pigment_pattern { granite scale 0.5 } 0.6"
)
echo "case,i,j,r,g,b" >"$work/normals.csv"
for c in "${normal_cases[@]}"; do
  IFS='|' read -r name text <<<"$c"
  cat >"$work/normal.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.375, -1.25, -10> direction z right 4 * x up 4 * y }
light_source { <0, 0, -1000> rgb <1, 0, 0> parallel point_at 0 shadowless }
light_source { <1000, 0, -1000> rgb <0, 1, 0> parallel point_at 0 shadowless }
light_source { <0, 1000, -1000> rgb <0, 0, 1> parallel point_at 0 shadowless }
plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { $text } }
POV
  run_pov "$work/normal.pov" +W16 +H16 +FN16 File_Gamma=1.0 "+O$work/normal.png"
  oiiotool --dumpdata "$work/normal.png" |
    sed -n 's/^ *Pixel (\([0-9]*\), \([0-9]*\)): \([0-9]*\) \([0-9]*\) \([0-9]*\) .*/\1,\2,\3,\4,\5/p' |
    sed "s/^/$name,/" >>"$work/normals.csv"
done
cp "$work/normals.csv" "$out/normals.csv"

echo "references written to $out"
