// rand() and seed(): POV-Ray's generator, several streams at once.
#version 3.7;
#declare R1 = seed(0);
#declare R2 = seed(12345);
#declare R3 = seed(-7);
#declare I = 0;
#while (I < 8)
  #debug concat(str(rand(R1), 0, 10), " ", str(rand(R2), 0, 10), " ", str(rand(R3), 0, 10), "\n")
  #declare I = I + 1;
#end
#debug concat(str(R1, 0, 0), str(R2, 0, 0), str(R3, 0, 0), "\n")
#declare S = seed(42.9);
#debug concat(str(rand(S), 0, 12), " ", str(rand(S), 0, 12), "\n")
#declare Big = seed(2147483647);
#debug concat(str(rand(Big), 0, 12), "\n")
