// Sample generators. A path asks for numbers by dimension index (see the layout below), never
// "the next number", so every path dimension gets its own stratification and scrambling, and all
// four modes give each dimension the same meaning.
//
//   random      independent uniform numbers, hashed from (pixel, sample, dimension, seed)
//   grid        the cell centres of an n x n grid (n^2 <= budget): regular, for teaching; biased
//   stratified  one jittered point per cell of that grid, cells visited in a shuffled order
//   sobol       Sobol' (0,2)-sequence, Owen-scrambled per pixel and dimension (Burley 2020)
//
// grid and stratified cover one pattern of n^2 samples per pixel, then start another; sobol is
// best at power-of-two sample counts.
#include "rng.glsl"
// kSamplerRandom, ...: generated from the C++ table (renderer/gpu/GlslEnums.cpp).
#include "enums.glsl"

// Dimension layout of a path: the camera jitter, then a fixed block per bounce, so that a given
// bounce's BSDF sample is the same dimension in every path whatever happened before. The lens of a
// thin-lens camera has a dimension of its own beyond every bounce block (depth <= 1024 reaches
// dimension 5125), so adding it renumbered nothing: pinhole renders kept their exact bits.
const uint kDimensionCamera = 0u;            // 2D: position inside the pixel
const uint kDimensionLens = 65535u;          // 2D: position on the lens (thin-lens cameras only)
const uint kDimensionsPerBounce = 5u;
uint bsdfDimension(int bounce)              { return 1u + uint(bounce) * kDimensionsPerBounce; }      // 2D
uint bsdfLobeDimension(int bounce)          { return 1u + uint(bounce) * kDimensionsPerBounce + 1u; } // 1D
uint lightChoiceDimension(int bounce)       { return 1u + uint(bounce) * kDimensionsPerBounce + 2u; } // 1D
uint lightPositionDimension(int bounce)     { return 1u + uint(bounce) * kDimensionsPerBounce + 3u; } // 2D
uint russianRouletteDimension(int bounce)   { return 1u + uint(bounce) * kDimensionsPerBounce + 4u; } // 1D
// Free flight through media (media.glsl), beyond the lens: scenes without media keep their bits.
const uint kDimensionFreeFlight = 65536u;
uint freeFlightDimension(int bounce)        { return kDimensionFreeFlight + uint(bounce); }           // 2D

struct Sampler {
    uint mode;
    uint pixelSeed;
    uint sampleIndex;
    uint gridSide; // n: grid and stratified patterns have n^2 samples
};

Sampler createSampler(uvec2 pixel, uint sampleIndex, uint seed, uint mode, uint sampleBudget) {
    // Integer square root without trusting float sqrt to round the right way.
    uint side = uint(sqrt(float(max(sampleBudget, 1u))));
    while (side * side > sampleBudget && side > 1u) --side;
    while ((side + 1u) * (side + 1u) <= sampleBudget) ++side;
    return Sampler(mode, pcgHash(pixel.x + pcgHash(pixel.y + pcgHash(seed))), sampleIndex, max(side, 1u));
}

// A bijection of [0, length) chosen by `seed` (Kensler, "Correlated Multi-Jittered Sampling",
// 2013): a hash restricted to the next power of two, walking the cycle until it lands in range.
uint permuteIndex(uint index, uint length, uint seed) {
    uint mask = length - 1u;
    mask |= mask >> 1u; mask |= mask >> 2u; mask |= mask >> 4u; mask |= mask >> 8u; mask |= mask >> 16u;
    do {
        index ^= seed; index *= 0xe170893du; index ^= seed >> 16u;
        index ^= (index & mask) >> 4u; index ^= seed >> 8u; index *= 0x0929eb3fu; index ^= seed >> 23u;
        index ^= (index & mask) >> 1u; index *= 1u | seed >> 27u; index *= 0x6935fa69u;
        index ^= (index & mask) >> 11u; index *= 0x74dcb303u; index ^= (index & mask) >> 2u;
        index *= 0x9e501cc3u; index ^= (index & mask) >> 2u; index *= 0xc860a3dfu;
        index &= mask; index ^= index >> 5u;
    } while (index >= length);
    return (index + seed) % length;
}

// Owen scrambling by hashing (Laine and Karras 2011, constants from Burley 2020): a random
// permutation of the binary tree of intervals, applied to the reversed bits.
uint nestedUniformScramble(uint x, uint seed) {
    x = bitfieldReverse(x);
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return bitfieldReverse(x);
}

// The first two Sobol' dimensions: van der Corput, and the dimension from the polynomial x + 1.
uint sobolDimension0(uint index) {
    return bitfieldReverse(index);
}

uint sobolDimension1(uint index) {
    // Direction k is row k of Pascal's triangle mod 2, so (Lucas' theorem) output bit 31 - j is the
    // parity of the index bits i that hold j as a bit subset: a sum over supersets in five
    // shift-xor steps, then the bits in order. A loop over the index's bits would take 32 rounds,
    // since the shuffled index has its high bits set (12% of a Cornell box pass on llvmpipe).
    index ^= (index >> 1u) & 0x55555555u;
    index ^= (index >> 2u) & 0x33333333u;
    index ^= (index >> 4u) & 0x0f0f0f0fu;
    index ^= (index >> 8u) & 0x00ff00ffu;
    index ^= (index >> 16u) & 0x0000ffffu;
    return bitfieldReverse(index);
}

// (stratum + jitter) / strata, kept inside the stratum: the float sum stratum + jitter rounds up
// to stratum + 1 when jitter is within half an ulp of 1, which would put the sample in the next
// stratum, or at exactly 1.0 from the last one.
float jitterInStratum(uint stratum, float jitter, uint strata) {
    float belowNext = uintBitsToFloat(floatBitsToUint(float(stratum + 1u)) - 1u);
    return min(float(stratum) + jitter, belowNext) / float(strata);
}

uint dimensionSeed(Sampler sampler, uint dimension) {
    return pcgHash(sampler.pixelSeed ^ pcgHash(dimension + 0x9e3779b9u));
}

vec2 samplerGet2D(Sampler sampler, uint dimension) {
    uint seed = dimensionSeed(sampler, dimension);
    uint patternSize = sampler.gridSide * sampler.gridSide;
    if (sampler.mode == kSamplerGrid || sampler.mode == kSamplerStratified) {
        uint inPattern = sampler.sampleIndex % patternSize;
        vec2 offset = vec2(0.5);
        uint cell;
        if (sampler.mode == kSamplerGrid) {
            // The same grid in every pixel; only the visiting order differs between dimensions,
            // so dimensions are not trivially correlated.
            cell = permuteIndex(inPattern, patternSize, pcgHash(dimension + 0x68bc21ebu));
        } else {
            uint patternSeed = pcgHash(seed + sampler.sampleIndex / patternSize);
            cell = permuteIndex(inPattern, patternSize, patternSeed);
            uint jitter = pcgHash(patternSeed ^ pcgHash(inPattern));
            offset = vec2(uintToUnitFloat(jitter), uintToUnitFloat(pcgHash(jitter)));
        }
        return vec2(jitterInStratum(cell % sampler.gridSide, offset.x, sampler.gridSide),
                    jitterInStratum(cell / sampler.gridSide, offset.y, sampler.gridSide));
    }
    if (sampler.mode == kSamplerSobol) {
        uint index = nestedUniformScramble(sampler.sampleIndex, seed);
        return vec2(uintToUnitFloat(nestedUniformScramble(sobolDimension0(index), pcgHash(seed ^ 0x5bd1e995u))),
                    uintToUnitFloat(nestedUniformScramble(sobolDimension1(index), pcgHash(seed ^ 0x1b873593u))));
    }
    uint bits = pcgHash(seed ^ pcgHash(sampler.sampleIndex));
    return vec2(uintToUnitFloat(bits), uintToUnitFloat(pcgHash(bits)));
}

float samplerGet1D(Sampler sampler, uint dimension) {
    uint seed = dimensionSeed(sampler, dimension);
    uint patternSize = sampler.gridSide * sampler.gridSide;
    if (sampler.mode == kSamplerGrid || sampler.mode == kSamplerStratified) {
        uint inPattern = sampler.sampleIndex % patternSize;
        if (sampler.mode == kSamplerGrid)
            return (float(permuteIndex(inPattern, patternSize, pcgHash(dimension + 0x68bc21ebu))) + 0.5) /
                   float(patternSize);
        uint patternSeed = pcgHash(seed + sampler.sampleIndex / patternSize);
        uint stratum = permuteIndex(inPattern, patternSize, patternSeed);
        float jitter = uintToUnitFloat(pcgHash(patternSeed ^ pcgHash(inPattern)));
        return jitterInStratum(stratum, jitter, patternSize);
    }
    if (sampler.mode == kSamplerSobol) {
        uint index = nestedUniformScramble(sampler.sampleIndex, seed);
        return uintToUnitFloat(nestedUniformScramble(sobolDimension0(index), pcgHash(seed ^ 0x5bd1e995u)));
    }
    return uintToUnitFloat(pcgHash(seed ^ pcgHash(sampler.sampleIndex)));
}
