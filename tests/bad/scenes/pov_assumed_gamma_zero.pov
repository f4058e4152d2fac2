#version 3.7;
global_settings { assumed_gamma 0 }
