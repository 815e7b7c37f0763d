#version 460
layout(location = 0) flat in uint inSurface;
layout(location = 0) out uint outSurface;

void main() { outSurface = inSurface; }
