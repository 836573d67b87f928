#version 450 core
// lpv.inject / lpv.geometry: routes each injected point to its cell's slice of the layered 3D
// target (gl_Layer), the paper's point-sprite injection.
layout(points) in;
layout(points, max_vertices = 1) out;

in VertexData {
  flat vec4 shR;
  flat vec4 shG;
  flat vec4 shB;
  flat int layer;
} vIn[];

out flat vec4 gShR;
out flat vec4 gShG;
out flat vec4 gShB;

void main() {
  gl_Position = gl_in[0].gl_Position;
  gl_PointSize = 1.0;
  gl_Layer = vIn[0].layer;
  gShR = vIn[0].shR;
  gShG = vIn[0].shG;
  gShB = vIn[0].shB;
  EmitVertex();
  EndPrimitive();
}
