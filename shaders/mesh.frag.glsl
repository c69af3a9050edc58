#version 330 core
// Blinn-Phong with a headlight and a dim fill light; two-sided so cut surfaces still read.
in vec3 vWorldPosition;
in vec3 vWorldNormal;
uniform vec3 uColor;
uniform vec3 uCameraPosition;
uniform float uAmbient;
uniform float uAlpha;  // 1 opaque; below 1 translucent (the MRI slice mode's surface)
out vec4 fragColor;
void main() {
    vec3 n = normalize(vWorldNormal);
    vec3 toEye = normalize(uCameraPosition - vWorldPosition);
    if (dot(n, toEye) < 0.0) n = -n;
    vec3 fill = normalize(vec3(0.3, -0.5, 0.8));
    float diffuse = max(dot(n, toEye), 0.0) * 0.75 + max(dot(n, fill), 0.0) * 0.25;
    // Headlight: the half vector between light and eye is the eye direction itself.
    float specular = pow(max(dot(n, toEye), 0.0), 48.0) * 0.25;
    vec3 color = uColor * (uAmbient + (1.0 - uAmbient) * diffuse) + vec3(specular);
    fragColor = vec4(color, uAlpha);
}
