#declare A = array[3] { 1, 2 };
