#version 300 es
// just a comment
