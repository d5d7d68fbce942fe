#include <ptview/window/MaterialsPanel.h>

#include <ptview/gl/ImageTexture.h>
#include <ptview/model/EditHistory.h>
#include <ptview/scene/MaterialInputs.h>
#include <ptview/scene/MaterialTextures.h>
#include <ptview/io/PrintableText.h>
#include <ptview/scene/SceneLoader.h>
#include <ptview/scene/SceneRanges.h>

#include <ptview/window/PanelWidgets.h>

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iterator>
#include <string>

namespace ptview {
namespace {

constexpr float kDefaultStrength = 10.0f; // a surface turned emitter lights the Cornell box
constexpr float kDefaultRoughness = 0.2f; // visibly rough, so metal and plastic differ from mirror
// What the loader gives a type that does not have the parameter, so that an edited model equals
// what saving and loading it gives back.
constexpr float kLoaderIor = 1.5f;
// A surface turned medium fills its shape with a grey fog of a mean free path of a metre: visible
// in a room-sized scene without hiding it.
constexpr float kDefaultFogScattering = 1.0f;

void emitterControlsFrom(const glm::vec3& radiance, glm::vec3& color, float& strength) {
    strength = std::max(radiance.r, std::max(radiance.g, radiance.b));
    color = strength > 0.0f ? radiance / strength : glm::vec3(1.0f);
}

// An emitter made from a surface shows the surface's colour, unless that is black.
glm::vec3 emitterColor(const glm::vec3& shownColor) {
    return shownColor == glm::vec3(0.0f) ? glm::vec3(1.0f) : shownColor;
}

// The material as `type`, keeping its colour (an emitter's shown colour) and the parameters both
// types have; a parameter new to it gets a usable value, and one the new type lacks goes back to
// the loader's default.
Material retyped(const Material& material, MaterialType type, const glm::vec3& shownColor) {
    const MaterialSchema& from = materialSchema(material.type);
    const MaterialSchema& to = materialSchema(type);
    Material result;
    result.name = material.name;
    result.importedFrom = material.importedFrom; // still the glTF file's, saved as an override of it
    result.type = type;
    if (type == MaterialType::Emitter) {
        result.radiance = emitterColor(shownColor) * kDefaultStrength;
    } else if (type != MaterialType::Medium) { // a medium has neither colour nor emission
        result.color = shownColor;
        // Emission carries over between surface types; an emitter turned surface stops emitting.
        if (material.type != MaterialType::Emitter) result.radiance = material.radiance;
    }
    if (to.hasIor) result.ior = from.hasIor ? material.ior : kLoaderIor;
    if (to.hasRoughness) result.roughness = from.hasRoughness ? material.roughness : kDefaultRoughness;
    const bool holdsMedium = type == MaterialType::Medium || materialInputTakers::refracting(to);
    if (holdsMedium && material.boundsMedium()) {
        result.sigmaA = material.sigmaA;
        result.sigmaS = material.sigmaS;
        result.g = material.g;
        result.hasInterior = type != MaterialType::Medium;
    } else if (type == MaterialType::Medium) {
        result.sigmaS = glm::vec3(kDefaultFogScattering);
    }
    return result;
}

} // namespace

Material retypedMaterial(const Material& material, MaterialType type) {
    glm::vec3 shownColor = material.color;
    if (material.type == MaterialType::Emitter) {
        float strength = std::max(material.radiance.r, std::max(material.radiance.g, material.radiance.b));
        shownColor = strength > 0.0f ? material.radiance / strength : glm::vec3(1.0f);
    }
    return retyped(material, type, shownColor);
}

Material withInterior(const Material& material, bool holdsMedium) {
    if (material.hasInterior == holdsMedium) return material;
    Material result = material;
    result.hasInterior = holdsMedium;
    // On: a clear solid ("interior": {}); off: the loader's values for a material without one.
    result.sigmaA = result.sigmaS = glm::vec3(0.0f);
    result.g = 0.0f;
    return result;
}

namespace {

const char* colorTooltip(MaterialType type) {
    switch (type) {
    case MaterialType::Diffuse: return "Lambertian reflectance";
    case MaterialType::DiffuseTransmission: return "Lambertian transmittance to the other side";
    case MaterialType::Mirror: return "constant reflectance, no Fresnel";
    case MaterialType::SpecularTransmission: return "refracted fraction; always refracts";
    case MaterialType::Glass: return "multiplies both the reflected and the refracted light";
    case MaterialType::Metal: return "reflectance at normal incidence (Schlick Fresnel)";
    case MaterialType::Plastic: return "albedo of the Lambertian base under the coat";
    case MaterialType::Principled: return "base colour: the diffuse albedo of the dielectric part, the metal's F0";
    case MaterialType::Emitter:
    case MaterialType::Medium: break; // no colour
    }
    return "";
}

// The thumbnail in the list, in pixels, and its texels (the size of the view on hover).
constexpr float kThumbnailSide = 48.0f;
constexpr int kThumbnailTexels = 192;

// The channel a thumbnail shows as grey: the one the input reads (docs/materials.md), so that
// a shared metallic-roughness image shows each input's own data; -1: the image as stored.
int thumbnailChannel(TextureSlot Material::*slot) {
    if (slot == &Material::roughnessTexture) return 1;
    if (slot == &Material::metallicTexture) return 2;
    return -1;
}

// One coefficient of a medium (per metre, per channel) as colour x density, the colour's largest
// component 1 (its hue), the density that of its strongest channel. Returns whether it changed.
bool coefficientControls(const char* name, glm::vec3& coefficient, glm::vec3& color, float& density, const char* colorTooltip,
                         const char* densityTooltip) {
    if (color * density != coefficient) {
        density = std::max(coefficient.r, std::max(coefficient.g, coefficient.b));
        color = density > 0.0f ? coefficient / density : glm::vec3(1.0f);
    }
    const SceneRange& range = ranges::kMediumCoefficient;
    ImGui::PushID(name);
    bool colorEdited = ImGui::ColorEdit3(name, &color.x, ImGuiColorEditFlags_Float);
    itemTooltip(colorTooltip);
    if (colorEdited) {
        color = glm::clamp(color, 0.0f, 1.0f);
        const float largest = std::max(color.r, std::max(color.g, color.b));
        if (largest > 0.0f) color /= largest; // the hue alone: the density says how much
    }
    // Logarithmic: thin fog and milk are orders of magnitude apart. Ctrl+click may type a value
    // beyond the span, within the scene format's range.
    bool densityEdited = ImGui::SliderFloat("density", &density, range.panelLo, range.panelHi, "%.3g /m",
                                            ImGuiSliderFlags_Logarithmic);
    itemTooltip(densityTooltip);
    ImGui::PopID();
    if (!colorEdited && !densityEdited) return false;
    density = std::clamp(density, static_cast<float>(range.lo), static_cast<float>(range.hi));
    coefficient = color * density;
    return true;
}

std::string fullTextureSource(const std::string& source) {
    return std::filesystem::u8path(source).lexically_normal().u8string();
}

// "spot_texture.png" for a file, "model.glb#/images/3" for an image inside a glTF file.
std::string textureSourceName(const std::string& source) {
    const std::size_t hash = source.find('#');
    const std::string file = source.substr(0, hash);
    const std::string name = std::filesystem::u8path(file).filename().u8string();
    return (name.empty() ? file : name) + (hash == std::string::npos ? "" : source.substr(hash));
}

} // namespace

void MaterialsPanel::draw(ViewerSession& session) {
    Scene& scene = session.model().scene;
    // A thumbnail whose image only the cache still holds (the scene reloaded or replaced, the
    // texture removed) goes, and its image with it: a reload decodes every image again.
    for (auto it = thumbnails_.begin(); it != thumbnails_.end();)
        it = it->second.first.use_count() == 1 ? thumbnails_.erase(it) : std::next(it);
    emitters_.resize(scene.materials.size());
    media_.resize(scene.materials.size());
    bool changed = false;
    if (scene.materials.empty()) ImGui::TextDisabled("the scene has no materials");
    ImGui::PushItemWidth(-110.0f); // room for the labels
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        Material& material = scene.materials[i];
        // "###" keeps the node's id (and open state) when its type changes. Names come from files
        // someone may have sent: control characters show as escapes (PrintableText.h).
        std::string label = printableText(material.name) + "  (" + materialSchema(material.type).name + ")###material" +
                            std::to_string(i);
        bool asked = materialToOpen_ == i; // the Pixel panel's "open in Materials"
        if (asked) ImGui::SetNextItemOpen(true);
        if (!ImGui::TreeNode(label.c_str())) continue;
        if (asked) {
            ImGui::SetScrollHereY(0.0f);
            materialToOpen_.reset();
        }
        // An edit that would leave a medium in a shape that encloses none (a quad, a disk, an open
        // mesh: the loader refuses it) is taken back at once, with the reason under the material.
        const Material before = material;
        bool edited = drawMaterial(material, emitters_[i]);
        // The medium's controls come after a principled material's textures, which so keep their
        // place in the panel (tests/window_textures.sh clicks them by position).
        if (material.type == MaterialType::Principled && drawTextures(scene, material, i))
            session.model().pendingChanges |= ViewerModel::kSceneChanged;
        if (material.type == MaterialType::Medium || materialInputTakers::refracting(materialSchema(material.type)))
            edited |= drawMedium(material, media_[i]);
        if (edited && material.boundsMedium() != before.boundsMedium()) {
            if (std::string problem = mediumBoundaryProblem(scene); !problem.empty()) {
                material = before;
                edited = false;
                mediumRefusals_[i] = problem + "; the edit is taken back";
            }
        }
        if (edited) mediumRefusals_.erase(i);
        if (auto refusal = mediumRefusals_.find(i); refusal != mediumRefusals_.end())
            errorText(printableText(refusal->second));
        changed |= edited;
        ImGui::TreePop();
    }
    ImGui::PopItemWidth();
    if (changed) session.model().pendingChanges |= ViewerModel::kMaterialsChanged;
    ImGui::Separator();
    save(session);
}

bool MaterialsPanel::drawMaterial(Material& material, EmitterControls& emitter) {
    bool changed = false;
    if (material.type == MaterialType::Emitter && emitter.color * emitter.strength != material.radiance)
        emitterControlsFrom(material.radiance, emitter.color, emitter.strength);

    const MaterialSchema& schema = materialSchema(material.type);
    if (ImGui::BeginCombo("type", schema.name)) {
        for (const MaterialSchema& candidate : kMaterialSchemas) {
            bool isCurrent = candidate.type == material.type;
            if (ImGui::Selectable(candidate.name, isCurrent) && !isCurrent) {
                glm::vec3 shownColor = material.type == MaterialType::Emitter ? emitter.color : material.color;
                material = retyped(material, candidate.type, shownColor);
                if (candidate.type == MaterialType::Emitter) {
                    emitter.color = emitterColor(shownColor); // their product is the radiance, exactly
                    emitter.strength = kDefaultStrength;
                }
                changed = true;
            }
            if (isCurrent) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    // The schema may have changed with the type.
    const MaterialSchema& current = materialSchema(material.type);

    constexpr ImGuiColorEditFlags kColorFlags = ImGuiColorEditFlags_Float;
    if (material.type == MaterialType::Emitter) {
        bool edited = ImGui::ColorEdit3("colour", &emitter.color.x, kColorFlags);
        itemTooltip("radiance = colour x strength");
        edited |= ImGui::DragFloat("strength", &emitter.strength, 0.1f, ranges::kRadiance.panelLo,
                                   ranges::kRadiance.panelHi, "%.2f", ImGuiSliderFlags_AlwaysClamp);
        itemTooltip("radiance of the front side, W sr^-1 m^-2, at colour 1");
        if (edited) {
            emitter.color = glm::clamp(emitter.color, ranges::kColor.panelLo, ranges::kColor.panelHi);
            material.radiance = emitter.color * emitter.strength;
            changed = true;
        }
        ImGui::TextDisabled("radiance %.3g %.3g %.3g", material.radiance.r, material.radiance.g,
                            material.radiance.b);
    } else if (current.colorKey) {
        if (ImGui::ColorEdit3(current.colorKey, &material.color.x, kColorFlags)) {
            material.color = glm::clamp(material.color, ranges::kColor.panelLo, ranges::kColor.panelHi); // the loader's range
            changed = true;
        }
        itemTooltip(colorTooltip(material.type));
    }
    if (material.type != MaterialType::Emitter && material.type != MaterialType::Medium) {
        if (ImGui::DragFloat3("emission", &material.radiance.x, 0.05f, ranges::kRadiance.panelLo, ranges::kRadiance.panelHi,
                              "%.2f", ImGuiSliderFlags_AlwaysClamp))
            changed = true;
        itemTooltip("radiance the surface emits from its front side, on top of what it reflects (W sr^-1 m^-2)");
    }
    // A slider per number the type takes (MaterialInputs.h), over its range's panel span, saying
    // what the range's table says; the normal map's scale only where there is a normal map.
    for (const MaterialInput& input : kMaterialInputs) {
        if (!input.panelLabel || !input.takenBy(current)) continue;
        if (input.write == InputWrite::WithTexture && !(material.*input.slot).used()) continue;
        if (input.number == &Material::g) continue; // with the medium's coefficients (drawMedium)
        float& value = material.*input.number;
        changed |= ImGui::SliderFloat(input.panelLabel, &value, input.range->panelLo, input.range->panelHi, "%.3f",
                                      ImGuiSliderFlags_AlwaysClamp);
        itemTooltip(input.range->description);
        if (input.number == &Material::roughness)
            ImGui::TextDisabled("alpha = roughness\xC2\xB2 = %.4f", material.roughness * material.roughness);
    }
    return changed;
}

bool MaterialsPanel::drawMedium(Material& material, MediumControls& medium) {
    bool changed = false;
    if (material.type != MaterialType::Medium) {
        bool holds = material.hasInterior;
        if (ImGui::Checkbox("holds a medium", &holds)) {
            material = withInterior(material, holds);
            changed = true;
        }
        itemTooltip("on: the closed shape is filled with a medium, entered through this surface (clear at first, as glass "
                    "is); off: a thin surface with the same medium on both sides");
        if (!material.hasInterior) return changed;
    }
    changed |= coefficientControls("absorption", material.sigmaA, medium.absorptionColor, medium.absorptionDensity,
                                   "sigma_a = colour x density: the light absorbed per metre of path, per channel; the "
                                   "colour's largest component is 1",
                                   "absorption per metre (m^-1) in the colour's strongest channel; the mean free path "
                                   "between absorptions is 1 / density metres");
    changed |= coefficientControls("scattering", material.sigmaS, medium.scatteringColor, medium.scatteringDensity,
                                   "sigma_s = colour x density: the light scattered per metre of path, per channel; the "
                                   "colour's largest component is 1",
                                   "scattering per metre (m^-1) in the colour's strongest channel; the mean free path "
                                   "between scatterings is 1 / density metres");
    const SceneRange& g = ranges::kPhaseAsymmetry;
    changed |= ImGui::SliderFloat("g", &material.g, g.panelLo, g.panelHi, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    itemTooltip(g.description);
    const glm::vec3 extinction = material.sigmaA + material.sigmaS;
    ImGui::TextDisabled("mean free path %.3g %.3g %.3g m", 1.0 / extinction.r, 1.0 / extinction.g, 1.0 / extinction.b);
    itemTooltip("1 / (sigma_a + sigma_s) per channel: the mean distance light goes before it is absorbed or scattered");
    return changed;
}

GLuint MaterialsPanel::thumbnail(const std::shared_ptr<const TextureImage>& image, int channel) {
    auto found = thumbnails_.find({image.get(), channel});
    if (found != thumbnails_.end()) return found->second.second.id();
    // At most kThumbnailTexels a side, nearest texel: enough for the larger view on hover; the
    // mipmaps keep the small one in the list from aliasing.
    constexpr int kSide = kThumbnailTexels;
    const int width = std::max(1, std::min(kSide, image->width * kSide / std::max(image->width, image->height)));
    const int height = std::max(1, std::min(kSide, image->height * kSide / std::max(image->width, image->height)));
    std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t from = (static_cast<std::size_t>(y * image->height / height) * static_cast<std::size_t>(image->width) +
                                      static_cast<std::size_t>(x * image->width / width)) * 4;
            std::uint8_t* to = texels.data() + (static_cast<std::size_t>(y) * width + x) * 4;
            std::copy_n(image->rgba.begin() + static_cast<std::ptrdiff_t>(from), 4, to);
            if (channel >= 0) { // that channel as grey, opaque
                std::fill_n(to, 3, image->rgba[from + static_cast<std::size_t>(channel)]);
                to[3] = 255;
            }
        }
    GlTexture texture;
    uploadImageTexture(texture, ImageRgba8{width, height, std::move(texels)}, TextureFilter::Mipmapped);
    const GLuint id = texture.id();
    thumbnails_.emplace(std::make_pair(image.get(), channel), std::make_pair(image, std::move(texture)));
    return id;
}

bool MaterialsPanel::drawTextures(Scene& scene, Material& material, std::size_t index) {
    bool changed = false;
    for (int k = 0; k < int(std::size(kMaterialTextureInputs)); ++k) {
        const MaterialTextureInput& input = kMaterialTextureInputs[k];
        ImGui::PushID(k);
        TextureSlot& slot = material.*input.slot;
        const bool used = slot.used() && static_cast<std::size_t>(slot.texture) < scene.textures.size();
        const auto key = std::make_pair(index, k);
        ImGui::Text("%s texture", input.label);
        if (used) {
            const SceneTexture& texture = scene.textures[static_cast<std::size_t>(slot.texture)];
            if (texture.image) {
                const auto id = reinterpret_cast<ImTextureID>(
                    static_cast<std::uintptr_t>(thumbnail(texture.image, thumbnailChannel(input.slot))));
                // The image's aspect ratio, its longer side kThumbnailSide.
                const float longer = float(std::max(texture.image->width, texture.image->height));
                const ImVec2 aspect(float(texture.image->width) / longer, float(texture.image->height) / longer);
                const float width = kThumbnailSide * aspect.x;
                ImGui::Image(id, ImVec2(width, kThumbnailSide * aspect.y));
                if (ImGui::IsItemHovered()) {
                    ImGui::BeginTooltip();
                    ImGui::Image(id, ImVec2(kThumbnailTexels * aspect.x, kThumbnailTexels * aspect.y));
                    ImGui::EndTooltip();
                }
                // The text column starts at the same place for every aspect ratio.
                ImGui::SameLine(0.0f, ImGui::GetStyle().ItemSpacing.x + kThumbnailSide - width);
            }
            ImGui::BeginGroup();
            // The file's name; its whole path (long ones wrapped mid-word) on hover. The lines
            // wrap at the sidebar's edge rather than being cut there.
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextUnformatted(printableText(textureSourceName(texture.source)).c_str());
            itemTooltip(fullTextureSource(texture.source).c_str());
            ImGui::TextDisabled("%dx%d, %s, uv x (%.3g, %.3g) + (%.3g, %.3g)", texture.image ? texture.image->width : 0,
                                texture.image ? texture.image->height : 0,
                                texture.colorSpace == TextureColorSpace::Srgb ? "sRGB" : "linear", slot.scale.x,
                                slot.scale.y, slot.offset.x, slot.offset.y);
            ImGui::PopTextWrapPos();
            if (ImGui::SmallButton("Remove")) {
                setMaterialTexture(scene, material, input, {});
                textureErrors_.erase(key); // the error of an earlier Load no longer describes the slot
                changed = true;
            }
            ImGui::EndGroup();
        } else {
            ImGui::SameLine();
            ImGui::TextDisabled("none (the factor alone)");
        }
        std::string& path = texturePaths_[key];
        ImGui::SetNextItemWidth(-60.0f);
        bool load = ImGui::InputTextWithHint("##texture", "image file (PNG or JPEG)", &path,
                                             ImGuiInputTextFlags_EnterReturnsTrue);
        ImGui::SameLine();
        load |= ImGui::Button("Load");
        if (load && !path.empty()) {
            // A file that does not load leaves the material and the scene as they were.
            try {
                setMaterialTexture(scene, material, input, std::filesystem::u8path(path));
                textureErrors_.erase(key);
                changed = true;
            } catch (const SceneError& error) {
                textureErrors_[key] = error.what();
            }
        }
        auto error = textureErrors_.find(key);
        if (error != textureErrors_.end()) {
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", printableText(error->second).c_str());
            ImGui::PopTextWrapPos();
        }
        ImGui::PopID();
    }
    return changed;
}

void MaterialsPanel::save(ViewerSession& session) {
    // The session keeps the target: the open scene's file, or what was typed since it opened.
    std::string path = session.saveTarget();
    ImGui::TextUnformatted("Save scene as");
    ImGui::SetNextItemWidth(-60.0f);
    bool submitted = ImGui::InputText("##path", &path, ImGuiInputTextFlags_EnterReturnsTrue);
    if (path != session.saveTarget()) session.setSaveTarget(path);
    ImGui::SameLine();
    submitted |= ImGui::Button("Save");
    if (submitted) {
        if (path.empty()) {
            saveFailed_ = true;
            saveStatus_ = "enter a file name";
        } else if (session.saveReplacesAnotherFile(path)) {
            ImGui::OpenPopup("Replace file");
        } else {
            saveTo(session, path);
        }
    }
    if (ImGui::BeginPopupModal("Replace file", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s exists and is not the open scene's file.\nReplace it with this scene?", printableText(path).c_str());
        if (ImGui::Button("Replace")) {
            saveTo(session, path);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    if (!saveStatus_.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(saveFailed_ ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "%s",
                           printableText(saveStatus_).c_str());
        ImGui::PopTextWrapPos();
    }
}

void MaterialsPanel::saveTo(ViewerSession& session, const std::string& path) {
    try {
        session.saveSceneAs(path);
        saveFailed_ = false;
        saveStatus_ = "saved " + path;
    } catch (const std::exception& error) {
        saveFailed_ = true;
        saveStatus_ = error.what();
    }
}

} // namespace ptview
