#include <ptview/tracer/PathRecorder.h>

#include <ptview/gl/GlProgram.h>
#include <ptview/gpu/GlslEnums.h>
#include <ptview/probes/ProbePass.h>
#include <ptview/gl/ShaderAssembler.h>
#include <ptview/gpu/ShaderFeatures.h>

#include <stdexcept>
#include <string>

namespace ptview {
namespace {

// GL 4.1 promises 8 draw buffers, ProbePass uses at most 4: a record takes kRecordFields / 4 passes,
// rounded up.
constexpr int kFieldsPerPass = 4;
constexpr int kPasses = (kRecordFields + kFieldsPerPass - 1) / kFieldsPerPass;

PathVertex decodeVertex(const std::vector<glm::vec4>& field) {
    const unsigned flags = static_cast<unsigned>(field[0].w);
    PathVertex v;
    v.kind = (flags & kVertexCamera) ? PathVertex::Kind::Camera
           : (flags & kVertexSurface) ? PathVertex::Kind::Surface
           : (flags & kVertexMedium) ? PathVertex::Kind::Medium : PathVertex::Kind::Escaped;
    if (v.kind == PathVertex::Kind::Escaped) {
        v.direction = glm::vec3(field[0]);
    } else {
        v.position = glm::vec3(field[0]);
        v.direction = glm::vec3(field[5]);
    }
    if (v.kind == PathVertex::Kind::Medium) {
        v.sigmaT = glm::vec3(field[1]);
        v.phaseG = field[12].w;
    } else {
        v.normalGeom = glm::vec3(field[1]);
    }
    v.material = static_cast<int>(field[1].w);
    v.normalShading = glm::vec3(field[2]);
    v.surfaceLight = static_cast<int>(field[2].w);
    v.throughputIn = glm::vec3(field[3]);
    v.bsdfPdf = field[3].w;
    v.throughputOut = glm::vec3(field[4]);
    v.bsdfPdfEvaluated = field[4].w;
    v.survival = field[5].w;
    v.lightPoint = glm::vec3(field[6]);
    v.sampledLight = static_cast<int>(field[6].w);
    v.lightPdf = field[7].x;
    v.lightBsdfPdf = field[7].y;
    v.lightMisWeight = field[7].z;
    v.lightPdfEvaluated = field[7].w;
    v.directContribution = glm::vec3(field[8]);
    v.emissionMisWeight = field[8].w;
    v.emissionContribution = glm::vec3(field[9]);
    v.emissionLightPdf = field[9].w;
    v.emitted = glm::vec3(field[10]);
    v.emissionBsdfPdf = field[10].w;
    v.shadowHitDistance = field[11].w;
    v.segmentTransmittance = glm::vec3(field[12]);
    v.shadowTransmittance = glm::vec3(field[13]);

    v.bsdfSampled = flags & kVertexBsdfSampled;
    v.bsdfDelta = flags & kVertexBsdfDelta;
    v.continued = flags & kVertexContinued;
    v.roulette = flags & kVertexRoulette;
    v.rouletteEnded = flags & kVertexRouletteEnded;
    v.lightSampled = flags & kVertexLightSampled;
    v.lightDelta = flags & kVertexLightDelta;
    v.lightAtInfinity = flags & kVertexLightAtInfinity;
    v.shadowTraced = flags & kVertexShadowTraced;
    v.shadowBlocked = flags & kVertexShadowBlocked;
    v.emissionCounted = flags & kVertexEmission;
    if (!v.lightSampled) v.sampledLight = -1;
    return v;
}

} // namespace

struct PathRecorder::Program {
    ShaderFeatures features;
    Integrator integrator;
    SamplerMode sampler;
    LightPaths lightPaths;
    AssembledShader source;
    std::unique_ptr<GlProgram> program;

    bool builtFor(const PathTracer& tracer) const {
        const RenderSettings& s = tracer.settings();
        return features == tracer.features() && integrator == s.integrator && sampler == s.sampler &&
               lightPaths == s.lightPaths;
    }
};

PathRecorder::PathRecorder() = default;
PathRecorder::~PathRecorder() = default;
PathRecorder::PathRecorder(PathRecorder&&) noexcept = default;
PathRecorder& PathRecorder::operator=(PathRecorder&&) noexcept = default;

const AssembledShader* PathRecorder::source() const {
    return program_ ? &program_->source : nullptr;
}

std::vector<RecordedPath> PathRecorder::record(PathTracer& tracer, glm::ivec2 pixel, int count, int firstSample) {
    const glm::ivec2 size = tracer.imageSize();
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y)
        throw std::invalid_argument("pixel (" + std::to_string(pixel.x) + ", " + std::to_string(pixel.y) +
                                    ") is outside the " + std::to_string(size.x) + "x" + std::to_string(size.y) + " image");
    if (count < 1) throw std::invalid_argument("the number of paths must be at least 1, got " + std::to_string(count));
    if (firstSample < 0) throw std::invalid_argument("the first sample index must not be negative");

    if (!program_ || !program_->builtFor(tracer)) {
        const RenderSettings& settings = tracer.settings();
        ShaderAssembler assembler(tracer.shaderDir());
        // The render's radiance program, whatever view is shown: paths carry radiance.
        specializePathRecorder(assembler, tracer.features(), settings.integrator, settings.sampler, settings.lightPaths);
        assembler.replaceWithText("recorded_path.glsl", recordedPathGlsl());
        auto built = std::make_unique<Program>();
        built->features = tracer.features();
        built->integrator = settings.integrator;
        built->sampler = settings.sampler;
        built->lightPaths = settings.lightPaths;
        built->source = assembler.assemble("path_record.frag");
        built->program = std::make_unique<GlProgram>(assembler.assemble("fullscreen.vert"), built->source);
        program_ = std::move(built);
    }

    // The camera, the vertex of every bounce up to the depth, and the last ray's escape or hit.
    const int verticesPerPath = tracer.settings().maxDepth + 2;
    const GlProgram& program = *program_->program;
    tracer.useSceneIn(program);
    glUniform2i(program.uniformLocation("uPixel"), pixel.x, size.y - 1 - pixel.y); // GL rows run bottom-up
    glUniform1i(program.uniformLocation("uFirstSample"), firstSample);
    glUniform1i(program.uniformLocation("uVerticesPerPath"), verticesPerPath);
    const int items = count * verticesPerPath;
    std::vector<ProbeData> fields;
    for (int set = 0; set < kPasses; ++set) {
        glUseProgram(program.id());
        glUniform1i(program.uniformLocation("uOutputSet"), set);
        std::vector<ProbeData> part = runProbePass(program, items, {}, kFieldsPerPass);
        for (ProbeData& data : part) fields.push_back(std::move(data));
    }

    std::vector<RecordedPath> paths(static_cast<size_t>(count));
    std::vector<glm::vec4> record(kRecordFields);
    for (int p = 0; p < count; ++p) {
        RecordedPath& path = paths[static_cast<size_t>(p)];
        path.sampleIndex = firstSample + p;
        for (int v = 0; v < verticesPerPath; ++v) {
            const size_t item = static_cast<size_t>(p) * static_cast<size_t>(verticesPerPath) + static_cast<size_t>(v);
            for (int f = 0; f < kRecordFields; ++f) record[static_cast<size_t>(f)] = fields[static_cast<size_t>(f)][item];
            if (v == 0) path.radiance = glm::vec3(record[11]);
            if (!(static_cast<unsigned>(record[0].w) & kVertexExists)) break; // the path ended before
            PathVertex vertex = decodeVertex(record);
            if (!path.vertices.empty())
                vertex.transmittanceSoFar = path.vertices.back().transmittanceSoFar * vertex.segmentTransmittance;
            path.vertices.push_back(vertex);
        }
    }
    return paths;
}

std::string recordedPathGlsl() {
    std::string text = "// The path recorder's record of a vertex, shared with C++. Generated by renderer/tracer/PathRecorder.cpp\n"
                       "// from renderer/tracer/RecordedPath.h (kRecordFields, VertexFlag).\n" +
                       glslIntConstant("kRecordFields", kRecordFields, "vec4 per vertex") +
                       "// Flags of a vertex, bits of a float holding an exact integer.\n";
    for (const VertexFlagName& flag : kVertexFlagNames) text += glslUintConstant(flag.name, flag.flag, flag.meaning);
    return text;
}

std::vector<RecordedPath> recordPaths(PathTracer& tracer, glm::ivec2 pixel, int count, int firstSample) {
    return PathRecorder().record(tracer, pixel, count, firstSample);
}

} // namespace ptview
