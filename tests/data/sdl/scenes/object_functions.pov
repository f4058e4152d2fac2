// trace(), inside(), min_extent() and max_extent() of declared objects, printed to 6
// decimals; POV-Ray's own output is object_functions.out (recorded with
// povray +Iobject_functions.pov -D -F +W1 +H1 -GA +GDobject_functions.out).
#version 3.7;
#declare Ball = sphere { <1, 2, 3>, 2 scale <1, 1, 2> }
#declare Block = box { <-1, -1, -1>, <1, 2, 3> rotate 30*y translate <0, 0, 5> }
#declare Bored = difference { box { -2, 2 } cylinder { -3*z, 3*z, 1 } }
#declare Ring = torus { 3, 0.5 rotate 90*x }
#macro V(A) concat("<", vstr(3, A, ", ", 0, 6), ">") #end
#macro Show(Name, O, From, Dir)
  #local N = <9, 9, 9>;
  #local P = trace(O, From, Dir, N);
  #debug concat(Name, " hit ", V(P), " normal ", V(N), "\n")
#end
Show("ball +z", Ball, <1, 2, -10>, z)
Show("ball -z", Ball, <1, 2, 20>, -z)
Show("ball slant", Ball, <-5, -3, 0>, <1, 1, 1>)
Show("ball miss", Ball, <10, 10, 10>, x)
Show("block x", Block, <-10, 0.5, 5>, x)
Show("block down", Block, <0.3, 10, 5.2>, -y)
Show("bored hole", Bored, <0, 0, -10>, z)
Show("bored side", Bored, <0.5, 1.5, -10>, z)
Show("ring", Ring, <0, 3, -10>, z)
#debug concat("inside ", str(inside(Ball, <1, 2, 3>), 0, 0), str(inside(Ball, <1, 2, 6.5>), 0, 0),
  str(inside(Ball, <1, 2, 7.5>), 0, 0), str(inside(Bored, <0, 0, 0>), 0, 0),
  str(inside(Bored, <1.5, 1.5, 0>), 0, 0), str(inside(Block, <0, 0, 5>), 0, 0), "\n")
#debug concat("ball extent ", V(min_extent(Ball)), " ", V(max_extent(Ball)), "\n")
#debug concat("bored extent ", V(min_extent(Bored)), " ", V(max_extent(Bored)), "\n")
#debug concat("ring extent ", V(min_extent(Ring)), " ", V(max_extent(Ring)), "\n")
// A text's box includes its blank glyphs' origins, as shapes.inc's Text_Width measures (its
// bounds lie within 4e-5 of POV-Ray's, which pads them: shifted by 1 and printed to 3
// decimals, so that no -0.000 appears).
#macro V3(A) concat("<", vstr(3, A + 1, ", ", 0, 3), ">") #end
#declare Blank = text { ttf "cyrvetic.ttf" " " 0.5, 0 }
#declare Spaced = text { ttf "cyrvetic.ttf" "l  " 1, 0 scale 2 }
#debug concat("blank extent ", V3(min_extent(Blank)), " ", V3(max_extent(Blank)), "\n")
#debug concat("spaced extent ", V3(min_extent(Spaced)), " ", V3(max_extent(Spaced)), "\n")
