// Warps from the unit square [0,1)^2 to other domains. Every warp sits beside its density, named
// from the same stem, with the measure the density is taken in; a density returns 0 outside its
// warp's domain, so it can be integrated over a larger one. Inverses map a point back to the u
// that produced it, where that is cheap.
#include "constants.glsl"

// Angle of (x, y) in [0, 2pi).
float azimuth(vec2 p) {
    float phi = atan(p.y, p.x);
    return phi < 0.0 ? phi + kTwoPi : phi;
}

// ---- Uniform disk, polar mapping (r = sqrt(u.x)): simple, but squashes strata near the centre.
vec2 sampleUniformDiskPolar(vec2 u) {
    float r = sqrt(u.x);
    float phi = kTwoPi * u.y;
    return vec2(r * cos(phi), r * sin(phi));
}

// Area density on the unit disk (shared by both disk warps).
float uniformDiskPdf(vec2 p) {
    return dot(p, p) <= 1.0 ? kInvPi : 0.0;
}

vec2 invertUniformDiskPolar(vec2 p) {
    return vec2(dot(p, p), azimuth(p) / kTwoPi);
}

// ---- Uniform disk, concentric mapping (Shirley and Chiu 1997): squares to rings, so strata
// keep their shape and area.
vec2 sampleUniformDiskConcentric(vec2 u) {
    vec2 offset = 2.0 * u - 1.0;
    if (offset.x == 0.0 && offset.y == 0.0) return vec2(0.0);
    float r, theta;
    if (abs(offset.x) > abs(offset.y)) {
        r = offset.x;
        theta = 0.25 * kPi * (offset.y / offset.x);
    } else {
        r = offset.y;
        theta = 0.5 * kPi - 0.25 * kPi * (offset.x / offset.y);
    }
    return r * vec2(cos(theta), sin(theta));
}

vec2 invertUniformDiskConcentric(vec2 p) {
    float r = length(p);
    if (r == 0.0) return vec2(0.5);
    float phi = atan(p.y, p.x); // (-pi, pi]
    vec2 offset;
    if (abs(phi) <= 0.25 * kPi) {            // right wedge: r = offset.x > 0
        offset = vec2(r, 4.0 * phi / kPi * r);
    } else if (abs(phi) >= 0.75 * kPi) {     // left wedge: r = offset.x < 0, angle shifted by pi
        float theta = phi > 0.0 ? phi - kPi : phi + kPi;
        offset = vec2(-r, 4.0 * theta / kPi * -r);
    } else if (phi > 0.0) {                  // top wedge: r = offset.y > 0
        offset = vec2((2.0 - 4.0 * phi / kPi) * r, r);
    } else {                                 // bottom wedge: r = offset.y < 0, angle shifted by pi
        float theta = phi + kPi;
        offset = vec2((2.0 - 4.0 * theta / kPi) * -r, -r);
    }
    return 0.5 * (offset + 1.0);
}

// ---- Uniform sphere.
vec3 sampleUniformSphere(vec2 u) {
    float z = 1.0 - 2.0 * u.x;
    float r = sqrt(max(0.0, 1.0 - z * z));
    float phi = kTwoPi * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

// Solid-angle density.
float uniformSpherePdf(vec3 w) {
    return 0.25 * kInvPi;
}

vec2 invertUniformSphere(vec3 w) {
    return vec2(0.5 * (1.0 - w.z), azimuth(w.xy) / kTwoPi);
}

// ---- Uniform spherical cap around +z: the cone of directions within thetaMax of the axis.
// Sphere lights sample the cap they subtend, spot lights their cone.
vec3 sampleUniformCone(vec2 u, float cosThetaMax) {
    float cosTheta = (1.0 - u.x) + u.x * cosThetaMax;
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = kTwoPi * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// Solid-angle density.
float uniformConePdf(vec3 w, float cosThetaMax) {
    return w.z >= cosThetaMax ? 1.0 / (kTwoPi * (1.0 - cosThetaMax)) : 0.0;
}

vec2 invertUniformCone(vec3 w, float cosThetaMax) {
    return vec2((1.0 - w.z) / (1.0 - cosThetaMax), azimuth(w.xy) / kTwoPi);
}

// ---- Uniform hemisphere around +z.
vec3 sampleUniformHemisphere(vec2 u) {
    float z = u.x;
    float r = sqrt(max(0.0, 1.0 - z * z));
    float phi = kTwoPi * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

// Solid-angle density.
float uniformHemispherePdf(vec3 w) {
    return w.z >= 0.0 ? 0.5 * kInvPi : 0.0;
}

vec2 invertUniformHemisphere(vec3 w) {
    return vec2(w.z, azimuth(w.xy) / kTwoPi);
}

// ---- Cosine-weighted hemisphere around +z (Malley's method: lift the concentric disk).
vec3 sampleCosineHemisphere(vec2 u) {
    vec2 d = sampleUniformDiskConcentric(u);
    return vec3(d, sqrt(max(0.0, 1.0 - dot(d, d))));
}

// Solid-angle density.
float cosineHemispherePdf(float cosTheta) {
    return max(cosTheta, 0.0) * kInvPi;
}

vec2 invertCosineHemisphere(vec3 w) {
    return invertUniformDiskConcentric(w.xy);
}

// ---- Uniform triangle: barycentrics (b0, b1) of the triangle, b2 = 1 - b0 - b1.
vec2 sampleUniformTriangle(vec2 u) {
    float s = sqrt(u.x);
    return vec2(1.0 - s, u.y * s);
}

// Density over the (b0, b1) plane, where the triangle has area 1/2. For a triangle of area A in
// space, the area density is 1/A.
float uniformTrianglePdf(vec2 b) {
    return (b.x >= 0.0 && b.y >= 0.0 && b.x + b.y <= 1.0) ? 2.0 : 0.0;
}

vec2 invertUniformTriangle(vec2 b) {
    float s = 1.0 - b.x;
    return vec2(s * s, s > 0.0 ? b.y / s : 0.0);
}

// ---- Henyey-Greenstein: directions about +z, the direction of travel, with the phase function
// (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2)) as density; g in (-1, 1) is the mean cosine,
// g > 0 scatters forward (as in pbrt and Cycles). Inverts the CDF of mu = cos theta,
// F(mu) = (1 - g) (1 + mu) / (d (1 + g + d)), d = sqrt(1 + g^2 - 2 g mu): with s = (1 - g^2) /
// (1 - g + 2 g u), 1 - mu = (1 - g)(1 - u)(1 - g + s) / (1 - g + 2 g u) and 1 + mu = (1 + g) u
// (1 + g + s) / (1 - g + 2 g u). Written so, without the textbook's 1 / (2 g), they hold at g = 0
// (uniform) and lose no digits near the poles, where a strongly peaked lobe puts its samples:
// sin theta comes from the product, not from 1 - cos^2.
vec3 sampleHenyeyGreenstein(vec2 u, float g) {
    float denominator = 1.0 - g + 2.0 * g * u.x;
    float s = (1.0 - g * g) / denominator;
    float oneMinusCos = (1.0 - g) * (1.0 - u.x) * (1.0 - g + s) / denominator;
    float onePlusCos = (1.0 + g) * u.x * (1.0 + g + s) / denominator;
    float cosTheta = clamp(oneMinusCos < onePlusCos ? 1.0 - oneMinusCos : onePlusCos - 1.0, -1.0, 1.0);
    float sinTheta = sqrt(max(0.0, oneMinusCos * onePlusCos));
    float phi = kTwoPi * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// Solid-angle density (the phase function itself: it integrates to 1 over the sphere).
float henyeyGreensteinPdf(float cosTheta, float g) {
    float d2 = 1.0 + g * g - 2.0 * g * cosTheta;
    return 0.25 * kInvPi * (1.0 - g * g) / (d2 * sqrt(d2));
}

vec2 invertHenyeyGreenstein(vec3 w, float g) {
    float d = sqrt(1.0 + g * g - 2.0 * g * w.z);
    return vec2((1.0 - g) * (1.0 + w.z) / (d * (1.0 + g + d)), azimuth(w.xy) / kTwoPi);
}
