#version 3.7;
parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> precompute 0, x }
