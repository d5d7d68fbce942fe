// Independent uniform random numbers from a PCG generator (O'Neill 2014): one 32-bit LCG state per
// pixel sample, seeded by hashing pixel, frame and user seed so neighbouring pixels and successive
// frames are decorrelated.

uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

struct Rng {
    uint state;
};

Rng rngCreate(uvec2 pixel, uint frameIndex, uint seed) {
    return Rng(pcgHash(pixel.x + pcgHash(pixel.y + pcgHash(frameIndex + pcgHash(seed)))));
}

// Uniform in [0, 1): the top 24 bits, so the result is exactly representable and never 1.0.
float rngNextFloat(inout Rng rng) {
    rng.state = rng.state * 747796405u + 2891336453u;
    uint word = ((rng.state >> ((rng.state >> 28u) + 4u)) ^ rng.state) * 277803737u;
    word = (word >> 22u) ^ word;
    return float(word >> 8u) * (1.0 / 16777216.0);
}

vec2 rngNextFloat2(inout Rng rng) {
    float u0 = rngNextFloat(rng);
    return vec2(u0, rngNextFloat(rng));
}
