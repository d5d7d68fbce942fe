// Environment maps: radiance from an equirectangular image around the scene, importance sampled
// in proportion to luminance with a piecewise-constant 2D distribution (pbrt's Distribution2D,
// built by renderer/scene/EnvironmentMap.cpp). Without a map the environment is the constant colour
// uEnvironmentRadiance, sampled uniformly over the sphere.
//
// Orientation (docs/scene-format.md). Texel (i, j) of a W x H map, row j = 0 the TOP row of the
// image, covers u in [i/W, (i+1)/W) and v in [j/H, (j+1)/H). With theta = pi v the angle from +Y
// and phi = 2 pi u, the map's direction is
//     d(u, v) = (-sin(phi) sin(theta), cos(theta), cos(phi) sin(theta)):
// v = 0 is straight up, the image's centre (u = 0.5) looks along -Z, u = 0.75 along +X, u = 0 and 1
// along +Z. Seen from inside, the image is not mirrored. uEnvironmentRotation turns the map about +Y
// by the right-hand rule, world = R_y(rotation) d, which subtracts the rotation from the azimuth:
// at +90 degrees the image's centre looks along -X.
//
// Densities are in solid angle. The map's density in (u, v) is constant over each texel (pdfUv),
// and d omega = 2 pi^2 sin(theta) du dv, so pdfSolidAngle = pdfUv / (2 pi^2 sin(theta)). The
// density reads each texel's probability from the same float CDFs that the sampler searches, so it
// is exactly the density sampled (not an approximation of luminance x sin(theta)); a texel of
// probability 0 (black) is never chosen.
#include "constants.glsl"
#include "frame_uniforms.glsl"
#include "warps.glsl"

uniform sampler2D uEnvironmentMap;            // RGBA32F, W x H, linear radiance (alpha unused)
uniform sampler2D uEnvironmentMarginalCdf;    // R32F, H x 1: probability of rows 0..j
uniform sampler2D uEnvironmentConditionalCdf; // R32F, W x H: probability of columns 0..i within row j
uniform bool uHasEnvironmentMap;
uniform float uEnvironmentIntensity;          // scales the map's radiance
uniform float uEnvironmentRotation;           // radians in [0, 2 pi), about +Y

// ---- Directions and map coordinates

// (u, v) in [0, 1]^2 of a world direction (need not be unit).
vec2 environmentMapUv(vec3 dirWorld) {
    float sinThetaScaled = length(dirWorld.xz);
    // atan(0, 0) is undefined in GLSL; at the poles any azimuth will do.
    float phi = sinThetaScaled > 0.0 ? atan(-dirWorld.x, dirWorld.z) : 0.0;
    float u = fract((phi + uEnvironmentRotation) * (0.5 * kInvPi));
    float v = atan(sinThetaScaled, dirWorld.y) * kInvPi; // better than acos near the poles
    return vec2(u, v);
}

// The texel holding (u, v); u or v of exactly 1 (fract's rounding, the south pole) stays in range.
ivec2 environmentMapTexel(vec2 uv) {
    ivec2 size = textureSize(uEnvironmentMap, 0);
    return min(ivec2(uv * vec2(size)), size - 1);
}

// The unit world direction of map coordinates (u, v). theta is measured from the nearer pole:
// near the south pole pi * v would carry float pi's rounding (a relative error of 1e-4 in
// sin(theta) in the last row of a 512-row map), while 1 - v is exact.
vec3 environmentMapDirection(vec2 uv) {
    float thetaFromPole = kPi * min(uv.y, 1.0 - uv.y);
    float sinTheta = sin(thetaFromPole);
    float cosTheta = uv.y <= 0.5 ? cos(thetaFromPole) : -cos(thetaFromPole);
    float phi = kTwoPi * uv.x - uEnvironmentRotation;
    return vec3(-sin(phi) * sinTheta, cosTheta, cos(phi) * sinTheta);
}

vec3 environmentMapRadiance(vec3 dirWorld) {
    return uEnvironmentIntensity * texelFetch(uEnvironmentMap, environmentMapTexel(environmentMapUv(dirWorld)), 0).rgb;
}

// ---- The piecewise-constant distribution

// The first entry of row `row` of cdf (count entries along x) that is above u: the texel whose
// interval [cdf[k - 1], cdf[k]) holds u. An interval of width 0 never holds u, so a texel of
// probability 0 is never returned; the last entry is exactly 1, so some entry is above u < 1.
int searchEnvironmentCdf(sampler2D cdf, int row, int count, float u) {
    int low = 0;
    int high = count - 1;
    while (low < high) {
        int middle = (low + high) / 2;
        if (u < texelFetch(cdf, ivec2(middle, row), 0).r) high = middle; else low = middle + 1;
    }
    return low;
}

// (cdf[k - 1], cdf[k]) of row `row`, with cdf[-1] = 0.
vec2 environmentCdfInterval(sampler2D cdf, int k, int row) {
    float below = k > 0 ? texelFetch(cdf, ivec2(k - 1, row), 0).r : 0.0;
    return vec2(below, texelFetch(cdf, ivec2(k, row), 0).r);
}

// Density in (u, v) of the texel: its probability times the texel count.
float environmentMapTexelPdfUv(ivec2 texel) {
    ivec2 size = textureSize(uEnvironmentConditionalCdf, 0);
    vec2 row = environmentCdfInterval(uEnvironmentMarginalCdf, texel.y, 0);
    vec2 column = environmentCdfInterval(uEnvironmentConditionalCdf, texel.x, texel.y);
    return (row.y - row.x) * float(size.y) * (column.y - column.x) * float(size.x);
}

// Map coordinates drawn with density pdfUv in (u, v): a row from the marginal CDF with u.y, a
// column from that row's conditional CDF with u.x, and where u falls within each chosen interval
// as the position within the texel.
vec2 sampleEnvironmentMapUv(vec2 u, out float pdfUv) {
    u = min(u, vec2(0.99999994)); // u = 1 (outside [0, 1)) would find the last entry, even a black one
    ivec2 size = textureSize(uEnvironmentConditionalCdf, 0);
    int row = searchEnvironmentCdf(uEnvironmentMarginalCdf, 0, size.y, u.y);
    int column = searchEnvironmentCdf(uEnvironmentConditionalCdf, row, size.x, u.x);
    vec2 rowCdf = environmentCdfInterval(uEnvironmentMarginalCdf, row, 0);
    vec2 columnCdf = environmentCdfInterval(uEnvironmentConditionalCdf, column, row);
    float dv = (u.y - rowCdf.x) / (rowCdf.y - rowCdf.x);
    float du = (u.x - columnCdf.x) / (columnCdf.y - columnCdf.x);
    pdfUv = (rowCdf.y - rowCdf.x) * float(size.y) * (columnCdf.y - columnCdf.x) * float(size.x);
    return vec2((float(column) + du) / float(size.x), (float(row) + dv) / float(size.y));
}

// Solid-angle density with which sampleEnvironmentMap produces dirWorld (need not be unit); 0 at
// the poles and in black texels.
float environmentMapPdf(vec3 dirWorld) {
    float sinTheta = length(dirWorld.xz) / length(dirWorld);
    if (!(sinTheta > 0.0)) return 0.0;
    return environmentMapTexelPdfUv(environmentMapTexel(environmentMapUv(dirWorld))) / (2.0 * kPi * kPi * sinTheta);
}

// A world direction drawn in proportion to the map's luminance, with its solid-angle density.
// That density is environmentMapPdf of the direction as returned, not pdfUv / (2 pi^2 sin(theta))
// of the texel it was drawn from: the two differ only where float rounding moves the direction
// across a texel edge (about 1 sample in 4000 on a 1024 x 512 map), and then the radiance looked
// up for the direction, this density and the MIS weights all still come from one texel (a drawn
// sun texel must not be weighed with a dim neighbour's radiance, nor a dim texel with the sun's).
// A direction at a pole (u.y = 0 in the top row) or rounded into a black texel fails with pdf 0.
vec3 sampleEnvironmentMap(vec2 u, out float pdfSolidAngle) {
    float pdfUv;
    vec3 dirWorld = environmentMapDirection(sampleEnvironmentMapUv(u, pdfUv));
    pdfSolidAngle = environmentMapPdf(dirWorld);
    return dirWorld;
}

// ---- The environment as the integrators see it: the map when there is one, else the constant
// colour (sampled uniformly over the sphere).

vec3 environmentRadiance(vec3 dirWorld) {
    return uHasEnvironmentMap ? environmentMapRadiance(dirWorld) : uEnvironmentRadiance;
}

vec3 sampleEnvironment(vec2 u, out float pdfSolidAngle) {
    if (uHasEnvironmentMap) return sampleEnvironmentMap(u, pdfSolidAngle);
    pdfSolidAngle = uniformSpherePdf(vec3(0.0));
    return sampleUniformSphere(u);
}

float environmentPdf(vec3 dirWorld) {
    return uHasEnvironmentMap ? environmentMapPdf(dirWorld) : uniformSpherePdf(dirWorld);
}
