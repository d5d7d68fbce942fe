#pragma once
// The viewer's "Materials" panel: every material of the scene under its own tree node,
// with its type, colour and the parameters its type has, edited live, a principled material's
// textures (thumbnail, source, size, colour space; replace or remove); and "Save scene as".
// It edits the session's scene model and flags the change; the session re-sends the materials to
// the renderer (PathTracer::setMaterials, which recompiles nothing).

#include <ptview/gl/GlObjects.h>
#include <ptview/session/ViewerSession.h>

#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ptview {

// The material as another type, the way the panel's type combo changes it: colour, emission and
// shared parameters carry over, a parameter new to the type gets a usable value.
// A medium carries over between types that hold one (medium, and the refracting types with an
// interior); a material turned medium without one gets a thin grey fog.
Material retypedMaterial(const Material& material, MaterialType type);

// A refracting material with a medium inside its closed shape (a clear one when it had none), or
// without (a thin surface): the "holds a medium" checkbox, the script's `interior on|off`. The
// coefficients of one without are the loader's (0), so the material saves and reads back the same.
Material withInterior(const Material& material, bool holdsMedium);

class MaterialsPanel {
public:
    // Draws the panel's controls into the current window (the viewer's sidebar); an edit flags
    // ViewerModel::kMaterialsChanged. A successful save makes the saved file the scene's file;
    // one that would replace another existing file asks first.
    void draw(ViewerSession& session);
    // Opens that material's node (and scrolls to it) the next time the panel is drawn.
    void openMaterial(std::size_t index) { materialToOpen_ = index; }

private:
    // An emitter's radiance shown as a colour in [0, 1] times a strength, since radiance goes
    // above 1. Kept between frames so that dimming the colour does not renormalize it under the
    // user's mouse; rebuilt from the radiance whenever the two disagree.
    struct EmitterControls {
        glm::vec3 color{1.0f};
        float strength = 0.0f;
    };

    // A medium's absorption and scattering shown as a colour whose largest component is 1 times
    // a density (per metre), as the emitter's radiance is; kept between frames for the same reason.
    struct MediumControls {
        glm::vec3 absorptionColor{1.0f};
        float absorptionDensity = 0.0f;
        glm::vec3 scatteringColor{1.0f};
        float scatteringDensity = 0.0f;
    };

    bool drawMaterial(Material& material, EmitterControls& emitter);
    // The coefficients and g of a medium, or of the one a refracting material holds (with the
    // "holds a medium" checkbox). Returns whether one changed.
    bool drawMedium(Material& material, MediumControls& medium);
    // A principled material's texture inputs: a thumbnail, the source, size and colour space of
    // each, a path field with Load, and Remove. Returns whether a texture changed (which may need
    // another program: the session uploads the scene again).
    bool drawTextures(Scene& scene, Material& material, std::size_t index);
    // A small GL texture of the image for ImGui::Image, made once per image and channel: the
    // image as stored (channel -1), or one channel as grey.
    GLuint thumbnail(const std::shared_ptr<const TextureImage>& image, int channel);
    void save(ViewerSession& session);
    void saveTo(ViewerSession& session, const std::string& path);

    std::vector<EmitterControls> emitters_; // one per material, used by emitters only
    std::vector<MediumControls> media_;     // one per material, used by those that bound a medium
    // Why the last edit of a material was taken back (it would leave a medium in a shape that
    // encloses none), shown under it until its next edit.
    std::map<std::size_t, std::string> mediumRefusals_;
    // Thumbnails by image and channel; the entry holds the image, so its address is not reused
    // while cached.
    std::map<std::pair<const TextureImage*, int>, std::pair<std::shared_ptr<const TextureImage>, GlTexture>> thumbnails_;
    // The path typed into each (material, input)'s field, and the last Load's error there.
    std::map<std::pair<std::size_t, int>, std::string> texturePaths_;
    std::map<std::pair<std::size_t, int>, std::string> textureErrors_;
    std::optional<std::size_t> materialToOpen_;
    std::string saveStatus_; // the outcome of the last save, shown under the button
    bool saveFailed_ = false;
};

} // namespace ptview
