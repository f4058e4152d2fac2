#version 3.7;
ovus { 1, -0.5 }
