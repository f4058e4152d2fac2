#version 3.7;
ovus { 0, 0 }
