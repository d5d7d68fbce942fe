// Hashing for random numbers: the PCG output permutation used as a hash (Jarzynski and Olano,
// "Hash Functions for GPU Rendering", 2020). Good avalanche at the cost of a few integer ops.
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// The top 24 bits as a float in [0, 1): exactly representable, never 1.0.
float uintToUnitFloat(uint bits) {
    return float(bits >> 8u) * (1.0 / 16777216.0);
}
