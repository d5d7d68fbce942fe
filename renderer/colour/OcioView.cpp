#include <ptview/colour/OcioView.h>

#include <OpenColorIO/OpenColorIO.h>

namespace ptview {
namespace {

namespace OCIO = OCIO_NAMESPACE;

OCIO::ConstConfigRcPtr loadConfig(const std::filesystem::path& configPath) {
    OCIO::ConstConfigRcPtr config;
    try {
        config = OCIO::Config::CreateFromFile(configPath.string().c_str());
        config->validate();
    } catch (const OCIO::Exception& e) {
        throw OcioError(configPath.string() + ": not a usable OpenColorIO config: " + e.what());
    }
    if (!config->hasRole(OCIO::ROLE_SCENE_LINEAR))
        throw OcioError(configPath.string() + ": the OpenColorIO config has no scene_linear role (what the render's radiance is)");
    return config;
}

std::string quotedList(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "\"" : ", \"") + name + "\"";
    return text.empty() ? "none" : text;
}

std::vector<std::string> displaysOf(const OCIO::Config& config) {
    std::vector<std::string> names;
    for (int i = 0; i < config.getNumDisplays(); ++i) names.emplace_back(config.getDisplay(i));
    return names;
}

std::vector<std::string> viewsOf(const OCIO::Config& config, const std::string& display) {
    std::vector<std::string> names;
    for (int i = 0; i < config.getNumViews(display.c_str()); ++i) names.emplace_back(config.getView(display.c_str(), i));
    return names;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    for (const std::string& n : names)
        if (n == name) return true;
    return false;
}

OcioShader extractShader(const OCIO::Processor& processor, const std::string& where) {
    OCIO::GpuShaderDescRcPtr desc = OCIO::GpuShaderDesc::CreateShaderDesc();
    desc->setLanguage(OCIO::GPU_LANGUAGE_GLSL_4_0);
    desc->setFunctionName("ocioDisplayView");
    desc->setResourcePrefix("ocio_");
    processor.getDefaultGPUProcessor()->extractGpuShaderInfo(desc);
    // Dynamic properties (an exposure or contrast the config leaves to the application) would be
    // uniforms to set every frame; ptview has its own exposure, so such views are refused.
    if (desc->getNumUniforms() > 0)
        throw OcioError(where + ": the view has dynamic properties (uniforms), which ptview does not drive");
    OcioShader shader;
    shader.glsl = desc->getShaderText();
    for (unsigned i = 0; i < desc->getNumTextures(); ++i) {
        const char* textureName = nullptr;
        const char* samplerName = nullptr;
        unsigned width = 0, height = 0;
        OCIO::GpuShaderDesc::TextureType channel = OCIO::GpuShaderDesc::TEXTURE_RGB_CHANNEL;
        OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
        desc->getTexture(i, textureName, samplerName, width, height, channel, interpolation);
        const float* values = nullptr;
        desc->getTextureValues(i, values);
        OcioLut lut;
        lut.samplerName = samplerName;
        lut.width = static_cast<int>(width);
        lut.height = static_cast<int>(height);
        lut.channels = channel == OCIO::GpuShaderDesc::TEXTURE_RED_CHANNEL ? 1 : 3;
        lut.linear = interpolation != OCIO::INTERP_NEAREST;
        lut.values.assign(values, values + std::size_t(width) * height * lut.channels);
        shader.luts.push_back(std::move(lut));
    }
    for (unsigned i = 0; i < desc->getNum3DTextures(); ++i) {
        const char* textureName = nullptr;
        const char* samplerName = nullptr;
        unsigned edge = 0;
        OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
        desc->get3DTexture(i, textureName, samplerName, edge, interpolation);
        const float* values = nullptr;
        desc->get3DTextureValues(i, values);
        OcioLut lut;
        lut.samplerName = samplerName;
        lut.width = lut.height = lut.depth = static_cast<int>(edge);
        lut.channels = 3;
        lut.linear = interpolation != OCIO::INTERP_NEAREST;
        lut.values.assign(values, values + std::size_t(edge) * edge * edge * 3);
        shader.luts.push_back(std::move(lut));
    }
    return shader;
}

} // namespace

OcioView::OcioView(const std::filesystem::path& configPath, const std::string& requestedDisplay, const std::string& requestedView)
    : configPath_(configPath), display_(requestedDisplay), view_(requestedView) {
    OCIO::ConstConfigRcPtr config = loadConfig(configPath);
    const std::string file = configPath.string();
    if (display_.empty()) display_ = config->getDefaultDisplay();
    if (view_.empty()) view_ = config->getDefaultView(display_.c_str());
    const std::string& display = display_; // the names asked for, or the config's defaults
    const std::string& view = view_;
    const std::vector<std::string> displays = displaysOf(*config);
    if (!contains(displays, display))
        throw OcioError(file + ": the OpenColorIO config has no display \"" + display + "\" (it has " + quotedList(displays) + ")");
    const std::vector<std::string> views = viewsOf(*config, display);
    if (!contains(views, view))
        throw OcioError(file + ": the OpenColorIO display \"" + display + "\" has no view \"" + view + "\" (it has " +
                        quotedList(views) + ")");
    try {
        OCIO::DisplayViewTransformRcPtr transform = OCIO::DisplayViewTransform::Create();
        transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
        transform->setDisplay(display.c_str());
        transform->setView(view.c_str());
        OCIO::ConstProcessorRcPtr processor = config->getProcessor(transform);
        shader_ = extractShader(*processor, file + ": display \"" + display + "\", view \"" + view + "\"");
        cpu_ = processor->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
        throw OcioError(file + ": display \"" + display + "\", view \"" + view + "\": " + e.what());
    }
}

std::string OcioView::label() const {
    return configPath_.filename().string() + ": " + display_ + " / " + view_;
}

void OcioView::applyCpu(std::vector<float>& rgb) const {
    const auto* processor = static_cast<const OCIO::CPUProcessor*>(cpu_.get());
    OCIO::PackedImageDesc image(rgb.data(), static_cast<long>(rgb.size() / 3), 1, 3);
    processor->apply(image);
}

std::vector<OcioDisplayViews> OcioView::displaysAndViews(const std::filesystem::path& configPath) {
    OCIO::ConstConfigRcPtr config = loadConfig(configPath);
    std::vector<OcioDisplayViews> result;
    for (const std::string& display : displaysOf(*config)) result.push_back({display, viewsOf(*config, display)});
    return result;
}

} // namespace ptview
