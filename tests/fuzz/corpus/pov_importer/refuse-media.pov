sphere { 0, 1 interior { media { emission 1 } } }
