#version 330 core
// The film: a quad in the scene textured with the user's DRR (already windowed to RGBA).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec2 aTexCoord;
uniform mat4 uViewProjection;
out vec2 vTexCoord;
void main() {
    vTexCoord = aTexCoord;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
