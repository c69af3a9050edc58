#version 330 core
// Lit surfaces of the 3D view (the bone, the X-ray source marker): world-space position and
// normal for the fragment shader.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uViewProjection;
out vec3 vWorldPosition;
out vec3 vWorldNormal;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = mat3(uModel) * aNormal;  // the model matrix is rigid (+ uniform scale)
    gl_Position = uViewProjection * world;
}
