// User-defined functions called in expressions, and functions.inc's closed forms: every
// number printed to 20 decimals, so that Lucent must give POV-Ray's doubles to the last bit.
#version 3.7;
#include "functions.inc"
#include "math.inc"
#macro Show(Label, V) #debug concat(Label, " ", str(V, 0, 20), "\n") #end
#declare A = function(a, b, c) { a*b + c/3 - pow(a, 3) + pow(b, 5) }
Show("A", A(1.1, 2.3, 0.7))
#declare B = function { sin(x)*cos(y) + tan(z) - atan2(x, y) + sqrt(abs(z)) + exp(x/7) }
Show("B", B(0.3, -1.7, 2.9))
#declare C = function(p) { ln(p) + log(p) + floor(p) + ceil(p) + int(-p) + mod(p, 0.7) + div(p, 0.3) }
Show("C", C(5.45))
#declare D = function { asin(x) + acos(y) + atan(z) + sinh(x) + cosh(y) + tanh(z) + radians(x*100) + degrees(y) }
Show("D", D(0.25, -0.5, 0.75))
#declare E = function { select(x, y, z) + select(x - 1, 10, 20, 30) + min(x, y, z) + max(x, y, 2*z) }
Show("E", E(1, 2, 3))
Show("E", E(-1, 2, 3))
#declare K = 7.5;
#declare G = function(q) { A(q, q + 1, q*2)*K - B(q, q, q) + sum(i, 1, 5, i*q) + prod(i, 1, 3, q + i) }
Show("G", G(0.45))
#declare H = function { (x < y) + (x <= y)*2 + (x = y)*4 + (x != y)*8 + (x >= y)*16 + (x > y)*32 + (x & y)*64 + (z | 0)*128 }
Show("H", H(1, 2, 0))
Show("H", H(2, 2, 1))
#declare I = function(u, v) { x*10 + y }
Show("I", I(3, 4))
Show("f_sphere", f_sphere(0.3, 1.2, -0.7, 0.9))
Show("f_r", f_r(0.3, 1.2, -0.7))
Show("f_th", f_th(0.3, 1.2, -0.7))
Show("f_ph", f_ph(0.3, 1.2, -0.7))
Show("f_rounded_box", f_rounded_box(0.9, -0.8, 0.2, 0.15, 0.5, 0.4, 0.3))
Show("f_rounded_box", f_rounded_box(0.1, 0.1, 0.1, 0.15, 0.5, 0.4, 0.3))
Show("f_superellipsoid", f_superellipsoid(0.3, 0.4, -0.5, 0.3, 0.6))
Show("f_torus", f_torus(1.2, 0.3, -0.4, 1, 0.25))
Show("f_torus2", f_torus2(1.2, 0.3, -0.4, 0.5, 1, 0.25))
Show("f_ellipsoid", f_ellipsoid(0.3, 1.2, -0.7, 1, 2, 3))
Show("f_paraboloid", f_paraboloid(0.3, 1.2, -0.7, 2))
Show("f_torus_gumdrop", f_torus_gumdrop(0.3, 1.2, -0.7, 0.5))
Show("f_umbrella", f_umbrella(0.3, 1.2, -0.7, 3))
Show("f_witch_of_agnesi", f_witch_of_agnesi(0.3, 1.2, -0.7, 1, 0.04))
Show("f_bicorn", f_bicorn(0.31, -0.42, 0.27, 0.05, 0.9))
Show("f_bifolia", f_bifolia(0.31, -0.42, 0.27, 0.05, 0.9))
Show("f_crossed_trough", f_crossed_trough(0.31, -0.42, 0.27, 0.05))
Show("f_cubic_saddle", f_cubic_saddle(0.31, -0.42, 0.27, 0.05))
Show("f_cushion", f_cushion(0.31, -0.42, 0.27, 0.05))
Show("f_devils_curve", f_devils_curve(0.31, -0.42, 0.27, 0.05))
Show("f_glob", f_glob(0.31, -0.42, 0.27, 0.05))
Show("f_heart", f_heart(0.31, -0.42, 0.27, 0.05))
Show("f_hunt_surface", f_hunt_surface(0.31, -0.42, 0.27, 0.05))
Show("f_hyperbolic_torus", f_hyperbolic_torus(0.31, -0.42, 0.27, 0.05, 0.9, 0.6))
Show("f_kampyle_of_eudoxus", f_kampyle_of_eudoxus(0.31, -0.42, 0.27, 0.05, 0.9, 0.6))
Show("f_klein_bottle", f_klein_bottle(0.31, -0.42, 0.27, 0.05))
Show("f_kummer_surface_v1", f_kummer_surface_v1(0.31, -0.42, 0.27, 0.05))
Show("f_kummer_surface_v2", f_kummer_surface_v2(0.31, -0.42, 0.27, 0.05, 0.9, 0.6, 0.35))
Show("f_lemniscate_of_gerono", f_lemniscate_of_gerono(0.31, -0.42, 0.27, 0.05))
Show("f_mitre", f_mitre(0.31, -0.42, 0.27, 0.05))
Show("f_nodal_cubic", f_nodal_cubic(0.31, -0.42, 0.27, 0.05))
Show("f_odd", f_odd(0.31, -0.42, 0.27, 0.05))
Show("f_ovals_of_cassini", f_ovals_of_cassini(0.31, -0.42, 0.27, 0.05, 0.9, 0.6, 0.35))
Show("f_parabolic_torus", f_parabolic_torus(0.31, -0.42, 0.27, 0.05, 0.9, 0.6))
Show("f_pillow", f_pillow(0.31, -0.42, 0.27, 0.05))
Show("f_quartic_paraboloid", f_quartic_paraboloid(0.31, -0.42, 0.27, 0.05))
Show("f_quartic_saddle", f_quartic_saddle(0.31, -0.42, 0.27, 0.05))
Show("f_quartic_cylinder", f_quartic_cylinder(0.31, -0.42, 0.27, 0.05, 0.9, 0.6))
Show("f_steiners_roman", f_steiners_roman(0.31, -0.42, 0.27, 0.05))
Show("f_folium_surface", f_folium_surface(0.31, -0.42, 0.27, 0.05, 0.9, 0.6))
// f_helix1: abyss.pov's cable (circles), a rounded rectangle turned 30 degrees, a square,
// a diamond, a point on the axis and one whose angle steps below 0 before the modulo.
Show("f_helix1", f_helix1(0.012, 0.4, -0.009, 3, 35, 0.0105, 0.0165, 2, 1, 0))
Show("f_helix1", f_helix1(0.8, 0.3, 0.5, 2, 1.5, 0.1, 0.9, 1.3, 0.5, 30))
Show("f_helix1", f_helix1(-0.6, -1.7, 0.45, 1, 2, 0.2, 0.7, 1, 0, 0))
Show("f_helix1", f_helix1(0.2, 0.9, -0.75, 4, 0.8, 0.15, 0.6, 0.7, 2, 0))
Show("f_helix1", f_helix1(0, 0.35, 0, 3, 1, 0.1, 0.5, 1, 1, 0))
Show("f_helix1", f_helix1(-0.3, -2.2, -0.4, 2, 1.1, 0.1, 0.5, 1, 0.3, -45))
#declare S = function { f_sphere(x, y, z, 1) - 0.2*f_rounded_box(x, y, z, 0.1, 1, 1, 1) }
Show("S", S(0.5, 0.6, 0.7))
Show("even", even(6) + 10*odd(7))
