// light_paths.glsl for programs that show all the light: every contribution counts, and the
// history is nothing the compiler has to keep.
struct PathHistory {
    int unused;
};

PathHistory startPathHistory() { return PathHistory(0); }

void recordScattering(inout PathHistory history, bool deltaLobe) {}

float lightPathWeight(int bounces, PathHistory history, bool foundByBsdfSample) { return 1.0; }
