// `--backend auto`: the decision rule, the cache of decisions, and the path tracer using both.
#include <ptview/tracer/BackendChoice.h>
#include "GlTestContext.h"
#include <ptview/tracer/PathTracer.h>
#include <ptview/scene/SceneLoader.h>
#include "TestFiles.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include <sys/stat.h>

namespace ptview {
namespace {

TEST(DecideBackend, TakesComputeOnlyWhenTheMedianRoundIsFasterByTheMargin) {
    EXPECT_EQ(decideBackend({{2.0, 1.0}, {2.0, 1.0}, {2.0, 1.0}}).backend, Backend::Compute);
    EXPECT_DOUBLE_EQ(decideBackend({{2.0, 1.0}, {2.0, 1.0}, {2.0, 1.0}}).computeSpeedup, 2.0);
    // A near tie stays on fragment, the backend every device has, so it cannot flip run to run.
    EXPECT_EQ(decideBackend({{1.05, 1.0}, {1.0, 1.0}, {1.08, 1.0}}).backend, Backend::Fragment);
    EXPECT_EQ(decideBackend({{1.0, 2.0}}).backend, Backend::Fragment);
}

TEST(DecideBackend, OneSlowRoundDoesNotDecide) {
    // A busy moment made one fragment round 10x slower; the median of the per-round ratios (not
    // the ratio of summed times, which that round would dominate) still says fragment.
    BackendChoice choice = decideBackend({{1.0, 1.2}, {10.0, 1.2}, {1.0, 1.2}, {1.0, 1.1}, {1.0, 1.2}});
    EXPECT_EQ(choice.backend, Backend::Fragment);
    EXPECT_NEAR(choice.computeSpeedup, 1.0 / 1.2, 1e-12);
    EXPECT_THROW(decideBackend({}), std::invalid_argument);
}

TEST(BackendChoice, DescribesHowItWasChosen) {
    EXPECT_EQ((BackendChoice{Backend::Compute, 1.84, false}).describe(),
              "compute, compute at 1.84x the fragment backend's speed (measured)");
    EXPECT_EQ((BackendChoice{Backend::Fragment, 1.05, true}).describe(),
              "fragment, compute at 1.05x the fragment backend's speed (cached measurement)");
    EXPECT_EQ((BackendChoice{Backend::Fragment, 0.0, false}).describe(), "fragment (this context has no compute shaders)");
}

TEST(BackendCacheKey, NamesDeviceAndProgram) {
    const std::string key = backendCacheKey("llvmpipe, 4.5", "quads diffuse full sobol radiance");
    EXPECT_EQ(key.size(), 16u);
    EXPECT_EQ(key.find_first_not_of("0123456789abcdef"), std::string::npos) << key;
    EXPECT_EQ(key, backendCacheKey("llvmpipe, 4.5", "quads diffuse full sobol radiance"));
    EXPECT_NE(key, backendCacheKey("NVIDIA H200, 4.6", "quads diffuse full sobol radiance"));
    EXPECT_NE(key, backendCacheKey("llvmpipe, 4.5", "quads diffuse full random radiance"));
}

TEST(BackendCache, KeepsDecisionsAcrossInstances) {
    testing::ScratchFiles files("backend_cache");
    const std::filesystem::path path = files.write("unused", "").parent_path() / "sub" / "backends.json";
    BackendChoice compute{Backend::Compute, 1.8, false};
    BackendCache(path).store("a", compute);
    BackendCache(path).store("b", BackendChoice{Backend::Fragment, 0.7, false});
    std::optional<BackendChoice> a = BackendCache(path).find("a");
    ASSERT_TRUE(a);
    EXPECT_EQ(a->backend, Backend::Compute);
    EXPECT_DOUBLE_EQ(a->computeSpeedup, 1.8);
    EXPECT_TRUE(a->fromCache);
    ASSERT_TRUE(BackendCache(path).find("b"));
    EXPECT_EQ(BackendCache(path).find("b")->backend, Backend::Fragment);
    EXPECT_FALSE(BackendCache(path).find("c"));
    EXPECT_FALSE(BackendCache(std::nullopt).find("a")) << "no path: no cache";
}

TEST(BackendCache, ABrokenCacheCostsAMeasurementNotTheRender) {
    testing::ScratchFiles files("backend_cache");
    const std::filesystem::path path = files.write("backends.json", "{\"a\": {\"backend\": \"compute\", ");
    EXPECT_FALSE(BackendCache(path).find("a"));
    files.write("backends.json", R"({"a": {"backend": "warp drive", "compute_speedup": 2}})");
    EXPECT_FALSE(BackendCache(path).find("a")) << "an unknown backend name is no decision";
    BackendCache(path).store("a", BackendChoice{Backend::Compute, 2.0, false});
    ASSERT_TRUE(BackendCache(path).find("a")) << "the broken entry was replaced";
    // A directory that cannot be written: a warning, no exception.
    const std::filesystem::path locked = files.write("x", "").parent_path() / "locked";
    std::filesystem::create_directories(locked);
    ::chmod(locked.c_str(), 0500);
    if (::geteuid() != 0) { // root writes anyway
        EXPECT_NO_THROW(BackendCache(locked / "backends.json").store("a", BackendChoice{}));
    }
    ::chmod(locked.c_str(), 0700);
}

// The path tracer measures once, caches, and afterwards runs what the cache says, whatever a new
// measurement would say: an entry turned around by hand is obeyed.
TEST(ChooseBackend, MeasuresOnceThenRunsTheCachedDecision) {
    testing::glContext();
    if (!PathTracer::computeSupported()) GTEST_SKIP() << "no OpenGL 4.3: fragment is the only backend";
    testing::ScratchFiles files("backend_cache");
    const std::filesystem::path path = files.write("unused", "").parent_path() / "backends.json";
    PathTracer tracer;
    tracer.setScene(loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json"));
    tracer.setImageSize({24, 16});
    const BackendCache cache(path);
    BackendChoice measured = tracer.chooseBackend(cache);
    EXPECT_FALSE(measured.fromCache);
    EXPECT_EQ(tracer.backend(), measured.backend);
    EXPECT_EQ(tracer.sampleCount(), 0) << "the measurement's samples are not part of the render";
    EXPECT_EQ(tracer.readMean().width, 24) << "the image keeps its size";

    nlohmann::json json = nlohmann::json::parse(testing::readFileBytes(path));
    ASSERT_EQ(json.size(), 1u) << json.dump();
    const Backend opposite = measured.backend == Backend::Compute ? Backend::Fragment : Backend::Compute;
    json.begin().value()["backend"] = backendName(opposite);
    files.write("backends.json", json.dump());
    BackendChoice cached = tracer.chooseBackend(cache);
    EXPECT_TRUE(cached.fromCache);
    EXPECT_EQ(cached.backend, opposite);
    EXPECT_EQ(tracer.backend(), opposite);

    // Another program (sampler) is another decision: measured again, cached beside the first.
    RenderSettings settings = tracer.settings();
    settings.sampler = settings.sampler == SamplerMode::Sobol ? SamplerMode::Random : SamplerMode::Sobol;
    tracer.setSettings(settings);
    EXPECT_FALSE(tracer.chooseBackend(cache).fromCache);
    EXPECT_EQ(nlohmann::json::parse(testing::readFileBytes(path)).size(), 2u);
}

// A decision holds for the code it timed: the same scene and settings with a shader changed (an
// upgraded ptview, an edited shaders/) are measured again, not run on the old decision.
TEST(ChooseBackend, AChangedShaderIsMeasuredAgain) {
    testing::glContext();
    if (!PathTracer::computeSupported()) GTEST_SKIP() << "no OpenGL 4.3: fragment is the only backend";
    testing::ScratchFiles files("backend_cache_shaders");
    const std::filesystem::path folder = files.write("unused", "").parent_path();
    const std::filesystem::path shaders = folder / "shaders";
    std::filesystem::copy(PTVIEW_SHADER_DIR, shaders, std::filesystem::copy_options::recursive);
    const BackendCache cache(folder / "backends.json");
    auto choose = [&cache](const std::filesystem::path& shaderDir) {
        PathTracer tracer(shaderDir);
        tracer.setScene(loadScene(PTVIEW_ASSETS_DIR "/scenes/cornell.json"));
        tracer.setImageSize({24, 16});
        return tracer.chooseBackend(cache);
    };
    EXPECT_FALSE(choose(shaders).fromCache);
    EXPECT_TRUE(choose(shaders).fromCache) << "the same shaders: the cached decision";
    std::ofstream(shaders / "integrator.glsl", std::ios::app) << "\n// changed\n";
    EXPECT_FALSE(choose(shaders).fromCache) << "integrator.glsl changed: measured again";
    EXPECT_EQ(nlohmann::json::parse(testing::readFileBytes(folder / "backends.json")).size(), 2u);
}

} // namespace
} // namespace ptview
