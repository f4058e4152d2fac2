#version 3.7;
parametric { function { u } function { v } <0, 0>, <1, 1> }
