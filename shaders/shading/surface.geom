#version 450 core
// G-buffer only: passes surface.vert's triangles through and hands the fragment shader what the
// shadow terminator rule needs (shaders/common/terminator.glsl): the triangle's world vertices and
// vertex normals (flat) and the fragment's barycentrics.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vWorldPos[];
in vec3 vNormal[];
in vec4 vTangent[];
in vec2 vUv[];

out vec3 gWorldPos;
out vec3 gNormal;
out vec4 gTangent;
out vec2 gUv;
out vec3 gBarycentric;
flat out vec3 gTriPosition[3];
flat out vec3 gTriNormal[3];

void main() {
  for (int i = 0; i < 3; ++i) {
    gWorldPos = vWorldPos[i];
    gNormal = vNormal[i];
    gTangent = vTangent[i];
    gUv = vUv[i];
    gBarycentric = vec3(i == 0, i == 1, i == 2);
    for (int k = 0; k < 3; ++k) {
      gTriPosition[k] = vWorldPos[k];
      gTriNormal[k] = vNormal[k];
    }
    gl_Position = gl_in[i].gl_Position;
    gl_PrimitiveID = gl_PrimitiveIDIn;
    EmitVertex();
  }
  EndPrimitive();
}
