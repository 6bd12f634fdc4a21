// The same triangle written the way the seeds write GLSL: compatibility built-ins only.
out vec3 vNormal;
out vec2 vTexCoord;
void main() {
    vNormal = gl_NormalMatrix * gl_Normal;
    vTexCoord = gl_MultiTexCoord0.st;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
