// media.glsl for programs of scenes without a participating medium: the same declarations with
// nothing behind them, so that the integrator compiles unchanged and the compiler drops its
// media code (mediaInScene() is the constant false).
#include "intersect.glsl"

struct MediumStack {
    ivec4 materials;
    int depth;
};

struct Medium {
    vec3 sigmaA;
    vec3 sigmaS;
    float g;
};

struct MediumVertex {
    vec3 posWorld;
    Medium medium;
};

bool mediaInScene() { return false; }

MediumStack cameraMediumStack() { return MediumStack(ivec4(0), 0); }

MediumStack mediaToward(MediumStack stack, int material, vec3 normalGeom, vec3 woWorld, vec3 wiWorld) { return stack; }

vec3 shadowTransmittance(Ray ray, float maxDistance, int light, MediumStack stack) { return vec3(1.0); }

const int kFlightSurface = 0;
const int kFlightEscaped = 1;
const int kFlightScattered = 2;
const int kFlightLost = 3;

int flyToNextVertex(Ray ray, inout MediumStack stack, inout vec3 throughput, vec2 u, out Hit hit,
                    out MediumVertex scattering) {
    scattering = MediumVertex(vec3(0.0), Medium(vec3(0.0), vec3(0.0), 0.0));
    return intersectScene(ray, hit) ? kFlightSurface : kFlightEscaped;
}

bool intersectSurface(Ray ray, out Hit hit) { return intersectScene(ray, hit); }

int nullBoundariesBefore(Ray ray, out ivec4 materials, out vec4 distances) {
    materials = ivec4(-1);
    distances = vec4(-1.0);
    return 0;
}
